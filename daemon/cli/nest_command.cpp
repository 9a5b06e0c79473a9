// `lastcut nest INPUT... --time-limit S [--seed N] [--threads N] [--gap MM] [--margin MM]
//  -o LAYOUT.json [--svg PICTURE.svg]`: nests pieces on a strip or on hides and writes a
// self-contained layout (engine/nest/nest_json.hpp) that `lastcut toolpath` reads.
// INPUT is a nest instance (JSON), or mold DXFs / folders written by `lastcut flatten` and DXF-AAMA
// pattern sets (nest_inputs.hpp tells them apart) together with --roll-width MM or --hides HIDE...
// (hide files, docs/hides.md). nest() checks every layout with the independent layout checker
// before it is written.
#include <algorithm>
#include <cstdio>
#include <functional>
#include <memory>
#include <optional>
#include <exception>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "daemon/cli/commands.hpp"
#include "daemon/cli/nest_inputs.hpp"
#include "daemon/cli/thread_team.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/layout_svg.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/nest/nester.hpp"
#include "engine/nest/pattern_items.hpp"

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
  std::optional<double> grain_tolerance_deg;  // pattern pieces with a grain line; nullopt: grain free
  int rotation_step_deg = 0;  // free
  bool mirrored_twins = false;
  std::string output_path, svg_path;
};

std::vector<NestItem> mold_items(const std::vector<Mold>& molds, const NestArguments& a) {
  MoldNestSpec spec;
  spec.copies = a.copies;
  spec.mirrored_twins = a.mirrored_twins;
  return items_from_molds(molds, spec);
}

std::vector<NestItem> pattern_items(const std::vector<PatternPiece>& pieces, int sets, const NestArguments& a) {
  PatternNestSpec spec;
  spec.sets = sets;
  spec.mirrored_twins = a.mirrored_twins;
  // A piece with a grain line keeps it within the tolerance (pieces without one stay free).
  const PieceRules rules{a.grain_tolerance_deg, a.min_quality};
  spec.rules = [rules](const PatternPiece&) { return rules; };
  return items_from_pattern(pieces, spec);
}

// The pieces as hide_batch's jobs: the molds are one job, as before (a pair stays a pair), and each
// set of the pattern is one (--copies N sets: N jobs), so a set's pieces come from one hide whose
// colour and grain match, while different sets may go on different hides.
std::vector<PieceGroup> piece_groups(const NestInputs& read, const NestArguments& a, const std::string& name) {
  std::vector<PieceGroup> groups;
  if (!read.molds.empty()) groups.push_back({name, "", 0, mold_items(read.molds, a)});
  for (int set = 1; !read.pattern_pieces.empty() && set <= a.copies; ++set)
    groups.push_back({name + " set " + std::to_string(set), "", 0, pattern_items(read.pattern_pieces, 1, a)});
  return groups;
}

