// `lastcut nest INPUT... --time-limit S [--seed N] [--threads N] [--gap MM] [--margin MM]
//  -o LAYOUT.json [--svg PICTURE.svg]`: nests pieces on a strip or on hides and writes a
// self-contained layout (engine/nest/nest_json.hpp) that `lastcut toolpath` reads.
// INPUT is a nest instance (JSON), or mold DXFs / folders written by `lastcut flatten` together
// with --roll-width MM or --hides HIDE... (hide files, docs/hides.md). nest() checks every layout with the independent layout checker before it is written.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <exception>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "daemon/cli/commands.hpp"
#include "daemon/cli/thread_team.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/layout_svg.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"

namespace lastcut::cli {
namespace {

struct NestArguments {
  std::vector<std::string> inputs;
  double time_limit_s = 10;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
  double gap_mm = -1, margin_mm = -1;
  double roll_width_mm = 0;
  std::vector<std::string> hides_paths;  // molds on these hide files (DXF, JSON) instead of a roll
  int copies = 1;
  int min_quality = 0;
  int rotation_step_deg = 0;  // free
  bool mirrored_twins = false;
  std::string output_path, svg_path;
};

// A mold DXF's label says which half it is ("medial"); the folder `lastcut flatten` wrote it to says
// whose last it is ("m-42-left"). The cutting room needs both on the piece.
Mold read_labelled_mold(const std::filesystem::path& file) {
  Mold mold = read_mold_dxf(file);
  const std::string folder = std::filesystem::absolute(file).parent_path().filename().string();
  if (!folder.empty() && mold.name.find(folder) == std::string::npos)
    mold.name = mold.name.empty() ? folder : folder + " " + mold.name;
  return mold;
}

std::vector<Mold> read_molds(const std::vector<std::string>& inputs) {
  std::vector<Mold> molds;
  for (const std::string& input : inputs) {
    const std::filesystem::path path(input);
    if (std::filesystem::is_directory(path)) {
      std::vector<std::filesystem::path> files;
      for (const auto& entry : std::filesystem::directory_iterator(path))
        if (entry.path().extension() == ".dxf") files.push_back(entry.path());
      std::sort(files.begin(), files.end());
      if (files.empty()) throw EngineError("folder " + input + " holds no mold DXF files");
      for (const auto& file : files) molds.push_back(read_labelled_mold(file));
    } else {
      molds.push_back(read_labelled_mold(path));
    }
  }
  return molds;
}

struct HideOrInstance {
  std::vector<Bin> bins;
  double gap_mm = 0, margin_mm = 0;
};

// A hide file (DXF, or a JSON bin object; hide_file.hpp, checked), or a nest instance JSON with
// "bins" (read as an instance, as before hide files: its gap and margin come along).
HideOrInstance read_hides(const std::string& path) {
  if (std::filesystem::path(path).extension() == ".json") {
    const nlohmann::json json = read_json_file(path);
    if (json.is_object() && json.contains("bins")) {
      const NestInstance instance = read_nest_instance(path);
      return {instance.bins, instance.gap_mm, instance.margin_mm};
    }
  }
  return {{read_hide_file(path).bin}};
}

BatchInstance load_instance(const NestArguments& a) {
  const bool single_json = a.inputs.size() == 1 && std::filesystem::path(a.inputs[0]).extension() == ".json";
  if (single_json) {
    if (a.roll_width_mm > 0) throw EngineError("--roll-width is for mold DXFs; a JSON instance carries its own strip or hides");
    return {read_nest_instance(a.inputs[0]), {}};
  }
  if (a.roll_width_mm <= 0 && a.hides_paths.empty())
    throw EngineError("nesting molds needs --roll-width MM (the usable width of the roll) or --hides HIDE...");
  if (a.roll_width_mm > 0 && !a.hides_paths.empty()) throw EngineError("choose a roll (--roll-width) or hides (--hides), not both");
  MoldNestSpec spec;
  spec.roll_width_mm = a.roll_width_mm > 0 ? a.roll_width_mm : 1;
  spec.copies = a.copies;
  spec.mirrored_twins = a.mirrored_twins;
  // Named after the one input, or after the layout file when there are several (a batch, not one last).
  const std::filesystem::path name_from = a.inputs.size() == 1 ? a.inputs[0] : a.output_path;
  if (a.hides_paths.empty()) return {instance_from_molds(read_molds(a.inputs), spec, name_from.stem().string()), {}};
  // Hides: the same engine entry as lastcutd (hide_batch.hpp); the molds of this command are one
  // job, so they go on one hide together (a pair stays a pair).
  std::vector<Bin> hides;
  double gap_mm = 0, margin_mm = 0;
  for (const std::string& path : a.hides_paths) {
    const HideOrInstance read = read_hides(path);
    hides.insert(hides.end(), read.bins.begin(), read.bins.end());
    gap_mm = std::max(gap_mm, read.gap_mm);
    margin_mm = std::max(margin_mm, read.margin_mm);
  }
  PieceGroup group{name_from.stem().string(), "", 0, items_from_molds(read_molds(a.inputs), spec)};
  for (NestItem& item : group.items) item.min_quality = a.min_quality;
  BatchSpec batch_spec;
  batch_spec.rotation_step_deg = a.rotation_step_deg;
  batch_spec.gap_mm = gap_mm;
  batch_spec.margin_mm = margin_mm;
  return hide_batch({group}, hides, batch_spec, name_from.stem().string());
}

int run_nest(const NestArguments& a) {
  try {
    const BatchInstance batch = load_instance(a);
    const NestInstance& instance = batch.instance;
    NestOptions options;
    options.time_limit_s = a.time_limit_s;
    options.seed = a.seed;
    options.threads = a.threads > 0 ? a.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
    if (a.gap_mm >= 0) options.gap_mm = a.gap_mm;
    if (a.margin_mm >= 0) options.margin_mm = a.margin_mm;
    // The engine has no threads of its own: a team started once runs the workers of every sweep.
    ThreadTeam team(static_cast<size_t>(options.threads - 1));
    options.run_parallel = team.runner();
    // A mold batch on hides goes through the batch entry (whole jobs, one hide per pair); every
    // other instance straight to the nester.
    const Layout layout = batch.group_of_item.empty() ? nest(instance, options) : nest_batch(batch, options);
    NestInstance written = instance;  // the layout records the gap and margin it was made with
    written.gap_mm = options.gap_mm.value_or(instance.gap_mm);
    written.margin_mm = options.margin_mm.value_or(instance.margin_mm);
    write_layout(a.output_path, layout, written);
    if (!a.svg_path.empty()) write_layout_svg(a.svg_path, layout, written);
    int demanded = 0, unplaced = 0;
    for (const NestItem& item : instance.items) demanded += item.demand;
    for (const Unplaced& u : layout.unplaced) unplaced += u.count;
    if (layout.strip_length)
      std::printf("%s: %zu of %d pieces on a strip %.1f mm long, utilisation %.2f %%\n", instance.name.c_str(),
                  layout.placements.size(), demanded, *layout.strip_length, 100 * layout.utilisation);
    else
      std::printf("%s: %zu of %d pieces on %d hide(s), utilisation of the used hides %.2f %%\n", instance.name.c_str(),
                  layout.placements.size(), demanded, used_bin_count(layout), 100 * layout.utilisation);
    for (const Unplaced& u : layout.unplaced) std::printf("  not placed: %s\n", unplaced_text(u, instance).c_str());
    return unplaced > 0 ? 3 : 0;
  } catch (const EngineError& error) {
    std::fprintf(stderr, "lastcut nest: error: %s\n", error.what());
    return 1;
  }
}

}  // namespace

void add_nest_command(CLI::App& app, int& exit_code) {
  auto arguments = std::make_shared<NestArguments>();
  auto* command = app.add_subcommand("nest", "nest pieces on a strip or on hides and write a layout (exit 3: some pieces did not fit)");
  command->add_option("input", arguments->inputs, "nest instance (JSON), or mold DXF files / folders from `lastcut flatten`")->required();
  command->add_option("--time-limit", arguments->time_limit_s, "seconds to improve the layout")->check(CLI::NonNegativeNumber)->required();
  command->add_option("--seed", arguments->seed, "random seed (same seed and threads: same layout for the same rounds)");
  command->add_option("--threads", arguments->threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  command->add_option("--gap", arguments->gap_mm, "minimum distance between pieces, mm (kerf + clearance)")->check(CLI::NonNegativeNumber);
  command->add_option("--margin", arguments->margin_mm, "minimum distance from the material edge and defects, mm")->check(CLI::NonNegativeNumber);
  command->add_option("--roll-width", arguments->roll_width_mm, "usable roll width for mold DXFs, mm")->check(CLI::PositiveNumber);
  command->add_option("--hides", arguments->hides_paths,
                      "nest mold DXFs on these hide files (DXF or JSON, docs/hides.md) or the hides of an instance file");
  command->add_option("--rotation-step", arguments->rotation_step_deg, "with --hides: rotations in steps of this, deg (360: none; default: free)")
      ->check(CLI::Range(1, 360));
  command->add_option("--min-quality", arguments->min_quality, "lowest leather quality the molds may lie on (with --hides)");
  command->add_option("--copies", arguments->copies, "copies of every mold (mold DXFs only)")->check(CLI::PositiveNumber);
  command->add_flag("--mirrored-twins", arguments->mirrored_twins, "add every mold mirrored, for the other foot (mold DXFs only)");
  command->add_option("-o,--output", arguments->output_path, "layout JSON to write")->required();
  command->add_option("--svg", arguments->svg_path, "SVG picture of the layout to write");
  command->callback([arguments, &exit_code] { exit_code = run_nest(*arguments); });
}

}  // namespace lastcut::cli
