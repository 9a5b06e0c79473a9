#include "test_layouts.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "engine/toolpath/cut_program.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

// A quarter-vamp-like mold: straight lasting edge along y = 0, a sharp heel corner, a curved top
// line sampled every few degrees, a rounded toe.
Polygon2 mold_shape(double length_mm, double height_mm) {
  Polygon2 shape;
  shape.points.push_back({0.0, 0.0});
  shape.points.push_back({length_mm, 0.0});
  for (int i = 1; i < 40; ++i) {  // toe and top line: a quarter ellipse then a gentle wave
    const double t = i / 40.0 * std::numbers::pi / 2;
    shape.points.push_back({length_mm * (0.6 + 0.4 * std::cos(t)), height_mm * std::sin(t)});
  }
  for (int i = 0; i <= 20; ++i) {
    const double x = length_mm * 0.6 * (1.0 - i / 20.0);
    shape.points.push_back({x, height_mm * (0.9 + 0.1 * std::cos(x / length_mm * 6.0))});
  }
  shape.points.push_back({-8.0, height_mm * 0.5});  // heel point: a sharp corner
  return shape;
}

Polygon2 rectangle(double width_mm, double height_mm) {
  return Polygon2{{{0, 0}, {width_mm, 0}, {width_mm, height_mm}, {0, height_mm}}};
}

std::vector<ItemMark> notches_on_edge_y0(double x1_mm, double x2_mm) {
  return {ItemMark{"notch-a", {x1_mm, 0.0}, {x1_mm, 2.0}}, ItemMark{"notch-b", {x2_mm, 0.0}, {x2_mm, 2.0}}};
}

}  // namespace

NestInstance shoe_instance() {
  NestInstance instance;
  instance.name = "toolpath-test";
  instance.strip_height = 600.0;
  NestItem medial{1, mold_shape(180.0, 90.0)};
  medial.label = "42 L medial";
  medial.marks = notches_on_edge_y0(40.0, 120.0);
  NestItem lateral{2, mold_shape(170.0, 80.0)};
  lateral.label = "42 R lateral";
  lateral.marks = notches_on_edge_y0(50.0, 110.0);
  lateral.marks.push_back(ItemMark{"ball-line", {90.0, 20.0}, {90.0, 40.0}});
  NestItem strap{3, rectangle(120.0, 30.0)};
  strap.label = "strap 41.5 left";
  strap.marks = notches_on_edge_y0(30.0, 90.0);
  NestItem tongue{4, Polygon2{{{0, 0}, {60, 0}, {70, 50}, {30, 80}, {-10, 50}}}};
  tongue.label = "";
  instance.items = {medial, lateral, strap, tongue};
  return instance;
}

Layout shoe_layout() {
  Layout layout;
  layout.instance = "toolpath-test";
  layout.strip_length = 760.0;
  auto place = [](int item, double rotation_deg, bool mirrored, double x, double y) {
    Placement placement;
    placement.item = item;
    placement.rotation_deg = rotation_deg;
    placement.mirrored = mirrored;
    placement.x = x;
    placement.y = y;
    return placement;
  };
  layout.placements = {
      place(3, 0.0, false, 520.0, 420.0),   place(1, 0.0, false, 20.0, 20.0),   place(4, 37.0, false, 660.0, 120.0),
      place(2, 180.0, false, 400.0, 300.0), place(1, 90.0, true, 330.0, 200.0),  place(2, 0.0, true, 210.0, 330.0),
      place(3, 90.0, false, 740.0, 300.0),  place(4, 0.0, false, 30.0, 420.0),
  };
  return layout;
}

Point2 expected_point(const Point2& own, const Placement& placement) {
  const double angle = placement.rotation_deg * std::numbers::pi / 180.0;
  const Point2 mirrored(placement.mirrored ? -own.x() : own.x(), own.y());
  return Point2(std::cos(angle) * mirrored.x() - std::sin(angle) * mirrored.y() + placement.x,
                std::sin(angle) * mirrored.x() + std::cos(angle) * mirrored.y() + placement.y);
}

Polygon2 expected_outline(const NestItem& item, const Placement& placement) {
  Polygon2 outline;
  for (const Point2& point : item.shape.points) outline.points.push_back(expected_point(point, placement));
  return outline;
}

MachineProfile profile_named(const std::string& name) {
  return load_machine_profile(name, {std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "machines"});
}

ShoeJob write_shoe_job(const std::string& profile_name, const std::string& test_name, const std::string& file_name,
                       CutFileWriter writer) {
  ShoeJob job;
  job.profile = profile_named(profile_name);
  job.program = plan_cut_program(placed_pieces(job.layout, job.instance, SheetRef{}), job.profile);
  job.file = scratch_dir(test_name) / file_name;
  write_text(job.file, writer(job.program, job.profile));
  return job;
}

std::filesystem::path scratch_dir(const std::string& test_name) {
  static const TempDir process_dir("toolpath");  // one per test process, removed at its exit
  const auto dir = process_dir / test_name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
}

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

double distance_to_polyline(const Point2& point, const std::vector<Point2>& polyline) {
  double best = INFINITY;
  if (polyline.size() == 1) return (polyline[0] - point).norm();
  for (size_t i = 0; i + 1 < polyline.size(); ++i) {
    const Point2 a = polyline[i], ab = polyline[i + 1] - a;
    const double t = ab.squaredNorm() > 0 ? std::clamp((point - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
    best = std::min(best, (a + t * ab - point).norm());
  }
  return best;
}

double distance_to_outline(const Point2& point, const Polygon2& outline) {
  std::vector<Point2> closed = outline.points;
  closed.push_back(outline.points.front());
  return distance_to_polyline(point, closed);
}

bool traces_outline(const std::vector<Point2>& path, const Polygon2& outline, double tolerance_mm) {
  if (path.size() < 3) return false;
  for (const Point2& point : path) {
    if (distance_to_outline(point, outline) > tolerance_mm) return false;
  }
  for (const Point2& vertex : outline.points) {
    if (distance_to_polyline(vertex, path) > tolerance_mm) return false;
  }
  if (polyline_length(path) < perimeter(outline) - tolerance_mm) return false;
  // Closed: the start is passed again at the end (before the overcut runs on).
  std::vector<Point2> tail(path.begin() + static_cast<long>(path.size() / 2), path.end());
  return distance_to_polyline(path.front(), tail) <= tolerance_mm;
}

}  // namespace lastcut::test
