#pragma once
// Hand-made layouts for the toolpath tests: mold-like pieces (a curved top line, a straight
// lasting edge, sharp heel corners) with notch marks and labels, placed with rotations and
// mirroring as a nester would. The expected placement is computed here independently of
// engine/nest (mirror x -> -x, rotate CCW about the own origin, translate) so a wrong transform
// in either place fails a test.
#include <filesystem>
#include <string>
#include <vector>

#include "engine/nest/layout.hpp"
#include "engine/nest/nest_problem.hpp"
#include "engine/toolpath/cut_program.hpp"
#include "engine/toolpath/machine_profile.hpp"

namespace lastcut::test {

NestInstance shoe_instance();
// Pieces spread over about 700 x 500 mm; every placement kind occurs (0/90/180/arbitrary degrees, mirrored).
Layout shoe_layout();

Point2 expected_point(const Point2& own, const Placement& placement);
Polygon2 expected_outline(const NestItem& item, const Placement& placement);

MachineProfile profile_named(const std::string& name);

// The shoe layout planned for one machine profile and written as that machine's cut file.
struct ShoeJob {
  NestInstance instance = shoe_instance();
  Layout layout = shoe_layout();
  MachineProfile profile;
  CutProgram program;
  std::filesystem::path file;  // the cut file, in scratch_dir(test_name)
};
using CutFileWriter = std::string (*)(const CutProgram& program, const MachineProfile& profile);
ShoeJob write_shoe_job(const std::string& profile_name, const std::string& test_name, const std::string& file_name,
                       CutFileWriter writer);

// A fresh directory under the system temp dir for one test's files.
std::filesystem::path scratch_dir(const std::string& test_name);
void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);

// Distance (mm) from a point to an open polyline / to a closed polygon's boundary.
double distance_to_polyline(const Point2& point, const std::vector<Point2>& polyline);
double distance_to_outline(const Point2& point, const Polygon2& outline);

// True when `path` is one closed cut of `outline` within tolerance_mm: every path point lies on
// the outline, every outline vertex lies on the path, and the path goes all the way round
// (length >= perimeter - tolerance) starting and ending at the same place (overcut allowed).
bool traces_outline(const std::vector<Point2>& path, const Polygon2& outline, double tolerance_mm);

}  // namespace lastcut::test
