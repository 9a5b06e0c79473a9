// The comparison picture (compare_report.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

#include "engine/compare/compare_report.hpp"
#include "engine/core/decimal_text.hpp"
#include "engine/core/svg_document.hpp"

namespace lastcut {

namespace {

constexpr double kMargin_mm = 12.0;
constexpr double kLegendHeight_mm = 26.0;
constexpr int kBins = 9;
// Diverging scale (ColorBrewer "RdBu" reversed): blue = mold inside the reference (too small),
// white = on it, red = mold outside (too large).
constexpr std::array<const char*, kBins> kBinColors = {"#2166ac", "#4393c3", "#92c5de", "#d1e5f0", "#f7f7f7",
                                                       "#fddbc7", "#f4a582", "#d6604d", "#b2182b"};

std::string fmt(double value, int decimals = 2) { return fixed_text(value, decimals); }

struct Frame {
  double min_x, max_y;
  std::string x(double u) const { return fmt(u - min_x + kMargin_mm); }
  std::string y(double v) const { return fmt(max_y - v + kMargin_mm); }
  std::string at(const Point2& p) const { return x(p.x()) + "," + y(p.y()); }
};

// Upper end of the colour scale: the tolerance, or the largest deviation rounded up to 0.5 mm.
double scale_limit_mm(const Comparison& comparison, double tolerance_mm) {
  double largest = 0.0;
  for (const auto& d : comparison.deviation.along_mold) largest = std::max(largest, std::abs(d.signed_mm));
  return std::max({tolerance_mm, std::ceil(largest * 2.0) / 2.0, 0.5});
}

int bin_of(double signed_mm, double limit_mm) {
  const double t = std::clamp((signed_mm / limit_mm + 1.0) / 2.0, 0.0, 1.0);
  return std::min(kBins - 1, static_cast<int>(t * kBins));
}

}  // namespace

std::string comparison_svg(const Comparison& comparison, double tolerance_mm) {
  Point2 lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  Point2 hi = -lo;
  for (const auto* outline : {&comparison.mold.outline, &comparison.reference_moved.outline})
    for (const auto& p : outline->points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  const Frame frame{lo.x(), hi.y()};
  const double width = std::max(hi.x() - lo.x() + 2 * kMargin_mm, 150.0);
  const double drawing_height = hi.y() - lo.y() + 2 * kMargin_mm;
  std::string svg = svg_document_start({0.0, 0.0, width, drawing_height + kLegendHeight_mm}, 0,
                                       "font-family=\"sans-serif\"");
  svg += "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";

  svg += "<polygon id=\"reference\" fill=\"#eeeeee\" stroke=\"#555555\" stroke-width=\"0.3\" "
         "stroke-dasharray=\"2,1\" points=\"";
  for (const auto& p : comparison.reference_moved.outline.points) svg += frame.at(p) + " ";
  svg += "\"/>\n";

  // The mold's edge: a dark underlay (the light middle of the scale must show on white), then
  // one run of segments per colour bin.
  svg += "<polygon id=\"mold\" fill=\"none\" stroke=\"#222222\" stroke-width=\"1.1\" points=\"";
  for (const auto& p : comparison.mold.outline.points) svg += frame.at(p) + " ";
  svg += "\"/>\n";
  const double limit = scale_limit_mm(comparison, tolerance_mm);
  const auto& samples = comparison.deviation.along_mold;
  svg += "<g id=\"mold-edge\" fill=\"none\" stroke-width=\"0.8\" stroke-linecap=\"round\">\n";
  for (size_t i = 0; i < samples.size();) {
    const int bin = bin_of(samples[i].signed_mm, limit);
    svg += "<polyline stroke=\"" + std::string(kBinColors[static_cast<size_t>(bin)]) + "\" points=\"" +
           frame.at(samples[i].at_mm);
    size_t j = i + 1;
    for (; j < samples.size() && bin_of(samples[j].signed_mm, limit) == bin; ++j) svg += " " + frame.at(samples[j].at_mm);
    svg += " " + frame.at(samples[j % samples.size()].at_mm) + "\"/>\n";
    i = j;
  }
  svg += "</g>\n<g id=\"margins\" font-size=\"3.5\">\n";
  for (const auto& corner : comparison.corners) {
    const char* colour = corner.margin_mm > tolerance_mm ? "#d00000" : "#007000";
    svg += "<line x1=\"" + frame.x(corner.mold_mm.x()) + "\" y1=\"" + frame.y(corner.mold_mm.y()) + "\" x2=\"" +
           frame.x(corner.reference_mm.x()) + "\" y2=\"" + frame.y(corner.reference_mm.y()) + "\" stroke=\"" + colour +
           "\" stroke-width=\"0.4\"/>\n";
    svg += "<circle cx=\"" + frame.x(corner.mold_mm.x()) + "\" cy=\"" + frame.y(corner.mold_mm.y()) +
           "\" r=\"0.8\" fill=\"" + colour + "\"/>\n";
    svg += "<circle cx=\"" + frame.x(corner.reference_mm.x()) + "\" cy=\"" + frame.y(corner.reference_mm.y()) +
           "\" r=\"0.8\" fill=\"none\" stroke=\"" + colour + "\" stroke-width=\"0.3\"/>\n";
    svg += "<text x=\"" + frame.x(corner.mold_mm.x() + 1.5) + "\" y=\"" + frame.y(corner.mold_mm.y() + 1.5) +
           "\" fill=\"" + colour + "\">" + xml_escaped(corner.name) + " " + fmt(corner.margin_mm) + " mm</text>\n";
  }
  svg += "</g>\n";

  const double top = drawing_height;
  const OverlapAlignment& a = comparison.alignment;
  svg += "<g id=\"legend\" font-size=\"3\">\n<text x=\"" + fmt(kMargin_mm) + "\" y=\"" + fmt(top + 3) + "\">mold " +
         xml_escaped(comparison.mold.name) + " (coloured edge) against reference " +
         xml_escaped(comparison.reference_moved.name) + " (grey, dashed" + (a.motion.mirrored ? ", mirrored" : "") +
         "): overlap " + fmt(100.0 * a.overlap_fraction()) + " %, Hausdorff " + fmt(comparison.deviation.hausdorff_mm) +
         " mm, corner tolerance " + fmt(tolerance_mm, 1) + " mm</text>\n";
  const double bar = (width - 2 * kMargin_mm) / kBins;
  for (int b = 0; b < kBins; ++b) {
    const double x = kMargin_mm + b * bar;
    svg += "<rect x=\"" + fmt(x) + "\" y=\"" + fmt(top + 6) + "\" width=\"" + fmt(bar) + "\" height=\"5\" fill=\"" +
           kBinColors[static_cast<size_t>(b)] + "\" stroke=\"#888888\" stroke-width=\"0.1\"/>\n";
  }
  for (int tick = 0; tick <= kBins; tick += 3) {
    const double value = -limit + 2.0 * limit * tick / kBins;
    svg += "<text x=\"" + fmt(kMargin_mm + tick * bar) + "\" y=\"" + fmt(top + 15) + "\" text-anchor=\"middle\">" +
           fmt(value) + "</text>\n";
  }
  svg += "<text x=\"" + fmt(kMargin_mm) + "\" y=\"" + fmt(top + 21) +
         "\">mold edge deviation, mm: - inside the reference (mold too small), + outside (too large)</text>\n</g>\n";
  svg += kSvgDocumentEnd;
  return svg;
}

}  // namespace lastcut
