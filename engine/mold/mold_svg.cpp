#include "engine/mold/mold_svg.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "engine/core/decimal_text.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/svg_document.hpp"

namespace lastcut {

namespace {

constexpr double kMargin_mm = 10.0;
constexpr double kLegendHeight_mm = 28.0;
constexpr int kBins = 10;
// Sequential colour scale, low strain to high (ColorBrewer "YlOrRd"-like, dark red = most strain).
constexpr std::array<const char*, kBins> kBinColors = {"#ffffcc", "#ffeda0", "#fed976", "#feb24c", "#fd8d3c",
                                                       "#fc4e2a", "#e31a1c", "#bd0026", "#990026", "#800026"};

std::string fmt(double value, int decimals = 2) { return fixed_text(value, decimals); }

double percentile(std::vector<double> values, double fraction) {
  if (values.empty()) return 1.0;
  const size_t k = std::min(values.size() - 1, static_cast<size_t>(fraction * static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

struct Frame {
  double min_x, max_y;
  std::string x(double u) const { return fmt(u - min_x + kMargin_mm); }
  std::string y(double v) const { return fmt(max_y - v + kMargin_mm); }
  std::string at(const Point2& p) const { return x(p.x()) + "," + y(p.y()); }
};

}  // namespace

void write_mold_svg(const std::filesystem::path& path, const Mold& mold, const Eigen::MatrixXd& UV,
                    const Eigen::MatrixXi& F, const Eigen::VectorXd& stretch_per_triangle) {
  if (UV.cols() != 2) throw EngineError("mold picture: flattened positions must have 2 columns");
  if (stretch_per_triangle.size() != F.rows())
    throw EngineError("mold picture: " + std::to_string(stretch_per_triangle.size()) + " stretch values for " +
                      std::to_string(F.rows()) + " triangles");
  if (F.rows() > 0 && (F.minCoeff() < 0 || F.maxCoeff() >= UV.rows()))
    throw EngineError("mold picture: a triangle refers to a vertex that does not exist");

  Point2 lo(std::numeric_limits<double>::max(), std::numeric_limits<double>::max());
  Point2 hi = -lo;
  for (Eigen::Index v = 0; v < UV.rows(); ++v) lo = lo.cwiseMin(UV.row(v).transpose()), hi = hi.cwiseMax(UV.row(v).transpose());
  for (const auto& p : mold.outline.points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
  if (!(lo.x() <= hi.x())) lo = hi = Point2::Zero();
  const Frame frame{lo.x(), hi.y()};
  const double width_mm = std::max(hi.x() - lo.x() + 2 * kMargin_mm, 80.0);
  const double drawing_height_mm = hi.y() - lo.y() + 2 * kMargin_mm;
  const double height_mm = drawing_height_mm + kLegendHeight_mm;

  // Colour range: robust to a few extreme triangles, never narrower than 1 % either side of 1.
  std::vector<double> values(stretch_per_triangle.data(), stretch_per_triangle.data() + stretch_per_triangle.size());
  values.erase(std::remove_if(values.begin(), values.end(), [](double s) { return !std::isfinite(s); }), values.end());
  const double low = std::min(percentile(values, 0.01), 0.99);
  const double high = std::max(percentile(values, 0.99), 1.01);

  // Each vertex's "x,y" is formatted once: a vertex is shared by about six triangles.
  std::vector<std::string> vertex_at(static_cast<size_t>(UV.rows()));
  for (Eigen::Index v = 0; v < UV.rows(); ++v) vertex_at[v] = frame.at(UV.row(v).transpose());
  std::vector<std::string> bin_paths(kBins);
  for (Eigen::Index f = 0; f < F.rows(); ++f) {
    const double s = stretch_per_triangle(f);
    const double t = std::isfinite(s) ? std::clamp((s - low) / (high - low), 0.0, 1.0) : 1.0;
    const int bin = std::min(kBins - 1, static_cast<int>(t * kBins));
    std::string& d = bin_paths[bin];
    d += 'M';
    d += vertex_at[F(f, 0)];
    d += 'L';
    d += vertex_at[F(f, 1)];
    d += 'L';
    d += vertex_at[F(f, 2)];
    d += 'Z';
  }

  std::ostringstream svg;
  svg << svg_document_start({0.0, 0.0, width_mm, height_mm})
      << "<title>mold " << xml_escaped(mold.name) << ": stretch of the leather (1 = unstrained), 1:1 in mm</title>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n<g id=\"stretch\" stroke-width=\"0.02\">\n";
  for (int b = 0; b < kBins; ++b) {
    const std::string& d = bin_paths[b];
    if (!d.empty())
      svg << "<path fill=\"" << kBinColors[b] << "\" stroke=\"" << kBinColors[b] << "\" d=\"" << d << "\"/>\n";
  }
  svg << "</g>\n<polygon id=\"outline\" fill=\"none\" stroke=\"black\" stroke-width=\"0.35\" points=\"";
  for (const auto& p : mold.outline.points) svg << frame.at(p) << ' ';
  svg << "\"/>\n";
  // The net line (the last's edge) dashed inside the cut outline: drawn, never cut.
  if (!mold.net.points.empty()) {
    svg << "<polygon id=\"net\" fill=\"none\" stroke=\"#303030\" stroke-width=\"0.25\" stroke-dasharray=\"2,1\" points=\"";
    for (const auto& p : mold.net.points) svg << frame.at(p) << ' ';
    svg << "\"/>\n";
  }
  svg << "<g id=\"marks\" stroke=\"#0050c8\" stroke-width=\"0.5\" font-family=\"sans-serif\" font-size=\"3\" "
         "fill=\"#0050c8\">\n";
  for (const auto& mark : mold.marks) {
    const Point2 inner = notch_inner_end(mark);
    const Point2 label = mark.position_mm + 3.0 * kNotchLength_mm * mark.inward_direction;
    svg << "<line x1=\"" << frame.x(mark.position_mm.x()) << "\" y1=\"" << frame.y(mark.position_mm.y()) << "\" x2=\""
        << frame.x(inner.x()) << "\" y2=\"" << frame.y(inner.y()) << "\"/>"
        << "<text stroke=\"none\" text-anchor=\"middle\" x=\"" << frame.x(label.x()) << "\" y=\"" << frame.y(label.y())
        << "\">" << xml_escaped(mark.name) << "</text>\n";
  }
  svg << "</g>\n";

  // Legend: colour bar with its values, the mold name and a scale bar.
  const double legend_top = drawing_height_mm + 2.0;
  const double bar_width = 6.0;
  svg << "<g id=\"legend\" font-family=\"sans-serif\" font-size=\"3\">\n"
      << "<text x=\"" << fmt(kMargin_mm) << "\" y=\"" << fmt(legend_top + 3) << "\">mold " << xml_escaped(mold.name)
      << " - stretch (1 = unstrained)</text>\n";
  for (int b = 0; b < kBins; ++b) {
    const double x = kMargin_mm + b * bar_width;
    svg << "<rect x=\"" << fmt(x) << "\" y=\"" << fmt(legend_top + 5) << "\" width=\"" << fmt(bar_width)
        << "\" height=\"5\" fill=\"" << kBinColors[b] << "\" stroke=\"black\" stroke-width=\"0.1\"/>\n";
  }
  for (int tick = 0; tick <= kBins; tick += kBins / 2) {
    svg << "<text text-anchor=\"middle\" x=\"" << fmt(kMargin_mm + tick * bar_width) << "\" y=\""
        << fmt(legend_top + 14) << "\">" << fmt(low + (high - low) * tick / kBins, 3) << "</text>\n";
  }
  const double scale_y = legend_top + 20;
  svg << "<line x1=\"" << fmt(kMargin_mm) << "\" y1=\"" << fmt(scale_y) << "\" x2=\"" << fmt(kMargin_mm + 50) << "\" y2=\""
      << fmt(scale_y) << "\" stroke=\"black\" stroke-width=\"0.5\"/>\n"
      << "<text x=\"" << fmt(kMargin_mm + 52) << "\" y=\"" << fmt(scale_y + 1) << "\">50 mm</text>\n</g>\n" << kSvgDocumentEnd;

  std::ofstream out(path, std::ios::binary);
  const std::string text = svg.str();
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw EngineError("cannot write mold picture " + path.string());
}

}  // namespace lastcut
