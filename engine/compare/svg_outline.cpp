// SVG pattern outlines (see reference_outline.hpp for the rules). A small scanner, not an XML
// parser: it reads the <svg> tag's size and every <path>'s d attribute, which is what pattern and
// tracing programs write.
#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "engine/compare/reference_outline.hpp"
#include "engine/core/engine_error.hpp"

namespace lastcut {

namespace {

constexpr double kMmPerPx = 25.4 / 96.0;

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw EngineError("cannot read pattern file " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// Value of attribute `name` inside the tag text (name="..." or name='...').
std::optional<std::string> attribute(const std::string& tag, const std::string& name) {
  for (size_t at = tag.find(name); at != std::string::npos; at = tag.find(name, at + 1)) {
    if (at > 0 && !std::isspace(static_cast<unsigned char>(tag[at - 1]))) continue;
    size_t k = at + name.size();
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (k >= tag.size() || tag[k] != '=') continue;
    ++k;
    while (k < tag.size() && std::isspace(static_cast<unsigned char>(tag[k]))) ++k;
    if (k >= tag.size() || (tag[k] != '"' && tag[k] != '\'')) continue;
    const size_t close = tag.find(tag[k], k + 1);
    if (close == std::string::npos) return std::nullopt;
    return tag.substr(k + 1, close - k - 1);
  }
  return std::nullopt;
}

// Numbers in a list ("0 0 210 297", "1.5-2e1.5"), as SVG writes them.
class NumberScanner {
 public:
  NumberScanner(const std::filesystem::path& path, const std::string& text) : path_(path), text_(text) {}
  void skip_separators() {
    while (at_ < text_.size() && (std::isspace(static_cast<unsigned char>(text_[at_])) || text_[at_] == ',')) ++at_;
  }
  bool at_number() {
    skip_separators();
    if (at_ >= text_.size()) return false;
    const char c = text_[at_];
    return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+' || c == '.';
  }
  bool at_end() {
    skip_separators();
    return at_ >= text_.size();
  }
  char next_char() { return text_[at_++]; }
  double number() {
    if (!at_number()) throw EngineError(path_.string() + ": a path ends where a number was expected");
    if (text_[at_] == '+') ++at_;
    double value = 0.0;
    const auto [end, error] = std::from_chars(text_.data() + at_, text_.data() + text_.size(), value);
    if (error != std::errc() || !std::isfinite(value))
      throw EngineError(path_.string() + ": '" + text_.substr(at_, 12) + "' in a path is not a number");
    at_ = static_cast<size_t>(end - text_.data());
    return value;
  }

 private:
  const std::filesystem::path& path_;
  const std::string& text_;
  size_t at_ = 0;
};

// Length with a CSS unit, in mm; nullopt for percentages or unknown units.
std::optional<double> length_mm(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || !(value > 0.0)) return std::nullopt;
  const std::string unit(end, text.data() + text.size());
  if (unit == "mm") return value;
  if (unit == "cm") return value * 10.0;
  if (unit == "in") return value * 25.4;
  if (unit == "pt") return value * 25.4 / 72.0;
  if (unit == "px" || unit.empty()) return value * kMmPerPx;
  return std::nullopt;
}

// mm per user unit, from the <svg> tag.
double user_unit_mm(const std::filesystem::path& path, const std::string& svg_tag) {
  const auto view_box = attribute(svg_tag, "viewBox");
  const auto width = attribute(svg_tag, "width");
  if (!view_box || !width) return kMmPerPx;
  NumberScanner numbers(path, *view_box);
  numbers.number(), numbers.number();
  const double box_width = numbers.number();
  const auto width_mm = length_mm(*width);
  if (!(box_width > 0.0) || !width_mm)
    throw EngineError(path.string() + ": the drawing size (width \"" + *width + "\", viewBox \"" + *view_box +
                      "\") gives no scale in mm");
  return *width_mm / box_width;
}

// Number of chords so that a curve with second-difference bound `bend` (mm) stays within tolerance.
// Clamped as a double: a curve of absurd size (1e62) would overflow int; its points are refused later.
int chord_count(double bend_mm, double factor) {
  constexpr double kMostChords = 10000.0;
  const double chords = std::ceil(std::sqrt(factor * bend_mm / kCurveTolerance_mm));
  if (!(chords <= kMostChords)) return static_cast<int>(kMostChords);
  return std::max(1, static_cast<int>(chords));
}

struct Subpaths {
  std::vector<Polygon2> closed;
  int open = 0;
};

// Parses one d attribute into closed rings (mm, y up).
void parse_path(const std::filesystem::path& path, const std::string& d, double scale, Subpaths& out) {
  NumberScanner scan(path, d);
  std::vector<Point2> current;  // user units, y down
  bool closed = false;
  Point2 pen = Point2::Zero(), start = Point2::Zero();
  const auto finish = [&] {
    if (current.size() >= 2 && (current.front() - current.back()).norm() < 1e-9) current.pop_back(), closed = true;
    if (current.size() >= 3 && closed) {
      Polygon2 ring;
      for (const auto& p : current) ring.points.emplace_back(p.x() * scale, -p.y() * scale);
      out.closed.push_back(std::move(ring));
    } else if (current.size() >= 2) {
      ++out.open;
    }
    current.clear();
    closed = false;
  };
  char command = 0;
  while (!scan.at_end()) {
    if (!scan.at_number()) {
      command = scan.next_char();
    } else if (command == 0 || command == 'Z' || command == 'z') {
      throw EngineError(path.string() + ": a path has numbers without a command");
    }
    const bool relative = std::islower(static_cast<unsigned char>(command));
    const Point2 base = relative ? pen : Point2::Zero();
    const auto point = [&]() -> Point2 {
      const double x = scan.number();
      return Point2(x, scan.number()) + base;
    };
    switch (std::toupper(static_cast<unsigned char>(command))) {
      case 'M':
        finish();
        pen = start = point();
        current.push_back(pen);
        command = relative ? 'l' : 'L';  // further pairs are line-tos
        break;
      case 'L': pen = point(); current.push_back(pen); break;
      case 'H': pen.x() = scan.number() + base.x(); current.push_back(pen); break;
      case 'V': pen.y() = scan.number() + base.y(); current.push_back(pen); break;
      case 'Q': {
        const Point2 c = point(), end = point();
        const int n = chord_count(scale * (pen - 2 * c + end).norm(), 0.25);
        for (int k = 1; k <= n; ++k) {
          const double t = static_cast<double>(k) / n;
          current.push_back((1 - t) * (1 - t) * pen + 2 * (1 - t) * t * c + t * t * end);
        }
        pen = end;
        break;
      }
      case 'C': {
        const Point2 c1 = point(), c2 = point(), end = point();
        const double bend = std::max((pen - 2 * c1 + c2).norm(), (c1 - 2 * c2 + end).norm());
        const int n = chord_count(scale * bend, 0.75);
        for (int k = 1; k <= n; ++k) {
          const double t = static_cast<double>(k) / n, s = 1 - t;
          current.push_back(s * s * s * pen + 3 * s * s * t * c1 + 3 * s * t * t * c2 + t * t * t * end);
        }
        pen = end;
        break;
      }
      case 'Z':
        closed = true;
        pen = start;
        finish();
        current.push_back(pen);  // a following command without M continues from the start
        break;
      default:
        throw EngineError(path.string() + ": path command '" + std::string(1, command) +
                          "' is not supported; use M, L, H, V, C, Q and Z (convert arcs and smooth curves to paths)");
    }
  }
  finish();
}

}  // namespace

Polygon2 read_svg_outline(const std::filesystem::path& path) {
  const std::string text = read_text(path);
  const size_t svg_at = text.find("<svg");
  if (svg_at == std::string::npos) throw EngineError(path.string() + " is not an SVG file: no <svg> element");
  const size_t svg_end = text.find('>', svg_at);
  if (svg_end == std::string::npos) throw EngineError(path.string() + " is not an SVG file: the <svg> tag is not closed");
  if (text.find("transform", svg_at) != std::string::npos)
    throw EngineError(path.string() + ": transform attributes are not supported; apply them to the paths first");
  const double scale = user_unit_mm(path, text.substr(svg_at, svg_end - svg_at));
  Subpaths subpaths;
  for (size_t at = text.find("<path", svg_end); at != std::string::npos; at = text.find("<path", at + 5)) {
    const size_t end = text.find('>', at);
    if (end == std::string::npos) throw EngineError(path.string() + " is not an SVG file: a <path> tag is not closed");
    if (const auto d = attribute(text.substr(at, end - at), "d")) parse_path(path, *d, scale, subpaths);
  }
  return largest_closed_outline(path, std::move(subpaths.closed), subpaths.open);
}

}  // namespace lastcut
