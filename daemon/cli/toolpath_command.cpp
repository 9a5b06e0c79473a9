// `lastcut toolpath LAYOUT.json --profile NAME|PATH [--format hpgl|gcode|dxf|svg] [-o FILE]`:
// turns a layout written by `lastcut nest` into a cut file for one machine and prints what the
// machine will do (cut length, travel, tool lifts). Profiles by name come from the source tree's
// config/machines and /etc/lastcut/machines.
#include <cstdio>
#include <exception>
#include <string>

#include "daemon/cli/commands.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/toolpath/cut_file.hpp"
#include "engine/toolpath/cut_job.hpp"
#include "engine/toolpath/cut_time.hpp"

namespace lastcut::cli {
namespace {

struct ToolpathArguments {
  std::string layout_path;
  std::string profile;
  std::string format;
  std::string output_path;
  std::string sheet;  // "BIN" or "BIN:COPY"
  bool layout_order = false;
};

std::string describe(const SheetRef& sheet) {
  if (sheet.bin < 0) return "strip";
  return std::to_string(sheet.bin) + (sheet.copy > 0 ? ":" + std::to_string(sheet.copy) : "");
}

SheetRef choose_sheet(const Layout& layout, const std::string& wanted) {
  const std::vector<SheetRef> sheets = sheets_in_layout(layout);
  if (sheets.empty()) throw EngineError("the layout places no pieces: nothing to cut");
  std::string available;
  for (const SheetRef& sheet : sheets) available += (available.empty() ? "" : ", ") + describe(sheet);
  if (wanted.empty()) {
    if (sheets.size() == 1) return sheets.front();
    throw EngineError("the layout uses " + std::to_string(sheets.size()) + " hides/sheets (" + available +
                      "); choose one with --sheet");
  }
  for (const SheetRef& sheet : sheets) {
    if (describe(sheet) == wanted || (sheet.copy == 0 && wanted == describe(sheet) + ":0")) return sheet;
  }
  throw EngineError("the layout has no sheet '" + wanted + "' (it has " + available + ")");
}

int run_toolpath(const ToolpathArguments& arguments) {
  const MachineProfile profile = load_machine_profile(arguments.profile, standard_machine_profile_dirs());
  const LayoutFile file = read_layout_file(arguments.layout_path);
  CutFileRequest request;
  request.sheet = choose_sheet(file.layout, arguments.sheet);
  if (!arguments.format.empty()) request.format = parse_cut_file_format(arguments.format);
  request.order = arguments.layout_order ? PieceOrder::AsGiven : PieceOrder::ShortTravel;
  const CutFile cut = make_cut_file(file.layout, file.instance, profile, request);
  std::string output = arguments.output_path;
  if (output.empty()) {
    std::filesystem::path path(arguments.layout_path);
    output = path.replace_extension(cut_file_extension(cut.format)).string();
  }
  save_cut_file(output, cut.text);
  const CutProgram& program = cut.program;
  const CutStats& stats = cut.stats;
  std::printf("%s: %zu pieces for machine '%s' (%s)\n", output.c_str(), program.pieces.size(), profile.name.c_str(),
              to_string(cut.format).c_str());
  std::printf("cut length    %10.1f mm\n", stats.cut_length_mm);
  std::printf("mark length   %10.1f mm\n", stats.mark_length_mm);
  std::printf("travel length %10.1f mm\n", stats.travel_length_mm);
  std::printf("tool lifts    %10d\n", stats.tool_lifts);
  std::printf("estimated     %10.1f min (feeds only, without acceleration)\n",
              estimated_duration_s(program, profile) / 60.0);
  for (const Unplaced& missing : file.layout.unplaced) {
    std::printf("not in layout: %d x item %d (%s)\n", missing.count, missing.item, missing.reason.c_str());
  }
  return 0;
}

}  // namespace

void add_toolpath_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<ToolpathArguments>();
  auto* command = app.add_subcommand("toolpath", "layout -> cut file (HPGL, G-code, DXF or SVG) for one machine");
  command->add_option("layout", arguments->layout_path, "layout JSON written by `lastcut nest`")->required();
  command->add_option("--profile,-p", arguments->profile, "machine profile: a name in config/machines or /etc/lastcut/machines, or a .toml path")
      ->required();
  command->add_option("--format,-f", arguments->format, "hpgl, gcode, dxf or svg (default: the machine's own)")
      ->check(CLI::IsMember({"hpgl", "gcode", "dxf", "svg"}));
  command->add_option("--output,-o", arguments->output_path, "cut file to write (default: layout name + .plt/.nc/.dxf/.svg)");
  command->add_option("--sheet", arguments->sheet, "which hide of a multi-hide layout: BIN or BIN:COPY");
  command->add_flag("--layout-order", arguments->layout_order, "cut pieces in layout order instead of the shortest travel");
  command->callback([arguments, &exit_code] {
    try {
      exit_code = run_toolpath(*arguments);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "lastcut toolpath: error: %s\n", error.what());
      exit_code = 1;
    }
  });
}

}  // namespace lastcut::cli
