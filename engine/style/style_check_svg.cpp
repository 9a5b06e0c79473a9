#include "engine/style/style_check_svg.hpp"

#include <algorithm>
#include <limits>

#include "engine/core/decimal_text.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/svg_document.hpp"
#include "engine/mold/clipper_paths.hpp"
#include "engine/style/forme_boundary.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut {
namespace {

constexpr double kSheetMargin_mm = 12;
constexpr double kHalfGap_mm = 25;       // between the medial and the lateral half
constexpr double kTitleHeight_mm = 14;   // above the halves: the title and the halves' names
constexpr double kNameSize_mm = 5;
// ColorBrewer "Set3": light colours that stay apart and keep black lines and text readable.
constexpr std::array<const char*, 10> kPieceColours = {"#8dd3c7", "#ffffb3", "#bebada", "#fb8072", "#80b1d3",
                                                       "#fdb462", "#b3de69", "#fccde5", "#d9d9d9", "#bc80bd"};

struct EdgeLook {
  EdgeKind kind;
  const char* stroke;
  const char* dash;
};
constexpr std::array<EdgeLook, 4> kEdgeLooks = {{{EdgeKind::Feather, "#6b3e1f", ""},
                                                 {EdgeKind::Top, "#1f4e9c", ""},
                                                 {EdgeKind::FrontSeam, "#555555", " stroke-dasharray=\"3 2\""},
                                                 {EdgeKind::BackSeam, "#555555", " stroke-dasharray=\"3 2\""}}};

// Where each half's flattening goes on the sheet: its box moved right of the one before, y turned down.
struct SheetPlacement {
  std::array<Point2, 2> low, high;
  std::array<double, 2> left_mm{};
  double width_mm = 0, height_mm = 0;

  explicit SheetPlacement(const std::array<const SegmentResult*, 2>& halves) {
    double x_mm = kSheetMargin_mm, tallest_mm = 0;
    for (std::size_t h = 0; h < 2; ++h) {
      const Eigen::MatrixXd& uv = halves[h]->UV;
      low[h] = uv.colwise().minCoeff().transpose();
      high[h] = uv.colwise().maxCoeff().transpose();
      left_mm[h] = x_mm;
      x_mm += high[h].x() - low[h].x() + kHalfGap_mm;
      tallest_mm = std::max(tallest_mm, high[h].y() - low[h].y());
    }
    width_mm = x_mm - kHalfGap_mm + kSheetMargin_mm;
    height_mm = kTitleHeight_mm + tallest_mm + 2 * kSheetMargin_mm;
  }
  Point2 at(std::size_t half, const Point2& uv) const {
    return {left_mm[half] + uv.x() - low[half].x(), kSheetMargin_mm + kTitleHeight_mm + high[half].y() - uv.y()};
  }
  void append(std::string& out, std::size_t half, const Point2& uv) const {
    const Point2 p = at(half, uv);
    append_fixed(out, p.x(), 2);
    out += ',';
    append_fixed(out, p.y(), 2);
  }
};

std::string polyline(const SheetPlacement& sheet, std::size_t half, const std::vector<Point2>& points, const std::string& attributes) {
  std::string text = "<polyline " + attributes + " fill=\"none\" points=\"";
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (i > 0) text += ' ';
    sheet.append(text, half, points[i]);
  }
  return text + "\"/>\n";
}

std::string region_path(const SheetPlacement& sheet, const PieceForme& piece, const char* colour) {
  std::string d;
  for (std::size_t h = 0; h < 2; ++h)
    for (const ClipperLib::Path& ring : piece.rings[h]) {
      for (std::size_t i = 0; i < ring.size(); ++i) {
        d += i == 0 ? 'M' : 'L';
        sheet.append(d, h, Point2(static_cast<double>(ring[i].X), static_cast<double>(ring[i].Y)) / kClipperUnitsPerMm);
      }
      d += 'Z';
    }
  return "<path class=\"piece-region\" data-piece=\"" + xml_escaped(piece.name) + "\" fill=\"" + colour +
         "\" fill-rule=\"evenodd\" stroke=\"none\" d=\"" + d + "\"/>\n";
}

