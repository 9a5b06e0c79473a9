// `lastcut flatten SCAN -o DIR`: one scan of a last (or an open patch) to molds, meshes and a
// report (the file contract is in engine/scan/scan_outputs.hpp; the guide in docs/flatten.md).
#include <cstdio>
#include <exception>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "daemon/cli/mold_allowance_options.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/scan/scan_outputs.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::cli {

namespace {

struct FlattenArguments {
  std::string scan;
  std::string out_dir;
  std::string method = "arap";
  std::string unit = "auto";
  std::string split = "auto";  // which lengthwise plane: auto (thesis 3.1) or expert (thesis 2.1)
  bool no_segment = false;
  bool keep_bad_molds = false;  // write molds that fail the quality gate (report.json marks them)
  double allowance_mm = 0.0;
  std::optional<double> lasting_mm, seam_mm, top_mm;  // per-edge allowances (docs/mold-allowances.md)
  std::string balance_notches = "off";                // off | SPACING | SEAM,FEATHER (mm)
  int max_triangles = 0;
  std::string side;                 // "", left or right
  double max_hole_mm = SegmentOptions{}.max_hole_fill_diameter_mm;
};

LengthUnit length_unit_from_name(const std::string& name) {
  static const std::map<std::string, LengthUnit> units{{"auto", LengthUnit::Auto},
                                                       {"mm", LengthUnit::Millimetre},
                                                       {"cm", LengthUnit::Centimetre},
                                                       {"m", LengthUnit::Metre},
                                                       {"in", LengthUnit::Inch}};
  return units.at(name);  // CLI11 has already checked the name
}

ScanOptions options_from(const FlattenArguments& arguments) {
  ScanOptions options;
  options.segment = !arguments.no_segment;
  options.segment_options.split_rule = arguments.split == "expert" ? SplitRule::Expert : SplitRule::Auto;
  options.flatten.method = arguments.method == "lscm"  ? FlattenMethod::Lscm
                           : arguments.method == "abf" ? FlattenMethod::Abf
                                                       : FlattenMethod::Arap;
  options.mold.allowance_mm = arguments.allowance_mm;
  if (arguments.lasting_mm || arguments.seam_mm || arguments.top_mm)
    options.mold.edge_allowances = EdgeAllowances{arguments.lasting_mm.value_or(0.0), arguments.seam_mm.value_or(0.0),
                                                  arguments.top_mm.value_or(0.0)};
  options.mold.balance_notches = *parse_balance_notches(arguments.balance_notches);
  options.read.unit = length_unit_from_name(arguments.unit);
  if (arguments.max_triangles > 0) options.read.max_triangles = arguments.max_triangles;
  if (!arguments.side.empty()) options.side = arguments.side == "left" ? FootSide::Left : FootSide::Right;
  options.segment_options.max_hole_fill_diameter_mm = arguments.max_hole_mm;
  return options;
}

// "" when value is one of choices, otherwise the one-line refusal: `--split must be auto or expert, not "x"`.
// Choice options are checked here rather than by CLI11, which prints two lines and exits 105.
std::string choice_problem(const std::string& option, const std::string& value, const std::vector<std::string>& choices) {
  for (const std::string& choice : choices)
    if (value == choice) return "";
  std::string listed;
  for (size_t i = 0; i < choices.size(); ++i)
    listed += (i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ") + choices[i];
  return option + " must be " + listed + ", not \"" + value + "\"";
}

int run_flatten(const FlattenArguments& arguments) {
  for (const std::string& problem : {choice_problem("--method", arguments.method, {"arap", "lscm", "abf"}),
                                     choice_problem("--unit", arguments.unit, {"auto", "mm", "cm", "m", "in"}),
                                     choice_problem("--split", arguments.split, {"auto", "expert"}),
                                     arguments.side.empty() ? "" : choice_problem("--side", arguments.side, {"left", "right"})}) {
    if (problem.empty()) continue;
    print_error(problem);
    return 2;
  }
  if (!(arguments.allowance_mm >= 0.0) || arguments.allowance_mm > 50.0) {
    print_error("allowance must be between 0 and 50 mm, not " + std::to_string(arguments.allowance_mm));
    return 2;
  }
  if (!(arguments.max_hole_mm >= 0.0) || arguments.max_hole_mm > 100.0) {
    print_error("--max-hole must be between 0 and 100 mm, not " + std::to_string(arguments.max_hole_mm));
    return 2;
  }
  if (const std::string problem = check_edge_allowances(arguments.allowance_mm, arguments.lasting_mm, arguments.seam_mm,
                                                        arguments.top_mm, arguments.balance_notches);
      !problem.empty()) {
    print_error(problem);
    return 2;
  }
  try {
    const ScanResult result = scan_to_molds(arguments.scan, options_from(arguments));
    // A mold beyond the gate is never a result by default: a script that only checks for files
    // must not find any. The reason is the same line lastcutd holds such a job with.
    const bool passed = result.quality.passed();
    if (!passed && !arguments.keep_bad_molds) {
      print_error(result.quality.reason() + " (no molds written; --keep-bad-molds writes them, marked in report.json)");
      return 3;
    }
    write_scan_outputs(result, arguments.out_dir);
    for (const HoleRepair& repair : result.repairs)
      std::printf("repaired: scan hole %.1f mm across closed (%s patch, %d vertices)\n", repair.across_mm,
                  repair.fan ? "fan" : "faired", repair.patch_vertices);
    for (const std::string& warning : result.warnings) std::printf("warning: %s\n", warning.c_str());
    for (const auto& segment : result.segments) {
      const DistortionMeasures& m = segment.measures;
      std::printf("%-8s %6d triangles  D_angle %.4f  D_area %.4f  area %+.2f %%  boundary %+.2f %%  flipped %d  %.2f s\n",
                  segment.name.c_str(), segment.mesh3d.triangle_count(), m.D_angle, m.D_area, m.area_error_pct,
                  m.boundary_error_pct, m.flipped_triangles, segment.flatten.seconds_total);
    }
    std::printf("molds, meshes and report.json in %s (%.2f s)\n", arguments.out_dir.c_str(), result.seconds_total);
    if (passed) return 0;
    print_error(result.quality.reason() + " (molds written anyway: not for cutting; report.json quality.passed is false)");
    return 3;
  } catch (const EngineError& error) {
    print_error(error.what());
  } catch (const std::bad_alloc&) {
    print_error("out of memory; try --max-triangles to simplify the scan first");
  } catch (const std::exception& error) {
    print_error(error.what());
  }
  return 1;
}

}  // namespace

void add_flatten_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<FlattenArguments>();
  auto* command = app.add_subcommand("flatten", "flatten a scanned last into medial and lateral molds (DXF, SVG, OBJ, report.json)");
  command->add_option("scan", arguments->scan, "scan of the last: STL, OBJ, PLY or OFF")->required();
  command->add_option("-o,--out", arguments->out_dir, "output folder (created if missing)")->required();
  command->add_option("--method", arguments->method, "flattening method: arap (least stretch), lscm (conformal) or abf (ABF++, angle based)")
      ->capture_default_str();
  // Choices are checked in run_flatten, so a wrong value gets the same one-line refusal as other bad input.
  command->add_option("--split", arguments->split,
                      "lengthwise cut: auto (plane through the contours' toe, heel and top centres) or expert "
                      "(through the heel middle, the second toe and the top centre)")
      ->capture_default_str();
  command->add_flag("--no-segment", arguments->no_segment, "the scan is one open patch: flatten it as it is");
  command->add_flag("--keep-bad-molds", arguments->keep_bad_molds,
                    "write the molds even when they fail the quality gate (exit status 3 all the same)");
  command->add_option("--allowance", arguments->allowance_mm, "outward margin added around each mold, mm")
      ->capture_default_str();
  command->add_option("--lasting", arguments->lasting_mm, "lasting margin along the feather line, mm (per-edge allowances)");
  command->add_option("--seam", arguments->seam_mm, "seam allowance along the centre cut, mm (per-edge allowances)");
  command->add_option("--top", arguments->top_mm, "allowance along the top line, mm (per-edge allowances, default 0)");
  command->add_option("--balance-notches", arguments->balance_notches,
                      "balance notch spacing along the centre cut and the feather line: off, MM or SEAM_MM,FEATHER_MM")
      ->capture_default_str();
  command->add_option("--unit", arguments->unit, "length unit of the scan: auto, mm, cm, m or in")
      ->capture_default_str();
  command->add_option("--max-triangles", arguments->max_triangles, "refuse (or simplify) scans with more triangles");
  command->add_option("--side", arguments->side, "the foot the last is for (left or right): names the halves of a symmetric last");
  command->add_option("--max-hole", arguments->max_hole_mm, "close scan holes up to this size across, mm (larger: refused)")
      ->capture_default_str();
  command->callback([arguments, &exit_code] { exit_code = run_flatten(*arguments); });
}

}  // namespace lastcut::cli
