#pragma once
// Issue 35's cutting room for the end-to-end tests of both stores (tests/daemon/pieces_daemon_test.cpp,
// tests/ledger/ledger_pieces_test.cpp): a derby order, a lined derby order (its linings of the lining
// roll: a job of two parts) and a loafer order, each a pair from one scanned last (the shipped styles,
// config/styles), and a DXF-AAMA pattern set of a tongue of leather
// and its linings, whose Categories name the hides' leather and the lining roll (a job cut in two parts); hide files with two poor zones and a backbone along x. The checks
// read the cut files themselves (gcode_pieces.hpp), never the nester's layout: every piece of every
// order cut exactly once, each by its label, a pair's pieces on one hide, every piece off the zones
// below its grade (the vamps: off both), every grained piece's grain within its tolerance of the
// backbone.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "engine/nest/nest_problem.hpp"

namespace lastcut::daemon::testing {

struct PieceOrder {
  std::string file;     // the name dropped into the watch folder (scan or pattern set)
  std::string sidecar;  // its NAME.job.toml
  std::string order;
};

// Writes the four orders' files into `staging` (scans made once per build tree). Returns them in drop order.
std::vector<PieceOrder> write_piece_orders(const std::filesystem::path& staging);

// The [paths] lines and the materials: leather hides (on `hide_cutter`) and the lining roll (its
// material's cutter: cutter-2).
std::string piece_paths_config();
std::string piece_materials_config(const std::string& hide_cutter);

// A w x h mm hide DXF with ZONE_1 and ZONE_2 rectangles (poor leather) and a backbone along x.
void write_zoned_hide(const std::filesystem::path& file, double w_mm, double h_mm);
// The zones write_zoned_hide draws, for the checks.
std::vector<QualityZone> zoned_hide_zones(double w_mm, double h_mm);

// What the cut files of one run cut.
struct CutPieces {
  std::map<std::string, int> times_cut;       // label -> how often a cut file cut it
  std::map<std::string, std::string> hide_of;  // label -> the hide batch that cut it ("" on a roll)
  int zone_checks = 0, grain_checks = 0;
  std::vector<std::string> problems;           // one line each
};

// Reads one G-code cut file of a batch; `zones` empty for a roll. `items`: every job's items by label.
void check_cut_file(const std::string& gcode, const std::string& batch, const std::vector<QualityZone>& zones,
                    const std::map<std::string, NestItem>& items, CutPieces& cut);

// The zones of the hides the tests drop (kPieceHideWidth_mm x kPieceHideHeight_mm, inside the grbl table).
inline constexpr double kPieceHideWidth_mm = 1250, kPieceHideHeight_mm = 850;

// What both stores' tests expect of the cut files, as gtest failures: no problem found, every item cut
// exactly its demand, 38 pieces in all, each order's leather on one hide (the linings of 202 and 301 on the roll),
// every leather piece checked against each zone below its grade and for its grain. Returns the pieces.
int expect_every_order_cut_once(const std::vector<PieceOrder>& orders, const std::map<std::string, NestItem>& items,
                                CutPieces& cut);

// A job folder's items files: items.json, or a job of several materials' items-<material>.json.
std::vector<std::filesystem::path> job_items_files(const std::filesystem::path& job_dir);
// Every job's items, by label, from items.json files.
std::map<std::string, NestItem> items_by_label(const std::vector<std::filesystem::path>& items_files);

}  // namespace lastcut::daemon::testing
