#include "engine/nest/layout_svg.hpp"

#include <algorithm>
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
    }
    svg << "</g>\n";
    // Labels upright, outside the flipped group.
    for (const Placement& p : layout.placements) {
      if (p.bin != panel.bin || p.copy != panel.copy) continue;
      const NestItem& item = find_item(instance, p.item);
      const Point2 c = area_centroid(placed_shape(item, p));
      const std::string label = item.label.empty() ? std::to_string(item.id) : item.label;
      svg << "<text x=\"" << pad - panel.frame.x0 + c.x() << "\" y=\"" << top + panel.frame.y1 - c.y() << "\" font-size=\"" << text_size
          << "\" text-anchor=\"middle\" dominant-baseline=\"middle\" fill=\"#17202a\">" << xml_escaped(label) << (p.mirrored ? " (m)" : "") << "</text>\n";
    }
    if (panel.bin >= 0)
      svg << "<text x=\"" << pad << "\" y=\"" << top + text_size << "\" font-size=\"" << text_size << "\" fill=\"#6b4f2a\">hide "
          << panel.bin << (panel.copy > 0 ? " copy " + std::to_string(panel.copy) : "") << "</text>\n";
    top += panel_height + pad;
  }
  for (const Unplaced& u : layout.unplaced) {
    top += 1.5 * text_size;
    svg << "<text x=\"" << pad << "\" y=\"" << top << "\" font-size=\"" << text_size << "\" fill=\"#c0392b\">NOT PLACED: item " << u.item << " x"
        << u.count << ": " << xml_escaped(u.reason) << "</text>\n";
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
