// Fuzz target: the layout reader (engine/toolpath/layout_pieces.hpp), read_layout_file on a
// layout JSON, then sheets_in_layout and placed_pieces for every sheet: what `lastcut toolpath
// LAYOUT.json` and the daemon's batch step do before planning cuts. A layout file may be edited
// by hand or come from another nester: outside input.
//
// What counts as fine: read_layout_file and placed_pieces document EngineError for a file that is
// not a usable layout (not JSON, missing fields, unknown items, non-finite numbers); callers catch
// exactly that. Any other exception (an nlohmann::json type_error or out_of_range slipping
// through) is not caught, so it surfaces as a libFuzzer crash, as do sanitizer reports.
#include <cstddef>
#include <cstdint>
#include <filesystem>

#include "engine/toolpath/layout_pieces.hpp"
#include "engine_file_fuzz.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return lastcut::fuzz::read_engine_file(data, size, "layout.json", [](const std::filesystem::path& path) {
    const lastcut::LayoutFile layout = lastcut::read_layout_file(path);
    for (const lastcut::SheetRef& sheet : lastcut::sheets_in_layout(layout.layout))
      (void)lastcut::placed_pieces(layout.layout, layout.instance, sheet);
  });
}
