// `lastcut compare MOLD REFERENCE`: a computed mold checked against the pattern a shop trusts
// (engine/compare; the guide in docs/compare.md). Exit 0 when every corner margin is within
// --tolerance, 3 when one is not, 1 when a file cannot be read or written, 2 for bad arguments.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "daemon/cli/commands.hpp"
#include "engine/compare/compare_report.hpp"
#include "engine/compare/reference_outline.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"

namespace lastcut::cli {

namespace {

namespace fs = std::filesystem;

constexpr int kExitBeyondTolerance = 3;

struct CompareArguments {
  std::string mold;
  std::string reference;
  std::string out_dir = ".";
  std::string mold_name;
  bool no_mirror = false;
  double tolerance_mm = 2.0;
};

// A printed 3-decimal value without "-0.000".
double shown(double value) { return std::abs(value) < 5e-4 ? 0.0 : value; }

void print_error(std::string reason) {
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  std::fprintf(stderr, "lastcut: error: %s\n", reason.c_str());
}

// MOLD is a mold DXF, or the output folder of `lastcut flatten` holding NAME.dxf per segment.
fs::path mold_file(const CompareArguments& arguments) {
  const fs::path given(arguments.mold);
  if (!fs::is_directory(given)) {
    if (!arguments.mold_name.empty())
      throw EngineError("--mold picks a mold inside a `lastcut flatten` folder; " + given.string() + " is not a folder");
    return given;
  }
  if (!arguments.mold_name.empty()) {
    const fs::path file = given / (arguments.mold_name + ".dxf");
    if (!fs::is_regular_file(file)) throw EngineError(given.string() + " holds no mold " + arguments.mold_name + ".dxf");
    return file;
  }
  std::vector<std::string> names;
  for (const std::string name : {"medial", "lateral", "patch"})
    if (fs::is_regular_file(given / (name + ".dxf"))) names.push_back(name);
  if (names.size() == 1) return given / (names.front() + ".dxf");
  if (names.empty()) throw EngineError(given.string() + " holds no mold (medial.dxf, lateral.dxf or patch.dxf)");
  std::string list;
  for (const auto& name : names) list += (list.empty() ? "" : ", ") + name;
  throw EngineError(given.string() + " holds " + std::to_string(names.size()) + " molds (" + list +
                    "); pick one with --mold");
}

int run_compare(const CompareArguments& arguments) {
  if (!(arguments.tolerance_mm >= 0.0) || arguments.tolerance_mm > 100.0) {
    print_error("tolerance must be between 0 and 100 mm");
    return 2;
  }
  try {
    const fs::path mold_path = mold_file(arguments);
    Mold mold = read_mold_dxf(mold_path);
    if (mold.name.empty()) mold.name = mold_path.stem().string();
    check_pattern_outline(mold_path.string(), mold.outline);
    const Mold reference = read_reference_outline(arguments.reference);
    CompareOptions options;
    options.overlap.allow_mirror = !arguments.no_mirror;
    const Comparison comparison = compare_mold(mold, reference, options);
    write_comparison(comparison, {mold_path.string(), arguments.reference}, arguments.tolerance_mm, arguments.out_dir,
                     "compare");

    const OverlapAlignment& a = comparison.alignment;
    std::printf("mold %s against %s\n", mold_path.string().c_str(), arguments.reference.c_str());
    std::printf("overlap    %7.2f %%   (A %.1f mm2 reference, B %.1f mm2 mold, C %.1f mm2 common)\n",
                100.0 * a.overlap_fraction(), a.reference_area_mm2, a.mold_area_mm2, a.intersection_area_mm2);
    std::printf("motion     %s, rotated %.3f deg, moved (%.3f, %.3f) mm\n", a.motion.mirrored ? "mirrored" : "not mirrored",
                shown(a.motion.rotation_rad * 180.0 / 3.14159265358979323846), shown(a.motion.translation_mm.x()),
                shown(a.motion.translation_mm.y()));
    if (comparison.corners.empty()) std::printf("corners    none: the mold has no notch marks\n");
    for (const auto& corner : comparison.corners)
      std::printf("corner     %-10s %6.2f mm  %s\n", corner.name.c_str(), corner.margin_mm,
                  corner.margin_mm > arguments.tolerance_mm ? "BEYOND TOLERANCE" : "ok");
    std::printf("hausdorff  %7.2f mm   mean distance %.2f mm\n", comparison.deviation.hausdorff_mm,
                comparison.deviation.mean_mm);
    std::printf("compare.json and compare.svg in %s\n", arguments.out_dir.c_str());
    const auto beyond = corners_beyond(comparison, arguments.tolerance_mm);
    if (beyond.empty()) return 0;
    std::printf("corner %s is %.2f mm off the reference (tolerance %.2f mm)\n", beyond.front().name.c_str(),
                beyond.front().margin_mm, arguments.tolerance_mm);
    return kExitBeyondTolerance;
  } catch (const std::exception& error) {
    print_error(error.what());
  }
  return 1;
}

}  // namespace

void add_compare_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<CompareArguments>();
  auto* command = app.add_subcommand(
      "compare",
      "check a mold against a reference pattern: overlap, corner margins, Hausdorff distance "
      "(exit 0: every corner margin within --tolerance; 3: a margin beyond it; 1: unreadable file)");
  command->add_option("mold", arguments->mold, "mold DXF, or the output folder of `lastcut flatten`")->required();
  command->add_option("reference", arguments->reference, "reference pattern outline: DXF or SVG, mm")->required();
  command->add_option("-o,--out", arguments->out_dir, "folder for compare.json and compare.svg")->capture_default_str();
  command->add_option("--mold", arguments->mold_name, "which mold of a flatten folder: medial, lateral or patch")
      ->check(CLI::IsMember({"medial", "lateral", "patch"}));
  command->add_flag("--no-mirror", arguments->no_mirror, "do not try the reference mirrored (left pattern, right mold)");
  command->add_option("--tolerance", arguments->tolerance_mm, "largest permissible corner margin, mm")
      ->capture_default_str();
  command->callback([arguments, &exit_code] { exit_code = run_compare(*arguments); });
}

}  // namespace lastcut::cli
