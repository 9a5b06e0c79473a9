#include "engine/nest/layout_svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/core/polygon_centroid.hpp"
#include "engine/core/svg_document.hpp"

namespace lastcut {
namespace {

struct Frame {
  double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
  void add(const Polygon2& p) {
    for (const Point2& q : p.points) x0 = std::min(x0, q.x()), y0 = std::min(y0, q.y()), x1 = std::max(x1, q.x()), y1 = std::max(y1, q.y());
  }
};

std::string points(const Polygon2& polygon, double dx, double dy) {
  std::ostringstream out;
  out.precision(10);
  for (const Point2& p : polygon.points) out << (p.x() + dx) << ',' << (p.y() + dy) << ' ';
  return out.str();
}

// A piece's label as drawn: one line when it fits across the piece, else two (split at the space
// nearest the middle: "m-42-left" over "medial"), the font shrunk until the longer line fits, but not
// below 40 % of the drawing's text size. Glyphs are taken as 0.6 em wide (sans-serif, generous).
struct LabelLayout {
  std::vector<std::string> lines;
  double font_size = 0;
};

LabelLayout fit_label(const std::string& label, double piece_width, double text_size) {
  constexpr double kGlyphEm = 0.6, kUsableWidth = 0.9, kSmallestShare = 0.4;
  auto fitting_size = [&](const std::vector<std::string>& lines) {
    size_t longest = 1;
    for (const std::string& line : lines) longest = std::max(longest, line.size());
    return std::clamp(kUsableWidth * piece_width / (kGlyphEm * static_cast<double>(longest)), kSmallestShare * text_size, text_size);
  };
  LabelLayout one{{label}, fitting_size({label})};
  const size_t middle = label.size() / 2;
  size_t split = std::string::npos;
  for (size_t i = 0; i < label.size(); ++i)
    if (label[i] == ' ' && (split == std::string::npos || std::abs(static_cast<double>(i) - middle) < std::abs(static_cast<double>(split) - middle)))
      split = i;
  if (one.font_size >= text_size || split == std::string::npos) return one;
  LabelLayout two{{label.substr(0, split), label.substr(split + 1)}, 0};
  two.font_size = fitting_size(two.lines);
  return two.font_size > one.font_size ? two : one;
}

}  // namespace

std::string layout_svg(const Layout& layout, const NestInstance& instance) {
  // Panels: the strip, or one per used hide copy, stacked downwards.
  struct Panel {
    int bin = -1, copy = 0;
    Frame frame;
  };
  std::vector<Panel> panels;
  if (instance.strip_height) {
    Panel strip;
    strip.frame = {0, 0, std::max(1e-9, layout.strip_length.value_or(0)), *instance.strip_height};
    panels.push_back(strip);
  } else {
    std::set<std::pair<int, int>> used;
    for (const Placement& p : layout.placements) used.insert({p.bin, p.copy});
    for (const auto& [bin, copy] : used) {
      Panel panel{bin, copy, {}};
      panel.frame.add(find_bin(instance, bin).outer);
      panels.push_back(panel);
    }
  }
  double width = 1, height = 0;
  for (const Panel& p : panels) width = std::max(width, p.frame.x1 - p.frame.x0), height += (p.frame.y1 - p.frame.y0);
  const double pad = 0.03 * width, text_size = 0.018 * width;
  const double header = 3 * text_size;
  const double footer = (layout.unplaced.size() + 1) * 1.5 * text_size;
  height += pad * (panels.size() + 1) + header + footer;
  std::ostringstream svg;
  svg.precision(10);
  svg << svg_document_start({0.0, 0.0, width + 2 * pad, height}, 1200, "font-family=\"sans-serif\"");
  svg << "<defs><pattern id=\"defect\" width=\"" << text_size << "\" height=\"" << text_size
      << "\" patternUnits=\"userSpaceOnUse\" patternTransform=\"rotate(45)\"><rect width=\"" << text_size << "\" height=\""
      << text_size << "\" fill=\"#f4c7c3\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"" << text_size
      << "\" stroke=\"#c0392b\" stroke-width=\"" << text_size / 4 << "\"/></pattern></defs>\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  char title[512];
  std::snprintf(title, sizeof title, "%s: %zu pieces placed, utilisation %.1f %%", layout.instance.c_str(),
                layout.placements.size(), 100 * layout.utilisation);
  std::string line = title;
  if (layout.strip_length) {
    std::snprintf(title, sizeof title, ", strip %.1f x %.1f mm", *layout.strip_length, *instance.strip_height);
    line += title;
  } else {
    line += ", " + std::to_string(used_bin_count(layout)) + " hide(s)";
  }
  svg << "<text x=\"" << pad << "\" y=\"" << 2 * text_size << "\" font-size=\"" << 1.3 * text_size << "\">" << xml_escaped(line) << "</text>\n";
  double top = header + pad;
  const double stroke = 0.0015 * width;
  for (const Panel& panel : panels) {
    const double panel_height = panel.frame.y1 - panel.frame.y0;
    // Flip y inside the panel: the layout's y axis points up.
    svg << "<g transform=\"translate(" << pad - panel.frame.x0 << ',' << top + panel.frame.y1 << ") scale(1,-1)\">\n";
    if (panel.bin < 0) {
      svg << "<rect x=\"0\" y=\"0\" width=\"" << panel.frame.x1 << "\" height=\"" << panel.frame.y1
          << "\" fill=\"#f3ead7\" stroke=\"#6b4f2a\" stroke-width=\"" << stroke << "\"/>\n";
    } else {
      const Bin& bin = find_bin(instance, panel.bin);
      svg << "<polygon points=\"" << points(bin.outer, 0, 0) << "\" fill=\"#f3ead7\" stroke=\"#6b4f2a\" stroke-width=\"" << stroke << "\"/>\n";
      for (const QualityZone& zone : bin.zones)
        svg << "<polygon points=\"" << points(zone.shape, 0, 0) << "\" fill=\"#f5b041\" fill-opacity=\"0.45\" stroke=\"#ca6f1e\" stroke-width=\""
            << stroke / 2 << "\"><title>quality " << zone.quality << "</title></polygon>\n";
      for (const Polygon2& hole : bin.holes)
        svg << "<polygon points=\"" << points(hole, 0, 0) << "\" fill=\"url(#defect)\" stroke=\"#c0392b\" stroke-width=\"" << stroke << "\"/>\n";
    }
    for (const Placement& p : layout.placements) {
      if (p.bin != panel.bin || p.copy != panel.copy) continue;
      const NestItem& item = find_item(instance, p.item);
      svg << "<polygon points=\"" << points(placed_shape(item, p), 0, 0) << "\" fill=\"#aed6f1\" fill-opacity=\"0.85\" stroke=\"#1b4f72\" stroke-width=\""
          << stroke << "\"/>\n";
      for (const ItemMark& mark : item.marks) {
        const Point2 a = place_point(mark.from_mm, p), b = place_point(mark.to_mm, p);
        svg << "<line x1=\"" << a.x() << "\" y1=\"" << a.y() << "\" x2=\"" << b.x() << "\" y2=\"" << b.y()
            << "\" stroke=\"#7d3c98\" stroke-width=\"" << stroke << "\"/>\n";
      }
      // Drawn lines thin and dashed: the pen draws them, nothing cuts them.
      for (const std::vector<Point2>& drawn : item.drawn_lines_mm) {
        Polygon2 placed;
        for (const Point2& q : drawn) placed.points.push_back(place_point(q, p));
        svg << "<polyline points=\"" << points(placed, 0, 0) << "\" fill=\"none\" stroke=\"#1b4f72\" stroke-width=\"" << stroke / 2
            << "\" stroke-dasharray=\"" << 3 * stroke << ',' << 2 * stroke << "\"/>\n";
      }
    }
    svg << "</g>\n";
    // Labels upright, outside the flipped group.
    for (const Placement& p : layout.placements) {
      if (p.bin != panel.bin || p.copy != panel.copy) continue;
      const NestItem& item = find_item(instance, p.item);
      const Polygon2 shape = placed_shape(item, p);
      const Point2 c = area_centroid(shape);
      Frame box;
      box.add(shape);
      const std::string label = (item.label.empty() ? std::to_string(item.id) : item.label) + (p.mirrored ? " (m)" : "");
      const LabelLayout fitted = fit_label(label, box.x1 - box.x0, text_size);
      const double first_line_y = top + panel.frame.y1 - c.y() - 0.5 * (fitted.lines.size() - 1) * 1.1 * fitted.font_size;
      for (size_t k = 0; k < fitted.lines.size(); ++k)
        svg << "<text x=\"" << pad - panel.frame.x0 + c.x() << "\" y=\"" << first_line_y + k * 1.1 * fitted.font_size
            << "\" font-size=\"" << fitted.font_size << "\" text-anchor=\"middle\" dominant-baseline=\"middle\" fill=\"#17202a\">"
            << xml_escaped(fitted.lines[k]) << "</text>\n";
    }
    if (panel.bin >= 0)
      svg << "<text x=\"" << pad << "\" y=\"" << top + text_size << "\" font-size=\"" << text_size << "\" fill=\"#6b4f2a\">hide "
          << panel.bin << (panel.copy > 0 ? " copy " + std::to_string(panel.copy) : "") << "</text>\n";
    top += panel_height + pad;
  }
  for (const Unplaced& u : layout.unplaced) {
    top += 1.5 * text_size;
    svg << "<text x=\"" << pad << "\" y=\"" << top << "\" font-size=\"" << text_size << "\" fill=\"#c0392b\">NOT PLACED: "
        << xml_escaped(unplaced_text(u, instance)) << "</text>\n";
  }
  svg << kSvgDocumentEnd;
  return svg.str();
}

void write_layout_svg(const std::filesystem::path& path, const Layout& layout, const NestInstance& instance) {
  std::ofstream out(path);
  if (!out) throw EngineError("cannot write picture " + path.string());
  out << layout_svg(layout, instance);
  if (!out) throw EngineError("writing picture " + path.string() + " failed");
}

}  // namespace lastcut
