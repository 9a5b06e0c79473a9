// Fuzz target: nesting on a hide read from a JSON hide file, what lastcutd does when a hide lands in
// the hides folder for a cutter (daemon/station/hide_step.cpp): read_hide_file, hide_batch with the
// waiting pieces (two shoe-mold pairs of one order and a single, every leather rule on: grades, the
// toe's grade, grain, pairs on one hide), nest_batch (greedy, two rounds), the offcut. The hide_json
// target stops where the reader accepts a hide; this one takes what mutations of a valid hide make of
// its outline, holes, zones and backbone into the hide container, the nester and the independent check.
//
// What counts as fine: EngineError (one line) from any of them; the daemon fails the hide with it.
// Anything else is a crash, as are sanitizer reports, hangs and out-of-memory.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "engine/nest/hide_batch.hpp"
#include "engine/nest/hide_file.hpp"
#include "engine/nest/hide_offcut.hpp"
#include "engine/nest/mold_items.hpp"
#include "engine_file_fuzz.hpp"
#include "tests/compare/synthetic_mold.hpp"

namespace {

// Every 20th point of the tests' synthetic mold (~270 x 110 mm, heel and toe notches): a few dozen
// points, so that one input nests in milliseconds.
std::vector<lastcut::PieceGroup> waiting_pieces() {
  lastcut::Mold mold = lastcut::testing::synthetic_mold();
  std::vector<lastcut::Point2> kept;
  for (size_t i = 0; i < mold.outline.points.size(); i += 20) kept.push_back(mold.outline.points[i]);
  mold.outline.points = kept;
  lastcut::MoldNestSpec pair;
  pair.mirrored_twins = true;
  lastcut::MoldNestSpec single;
  return {{"J1", "order-1", 2, lastcut::items_from_molds({mold}, pair)},
          {"J2", "order-1", 2, lastcut::items_from_molds({mold}, pair)},
          {"J3", "", 1, lastcut::items_from_molds({mold}, single)}};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const std::vector<lastcut::PieceGroup> groups = waiting_pieces();
  return lastcut::fuzz::read_engine_file(data, size, "hide.json", [](const std::filesystem::path& path) {
    const lastcut::HideFile hide = lastcut::read_hide_file(path);
    lastcut::BatchSpec spec;
    spec.gap_mm = 2;
    spec.margin_mm = 2;
    spec.min_quality = 1;
    spec.toe_min_quality = 2;
    spec.grain_tolerance_deg = 10;
    const lastcut::BatchInstance batch = lastcut::hide_batch(groups, {hide.bin}, spec, "fuzz");
    lastcut::NestOptions options;
    options.hide_method = lastcut::HideMethod::Greedy;
    options.iteration_limit = 2;
    const lastcut::Layout layout = lastcut::nest_batch(batch, options);
    (void)lastcut::hide_offcut(layout, batch.instance, 0);
  });
}
