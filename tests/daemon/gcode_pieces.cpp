#include "tests/daemon/gcode_pieces.hpp"

#include <cmath>
#include <numbers>
#include <regex>
#include <sstream>

#include "engine/core/polygon_centroid.hpp"

namespace lastcut::daemon::testing {
namespace {

// The value of `letter` on a G-code line, if the line has it.
bool word(const std::string& line, char letter, double& value) {
  for (std::size_t at = 0; at < line.size(); ++at) {
    if (line[at] != letter) continue;
    char* end = nullptr;
    const double read = std::strtod(line.c_str() + at + 1, &end);
    if (end == line.c_str() + at + 1) continue;
    value = read;
    return true;
  }
  return false;
}

}  // namespace

std::vector<CutPiece> pieces_of_gcode(const std::string& gcode) {
  std::vector<CutPiece> pieces;
  const std::regex piece_comment(R"(^; piece \d+/\d+: (.*?) ?\(item (\d+)\)\s*$)");
  std::istringstream lines(gcode);
  std::string line;
  Point2 at(0, 0);
  double z = 0;
  int motion = 0;
  while (std::getline(lines, line)) {
    std::smatch match;
    if (std::regex_match(line, match, piece_comment)) {
      pieces.push_back({match[1].str(), std::stoi(match[2].str()), {}});
      continue;
    }
    if (line.empty() || line[0] == ';' || line[0] == '(') continue;
    double g = -1;
    if (word(line, 'G', g) && g >= 0 && g <= 3) motion = static_cast<int>(g);
    Point2 to = at;
    word(line, 'X', to.x());
    word(line, 'Y', to.y());
    word(line, 'Z', z);
    const bool down = z < 0 && !pieces.empty();
    if (down && pieces.back().knife_path_mm.empty()) pieces.back().knife_path_mm.push_back(at);
    if (down && (motion == 2 || motion == 3) && (to - at).norm() > 0) {
      double i = 0, j = 0;
      word(line, 'I', i);
      word(line, 'J', j);
      const Point2 center = at + Point2(i, j);
      const double radius = (at - center).norm();
      double start = std::atan2(at.y() - center.y(), at.x() - center.x());
      double sweep = std::atan2(to.y() - center.y(), to.x() - center.x()) - start;
      if (motion == 3 && sweep <= 0) sweep += 2 * std::numbers::pi;  // counter-clockwise
      if (motion == 2 && sweep >= 0) sweep -= 2 * std::numbers::pi;  // clockwise
      const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / (2 * std::numbers::pi / 180))));
      for (int k = 1; k < steps; ++k) {
        const double angle = start + sweep * k / steps;
        pieces.back().knife_path_mm.emplace_back(center.x() + radius * std::cos(angle), center.y() + radius * std::sin(angle));
      }
      pieces.back().knife_path_mm.push_back(to);
    } else if (down && motion == 1 && (to - at).norm() > 0) {
      pieces.back().knife_path_mm.push_back(to);
    }
    at = to;
  }
  return pieces;
}

Polygon2 cut_outline(const CutPiece& piece) {
  Polygon2 ring;
  const std::vector<Point2>& path = piece.knife_path_mm;
  if (path.size() < 4) return ring;
  // The knife returns to its start and runs on past it (the overcut): the ring ends at the return.
  double run = 0;
  std::size_t end = path.size();
  for (std::size_t k = 1; k < path.size(); ++k) {
    run += (path[k] - path[k - 1]).norm();
    if (run > 20 && (path[k] - path.front()).norm() < 0.6) {
      end = k;
      break;
    }
  }
  ring.points.assign(path.begin(), path.begin() + static_cast<std::ptrdiff_t>(end));
  return ring;
}

double principal_axis_deg(const Polygon2& ring) {
  const Point2 axis = principal_axis(ring);
  double deg = std::atan2(axis.y(), axis.x()) * 180 / std::numbers::pi;
  if (deg < 0) deg += 180;
  return deg >= 180 ? deg - 180 : deg;
}

}  // namespace lastcut::daemon::testing
