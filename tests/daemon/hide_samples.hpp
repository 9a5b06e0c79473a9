#pragma once
// Hides and molds for the daemon tests of hides (single station: hide_daemon_test.cpp; ledger:
// tests/ledger/ledger_hides_test.cpp): hide files sized from the pieces' own bounding boxes, so an
// outcome does not depend on how well the nester packs, and the independent check of a written layout.
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <utility>

#include <nlohmann/json.hpp>

namespace lastcut::daemon::testing {

// The hide material the hide tests configure: [materials.leather] on `cutter`, pairs on one hide,
// grade 2 for a piece and 3 for its toe, grain within 10 deg, 3 mm spacing, turns of 90 deg.
std::string leather_hide_material(const std::string& cutter);

// A hide DXF: a w x h mm rectangle, a 20 x 20 mm hole and (with `zones`) a 40 x 40 mm grade-1 zone,
// a 40 x 40 mm grade-2 zone (good enough for a piece, not for its toe) and a backbone along x, in its
// right 70 mm, beside the room the pieces need.
void write_hide_dxf(const std::filesystem::path& file, double w, double h, bool zones);
// A hide JSON (the format of ../shared/data/nesting/leather): a w x h mm rectangle with a 12 x 12 mm
// hole near its right edge.
void write_hide_json(const std::filesystem::path& file, double w, double h);

// The largest length and width (mm) of the bounding boxes of the pieces in a job's items.json.
std::pair<double, double> piece_box_mm(const std::filesystem::path& items_json);
// The area (mm^2) of the pieces in a job's items.json, each times its demand.
double pieces_area_mm2(const std::filesystem::path& items_json);

// label -> copies: of the pieces in a job's items.json, and of those placed in a batch's layout.json
// (a piece's label names its order, foot and name, so each piece of a shop's orders is told apart).
std::map<std::string, int> pieces_by_label(const std::filesystem::path& items_json);
std::map<std::string, int> placed_by_label(const std::filesystem::path& layout_json);

// The spool's hide batch holding hide file `file` (its batch.json), or null while there is none; and its
// stage ("" while none).
nlohmann::json spool_hide_batch(const std::filesystem::path& spool, const std::string& file);
std::string spool_hide_stage(const std::filesystem::path& spool, const std::string& file);

// Two orders cut from hides (hide name -> its batch's layout.json, each checked by check_hide_layout):
// every piece of `split` and `whole` (label -> copies) cut exactly once over the layouts, `whole` on
// one hide, `split` on two or more, `first_hide` among them. Returns the hides `split` lies on.
std::set<std::string> check_orders_over_hides(const std::map<std::string, std::filesystem::path>& layouts,
                                              const std::map<std::string, int>& split,
                                              const std::map<std::string, int>& whole, const std::string& first_hide);

// Checks every placement of a hide batch's layout.json with the independent checker, and that the
// material's rules reached it (min_quality 2, toe regions of grade 3, grain within 10 deg where the
// hide has a backbone, the hide's hole and `zones` zones). Returns the number of placements.
std::size_t check_hide_layout(const std::filesystem::path& layout_json, std::size_t zones);

}  // namespace lastcut::daemon::testing