// The items on a roll, ids 0.. (molds first): --copies pairs of molds, or sets of the pattern (each
// piece's demand is its Quantity x sets).
std::vector<NestItem> roll_items(const NestInputs& read, const NestArguments& a) {
  std::vector<NestItem> items;
  if (!read.molds.empty()) items = mold_items(read.molds, a);
  if (read.pattern_pieces.empty()) return items;
  for (NestItem& item : pattern_items(read.pattern_pieces, a.copies, a)) {
    item.id = static_cast<int>(items.size());
    items.push_back(std::move(item));
  }
  return items;
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
    if (a.roll_width_mm > 0) throw EngineError("--roll-width is for mold DXFs and pattern sets; a JSON instance carries its own strip or hides");
    return {read_nest_instance(a.inputs[0]), {}};
  }
  if (a.roll_width_mm <= 0 && a.hides_paths.empty())
    throw EngineError("nesting molds or pattern sets needs --roll-width MM (the usable width of the roll) or --hides HIDE...");
  if (a.roll_width_mm > 0 && !a.hides_paths.empty()) throw EngineError("choose a roll (--roll-width) or hides (--hides), not both");
  // Named after the one input, or after the layout file when there are several (a batch, not one last).
  const std::filesystem::path name_from = a.inputs.size() == 1 ? a.inputs[0] : a.output_path;
  const std::string name = name_from.stem().string();
  const NestInputs read = read_nest_inputs(a.inputs);
  if (a.hides_paths.empty()) {
    NestInstance instance;
    instance.name = name;
    instance.strip_height = a.roll_width_mm;
    instance.items = roll_items(read, a);
    return {instance, {}};
  }
  // Hides: the same engine entry as lastcutd (hide_batch.hpp), whole jobs on one hide (piece_groups).
  std::vector<Bin> hides;
  double gap_mm = 0, margin_mm = 0;
  for (const std::string& path : a.hides_paths) {
    const HideOrInstance hide = read_hides(path);
    hides.insert(hides.end(), hide.bins.begin(), hide.bins.end());
    gap_mm = std::max(gap_mm, hide.gap_mm);
    margin_mm = std::max(margin_mm, hide.margin_mm);
  }
  BatchSpec batch_spec;
  batch_spec.min_quality = a.min_quality;
  batch_spec.rotation_step_deg = a.rotation_step_deg;
  batch_spec.gap_mm = gap_mm;
  batch_spec.margin_mm = margin_mm;
  return hide_batch(piece_groups(read, a, name), hides, batch_spec, name);
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
    // Pieces on hides go through the batch entry (whole jobs, one hide per pair or set); every
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
  command->add_option("input", arguments->inputs,
                      "nest instance (JSON), or mold DXF files / folders from `lastcut flatten` and DXF-AAMA pattern sets")
      ->required();
  command->add_option("--time-limit", arguments->time_limit_s, "seconds to improve the layout")->check(CLI::NonNegativeNumber)->required();
  command->add_option("--seed", arguments->seed, "random seed (same seed and threads: same layout for the same rounds)");
  command->add_option("--threads", arguments->threads, "worker threads (default: all cores)")->check(CLI::NonNegativeNumber);
  command->add_option("--gap", arguments->gap_mm, "minimum distance between pieces, mm (kerf + clearance)")->check(CLI::NonNegativeNumber);
  command->add_option("--margin", arguments->margin_mm, "minimum distance from the material edge and defects, mm")->check(CLI::NonNegativeNumber);
  command->add_option("--roll-width", arguments->roll_width_mm, "usable roll width for mold DXFs and pattern sets, mm")->check(CLI::PositiveNumber);
  command->add_option("--hides", arguments->hides_paths,
                      "nest mold DXFs and pattern sets on these hide files (DXF or JSON, docs/hides.md) or the hides of an instance file");
  command->add_option("--rotation-step", arguments->rotation_step_deg, "with --hides: rotations in steps of this, deg (360: none; default: free)")
      ->check(CLI::Range(1, 360));
  command->add_option("--min-quality", arguments->min_quality, "lowest leather quality the pieces may lie on (with --hides)");
  command->add_option("--grain-tolerance", arguments->grain_tolerance_deg,
                      "pattern pieces with a grain line keep it within this of the backbone (hides) or the roll's length, deg")
      ->check(CLI::Range(0.0, 90.0));
  command->add_option("--copies", arguments->copies, "copies of every mold, or sets of a pattern (not for JSON)")->check(CLI::PositiveNumber);
  command->add_flag("--mirrored-twins", arguments->mirrored_twins, "add every mold or pattern piece mirrored, for the other foot (not for JSON)");
  command->add_option("-o,--output", arguments->output_path, "layout JSON to write")->required();
  command->add_option("--svg", arguments->svg_path, "SVG picture of the layout to write");
  command->callback([arguments, &exit_code] { exit_code = run_nest(*arguments); });
}

}  // namespace lastcut::cli
