// `lastcut style ...`: styles (issue 34). `style pieces` is pieces_command.cpp, `style new`
// style_new_command.cpp; here:
//
// `lastcut style transfer REFERENCE_SCAN LINES.obj NEW_SCAN -o OUT.obj`: lines drawn on a reference last
// (OBJ polylines, engine/style/style_lines_obj.hpp) taken onto another scanned last (style_transfer.hpp),
// written as OBJ polylines in the new scan's frame under the same names, one summary line per line.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_lines_obj.hpp"
#include "engine/style/style_transfer.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct TransferArguments {
  std::string reference_scan, lines, scan, out;
  std::string side, reference_side;  // "", left or right (as `lastcut flatten --side`)
};

// "" when value is empty, left or right, otherwise the one-line refusal (the words of `lastcut flatten`).
std::string side_problem(const std::string& option, const std::string& value) {
  return value.empty() || value == "left" || value == "right" ? "" : option + " must be left or right, not \"" + value + "\"";
}


int run_style_transfer(const TransferArguments& arguments) {
  for (const std::string& problem :
       {side_problem("--side", arguments.side), side_problem("--reference-side", arguments.reference_side)}) {
    if (problem.empty()) continue;
    print_error(problem);
    return 2;
  }
  try {
    const std::vector<StyleLine> lines = read_style_lines_obj(arguments.lines);  // a bad file is refused before the scans are read
    const ScanResult reference = segmented(arguments.reference_scan, side_named(arguments.reference_side));
    const ScanResult target = segmented(arguments.scan, side_named(arguments.side));
    const StyleTransfer transfer(reference, target);
    std::set<std::string> names;
    for (const StyleLine& line : lines) names.insert(line.name);
    std::vector<StyleLine> out;
    std::vector<std::string> summary;
    for (const StyleLine& line : lines) {
      const TransferredCurve curve = transfer.transfer_curve(line.points_mm);
      const std::vector<std::vector<Eigen::Vector3d>> runs = runs_on_upper(curve);
      if (runs.empty()) throw EngineError("the line \"" + line.name + "\" does not lie on the reference last's upper");
      std::size_t written = 0;
      for (std::size_t r = 0; r < runs.size(); ++r) {
        // A line that leaves the upper and comes back is written in parts: NAME, NAME (2), ...
        const std::string name = r == 0 ? line.name : line.name + " (" + std::to_string(r + 1) + ")";
        if (r > 0 && !names.insert(name).second)
          throw EngineError("the line \"" + line.name + "\" leaves the upper and comes back: its part \"" + name +
                            "\" would take the name of another line");
        out.push_back({name, runs[r]});
        written += runs[r].size();
      }
      const auto on_edge = std::count_if(curve.points.begin(), curve.points.end(), on_upper_edge);
      char text[160];
      std::snprintf(text, sizeof text, "%5zu points written  %5d dropped (off the reference's upper)  %2td on an edge of the upper",
                    written, curve.dropped_points, on_edge);
      summary.push_back(line.name + std::string(line.name.size() < 16 ? 16 - line.name.size() : 0, ' ') + " " + text +
                        (runs.size() > 1 ? "  in " + std::to_string(runs.size()) + " parts" : ""));
    }
    write_style_lines_obj(arguments.out, out);  // the summary only once the file is there
    for (const std::string& line : summary) std::printf("%s\n", line.c_str());
    std::printf("%zu lines onto %s in %s\n", lines.size(), arguments.scan.c_str(), arguments.out.c_str());
    return 0;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    print_error(error.what());
  }
  return 1;
}

}  // namespace

void add_style_command(CLI::App& app, int& exit_code) {
  auto* style = app.add_subcommand("style", "styles: upper pieces drawn once on a reference last, cut from every scanned last");
  style->require_subcommand(1);
  add_style_pieces_command(*style, exit_code);
  auto transfer_arguments = std::make_shared<TransferArguments>();
  auto* transfer = style->add_subcommand("transfer", "lines drawn on a reference last taken onto another scanned last (OBJ polylines)");
  transfer->add_option("reference", transfer_arguments->reference_scan, "scan of the reference last the lines are drawn on")->required();
  transfer->add_option("lines", transfer_arguments->lines, "the lines: OBJ polylines (v, l) in the reference scan's frame, mm")->required();
  transfer->add_option("scan", transfer_arguments->scan, "scan of the last to take the lines to")->required();
  transfer->add_option("-o,--out", transfer_arguments->out, "output OBJ: the lines on the new last, in its scan's frame")->required();
  transfer->add_option("--side", transfer_arguments->side, "the foot the new last is for (left or right): names the halves of a symmetric last");
  transfer->add_option("--reference-side", transfer_arguments->reference_side, "the foot the reference last is for (left or right)");
  transfer->callback([transfer_arguments, &exit_code] { exit_code = run_style_transfer(*transfer_arguments); });
  add_style_new_command(*style, exit_code);
  add_style_check_command(*style, exit_code);
}

}  // namespace lastcut::cli