// The half's own edges, each a polyline of its outline vertices in the flattening.
std::string half_edges(const SheetPlacement& sheet, std::size_t h, const SegmentResult& half) {
  const FormeBoundary boundary = forme_boundary(half.mesh3d, half.topology, half.landmarks);
  std::string text;
  for (const EdgeLook& look : kEdgeLooks) {
    std::vector<Point2> points;
    for (const int v : boundary.edge(look.kind).vertices) points.push_back(half.UV.row(v).transpose());
    text += polyline(sheet, h, points,
                     "class=\"edge\" data-edge=\"" + to_string(look.kind) + "\" stroke=\"" + look.stroke + "\" stroke-width=\"0.6\"" + look.dash);
  }
  return text;
}

// A transferred line as the stretches it makes on each half.
std::string line_stretches(const SheetPlacement& sheet, const std::string& name, const TransferredCurve& line) {
  std::string text;
  std::vector<Point2> stretch;
  std::size_t stretch_half = 0;
  const auto flush = [&] {
    if (stretch.size() >= 2)
      text += polyline(sheet, stretch_half, stretch,
                       "class=\"style-line\" data-line=\"" + xml_escaped(name) + "\" stroke=\"#000000\" stroke-width=\"0.5\"");
    stretch.clear();
  };
  for (const TransferredPoint& point : line.points) {
    const std::size_t h = point.half == "lateral" ? 1 : 0;
    if (!stretch.empty() && (h != stretch_half || (point.forme_uv_mm - stretch.back()).norm() > kRunGap_mm)) flush();  // left the upper and came back: not drawn
    stretch_half = h;
    stretch.push_back(point.forme_uv_mm);
  }
  flush();
  return text;
}

// A text at a point of the sheet (mm).
std::string text_at(const Point2& at, const std::string& attributes, const std::string& words) {
  return "<text " + attributes + " x=\"" + fixed_text(at.x(), 2) + "\" y=\"" + fixed_text(at.y(), 2) + "\">" + xml_escaped(words) + "</text>\n";
}

}  // namespace

void write_style_check_svg(const std::filesystem::path& path, const StyleCheckSheet& sheet) {
  const SheetPlacement placement(sheet.halves);
  std::string svg = svg_document_start({0, 0, placement.width_mm, placement.height_mm}, 0, "font-family=\"sans-serif\"");
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"#ffffff\"/>\n";
  svg += text_at({kSheetMargin_mm, kSheetMargin_mm}, "font-size=\"6\"", sheet.title);
  for (std::size_t h = 0; h < 2; ++h)
    svg += text_at({placement.left_mm[h], kSheetMargin_mm + kTitleHeight_mm - 3}, "class=\"half-name\" font-size=\"5\"", sheet.halves[h]->name);
  for (std::size_t p = 0; p < sheet.pieces.size(); ++p)
    svg += region_path(placement, sheet.pieces[p], kPieceColours[p % kPieceColours.size()]);
  for (std::size_t h = 0; h < 2; ++h) svg += half_edges(placement, h, *sheet.halves[h]);
  for (const auto& [name, line] : sheet.lines) svg += line_stretches(placement, name, line);
  for (std::size_t p = 0; p < sheet.pieces.size() && p < sheet.labels.size(); ++p) {
    if (!sheet.labels[p]) continue;
    const TransferredPoint& label = *sheet.labels[p];
    svg += text_at(placement.at(label.half == "lateral" ? 1 : 0, label.forme_uv_mm),
                   "class=\"piece-name\" font-size=\"" + fixed_text(kNameSize_mm, 1) + "\" text-anchor=\"middle\"", sheet.pieces[p].name);
  }
  svg += kSvgDocumentEnd;
  if (const Status written = write_file_durably(path, svg); !written) throw EngineError(written.error());
}

}  // namespace lastcut
