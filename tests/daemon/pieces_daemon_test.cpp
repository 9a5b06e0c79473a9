// lastcutd cutting a shoe's pieces (issue 35), one station, the real binaries: a derby order, a lined
// derby order (its linings cut from the roll before its leather) and a loafer order (each a pair from one scanned last, pieces made with the shipped styles) and a
// DXF-AAMA pattern set of a tongue and its linings are dropped together; leather hides with poor zones
// and a backbone are dropped for cutter-1 until every order is cut, the linings go to the roll on
// cutter-2 (order 301 is one job of two materials, cut in two parts). Checked
// on the cut files the simulated grbl tables received, by an independent reading of the G-code
// (piece_orders.hpp): every piece of every order cut exactly once and labelled, a pair on one hide,
// no piece on a zone below its grade, every grain within its tolerance of the backbone.
#include <gtest/gtest.h>

#include "daemon_rig.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/daemon/piece_orders.hpp"

namespace lastcut::daemon::testing {
namespace {

// The stage of the batch of hide file `file` ("" while there is none).
std::string hide_stage(const DaemonRig& rig, const std::string& file) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(rig.spool() / "batches", error), end; !error && it != end; it.increment(error)) {
    const auto batch = nlohmann::json::parse(read_text(it->path() / "batch.json"), nullptr, false);
    if (!batch.is_discarded() && batch.contains("hide") && batch["hide"].value("file", "") == file) return batch.value("stage", "");
  }
  return "";
}

TEST(DaemonPieces, StylesAndAPatternSetAreCutByMaterialWithTheirRules) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.grbl_cutters = {"cutter-1", "cutter-2"};  // G-code: the piece labels are in the file
  options.extra_paths = piece_paths_config();
  options.extra_config = piece_materials_config("cutter-1");
  DaemonRig rig("pieces-e2e", options);
  const auto staging = rig.root() / "staging";
  const std::vector<PieceOrder> orders = write_piece_orders(staging);
  rig.start_cutters();
  rig.start_daemon();
  for (const PieceOrder& order : orders) {
    write_text(rig.watch() / (std::filesystem::path(order.file).stem().string() + ".job.toml"), order.sidecar);
    drop(staging / order.file, rig.watch(), order.file);
  }
  // The linings are cut from the roll at once (301's first part); the leather waits for hides: one at a time until no
  // order waits (each hide has room for about two pairs).
  std::filesystem::create_directories(rig.root() / "hides");
  const auto all_done = [&] {
    int done = 0;
    for (const PieceOrder& order : orders) done += rig.find_job(order.file).folder == "done";
    return done == static_cast<int>(orders.size());
  };
  // Every order waits for a hide (computed, its part of leather current) or is cut (done); nothing is on
  // its way. Order 301 gets there once its linings are cut.
  const auto leather_settled = [&] {
    for (const PieceOrder& order : orders) {
      const DaemonRig::FoundJob job = rig.find_job(order.file);
      if (job.folder == "done") continue;
      if (job.folder != "work" || job.state.value("stage", "") != "computed" ||
          job.state["ticket"].value("material", "") != "leather")
        return false;
    }
    return true;
  };
  ASSERT_TRUE(wait_until(leather_settled, 120)) << read_text(rig.daemon_log());
  // `lastcut status` says which of 301's pieces wait for which material.
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  EXPECT_NE(read_text(status_log).find("parts: 6 pieces of lining cut; 2 pieces of leather now"), std::string::npos)
      << read_text(status_log);
  for (int hide = 1; hide <= 4 && !all_done(); ++hide) {
    const std::string name = "hide-" + std::to_string(hide) + ".dxf";
    write_zoned_hide(staging / name, kPieceHideWidth_mm, kPieceHideHeight_mm);
    drop(staging / name, rig.root() / "hides", name);
    ASSERT_TRUE(wait_until([&] { const std::string stage = hide_stage(rig, name); return (stage == "cut" || stage == "empty") && leather_settled(); }, 120))
        << name << "\n" << read_text(rig.daemon_log());
  }
  ASSERT_TRUE(wait_until(all_done, 60)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();
  // A style's or a pattern set's job says what it computes: pieces, not molds.
  const std::string log = read_text(rig.daemon_log());
  EXPECT_EQ(log.find("computing molds"), std::string::npos);
  EXPECT_NE(log.find("computing pieces, attempt 1"), std::string::npos);

  // What the cut files cut, read independently of the nester.
  std::vector<std::filesystem::path> items_files;
  for (const PieceOrder& order : orders)
    for (const auto& file : job_items_files(rig.spool() / "done" / rig.find_job(order.file).id)) items_files.push_back(file);
  const std::map<std::string, NestItem> items = items_by_label(items_files);
  CutPieces cut;
  const std::string on_cutter_1 = rig.received("cutter-1"), on_cutter_2 = rig.received("cutter-2");
  for (const auto& entry : std::filesystem::directory_iterator(rig.spool() / "batches")) {
    const auto batch = read_json_file(entry.path() / "batch.json");
    if (batch.value("stage", "") != "cut") continue;
    const std::string gcode = read_text(entry.path() / "cut.nc");
    const bool on_hide = batch.contains("hide");
    EXPECT_EQ(count_occurrences(on_hide ? on_cutter_1 : on_cutter_2, gcode), 1) << entry.path();
    check_cut_file(gcode, entry.path().filename().string(),
                   on_hide ? zoned_hide_zones(kPieceHideWidth_mm, kPieceHideHeight_mm) : std::vector<QualityZone>{}, items, cut);
  }
  expect_every_order_cut_once(orders, items, cut);
}

}  // namespace
}  // namespace lastcut::daemon::testing
