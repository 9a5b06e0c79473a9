// An order that allows splitting (sidecar split_over_hides = true, docs/hides.md), end to end with
// the real binaries: two orders of a mirrored pair each (four halves), one that may split and one that
// may not, wait for hides too small for a whole pair. Proves: the first hide takes some of the order
// that may split and none of the other (which waits whole); the rest of the first order is cut on a
// later hide; every half of both orders is cut exactly once, read from the hides' written layouts
// and checked there by the independent checker; the order that may not split lies on one hide;
// `lastcut status` and the job's report say which pieces were cut and which wait.
// The hides are sized from the pieces' own bounding boxes (hide_samples.hpp), so the outcome follows
// from areas, not from how well the nester packs.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "daemon_rig.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/daemon/hide_samples.hpp"

namespace lastcut::daemon::testing {
namespace {

TEST(DaemonHides, AnOrderThatAllowsSplittingIsCutOverTwoHidesEachPieceOnce) {
  RigOptions options;
  options.cutters = {"cutter-1"};
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config = leather_hide_material("cutter-1");
  DaemonRig rig("hides-split", options);
  const auto hides = rig.root() / "hides";
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  rig.start_cutters();
  rig.start_daemon();

  const auto drop_pair = [&](const std::string& name, const std::string& ticket) {
    write_variant(small_last(41, "left", 7), staging / name, name);
    write_text(rig.watch() / (std::filesystem::path(name).stem().string() + ".job.toml"),
               "material = \"leather\"\nside = \"pair\"\n" + ticket);
    drop(staging / name, rig.watch(), name);
  };
  const auto computed = [&](const std::string& scan) {
    const auto found = rig.find_job(scan);
    return found.folder == "work" && found.state.value("stage", "") == "computed";
  };
  // Order 300 first (the older, nested first), then order 400.
  drop_pair("o300-pair.stl", "order = \"300\"\nsplit_over_hides = true\n");
  ASSERT_TRUE(wait_until([&] { return computed("o300-pair.stl"); }, 120)) << read_text(rig.daemon_log());
  drop_pair("o400-pair.stl", "order = \"400\"\n");
  ASSERT_TRUE(wait_until([&] { return computed("o400-pair.stl"); }, 120)) << read_text(rig.daemon_log());
  const std::string o300 = rig.find_job("o300-pair.stl").id, o400 = rig.find_job("o400-pair.stl").id;
  const auto items_300 = rig.spool() / "work" / o300 / "items.json";
  const std::map<std::string, int> pieces_300 = pieces_by_label(items_300);
  const std::map<std::string, int> pieces_400 = pieces_by_label(rig.spool() / "work" / o400 / "items.json");
  ASSERT_EQ(pieces_300.size(), 4u) << "a mirrored pair: two halves a foot, each labelled with its foot";

  // Hide A: room for two halves side by side, less area than a pair's four halves.
  const auto [length, width] = piece_box_mm(items_300);
  const double w_a = length + 45, h_a = 2 * width + 24;
  ASSERT_LT(w_a * h_a, pieces_area_mm2(items_300));
  write_hide_json(staging / "hide-a.json", w_a, h_a);
  drop(staging / "hide-a.json", hides, "hide-a.json");
  ASSERT_TRUE(wait_until([&] { const auto s = spool_hide_stage(rig.spool(), "hide-a.json"); return s == "cut" || s == "empty"; }, 60))
      << read_text(rig.daemon_log());
  const auto batch_a = spool_hide_batch(rig.spool(), "hide-a.json");
  ASSERT_EQ(batch_a.value("stage", ""), "cut") << batch_a.dump(1);
  EXPECT_EQ(batch_a["jobs"], nlohmann::json::array({o300})) << "order 400 may not split: it waits whole";
  const auto report_a = read_json_file(rig.spool() / "batches" / batch_a.value("id", "") / "hide-report.json");
  ASSERT_TRUE(report_a.contains("jobs_split")) << report_a.dump(1);
  const int placed_a = report_a["jobs_split"][0].value("pieces_placed", 0);
  EXPECT_EQ(report_a["jobs_split"][0].value("job", ""), o300);
  EXPECT_GE(placed_a, 1);
  EXPECT_EQ(placed_a + report_a["jobs_split"][0].value("pieces_waiting", 0), 4);

  // Order 300 waits for the next hide with the rest of its pieces as its next part; status says so.
  ASSERT_TRUE(wait_until([&] { return computed("o300-pair.stl"); }, 10)) << read_text(rig.daemon_log());
  const auto state_300 = rig.find_job("o300-pair.stl").state;
  EXPECT_EQ(state_300.value("part", -1), 1);
  ASSERT_EQ(state_300["parts"].size(), 2u) << state_300.dump(1);
  EXPECT_EQ(state_300["parts"][1].value("pieces", 0), 4 - placed_a);
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  const std::string progress = std::to_string(placed_a) + (placed_a == 1 ? " piece" : " pieces") + " of leather cut; " +
                               std::to_string(4 - placed_a) + (placed_a == 3 ? " piece" : " pieces") + " of leather now";
  EXPECT_NE(read_text(status_log).find(progress), std::string::npos) << read_text(status_log);
  EXPECT_NE(read_text(rig.daemon_log()).find(std::to_string(placed_a) + " of 4 pieces of leather on hide hide-a; " +
                                             std::to_string(4 - placed_a) + " wait for the next hide"),
            std::string::npos);

  // Hides of room for a pair's four halves, one at a time, until both orders are cut.
  std::vector<std::string> hide_files = {"hide-a.json"};
  for (int n = 1; rig.find_job("o300-pair.stl").folder != "done" || rig.find_job("o400-pair.stl").folder != "done"; ++n) {
    ASSERT_LE(n, 4) << "four hides of room for a pair each and the orders are not cut";
    const std::string file = "hide-b" + std::to_string(n) + ".json";
    write_hide_json(staging / file, 2 * length + 110, 2 * width + 30);
    drop(staging / file, hides, file);
    ASSERT_TRUE(wait_until([&] { const auto s = spool_hide_stage(rig.spool(), file); return s == "cut" || s == "empty"; }, 60))
        << read_text(rig.daemon_log());
    hide_files.push_back(file);
    ASSERT_TRUE(wait_until([&] { return rig.find_job("o300-pair.stl").folder == "done" || computed("o300-pair.stl"); }, 10));
    ASSERT_TRUE(wait_until([&] { return rig.find_job("o400-pair.stl").folder == "done" || computed("o400-pair.stl"); }, 10));
  }
  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  // Every half of both orders cut exactly once, over the hides' layouts; order 400's on one hide.
  const std::string on_cutter = rig.received("cutter-1");
  std::map<std::string, std::filesystem::path> layouts;
  for (const std::string& file : hide_files) {
    const auto batch = spool_hide_batch(rig.spool(), file);
    if (batch.value("stage", "") != "cut") continue;
    const auto dir = rig.spool() / "batches" / batch.value("id", "");
    EXPECT_EQ(count_occurrences(on_cutter, read_text(dir / "cut.plt")), 1) << file;
    layouts[file] = dir / "layout.json";
  }
  const std::set<std::string> hides_of_300 = check_orders_over_hides(layouts, pieces_300, pieces_400, "hide-a.json");
  // The job's report lists each hide that cut a part of it.
  const auto report_300 = read_json_file(rig.spool() / "done" / o300 / "report.json");
  ASSERT_TRUE(report_300.contains("parts_cut")) << report_300.dump(1);
  EXPECT_EQ(report_300["parts_cut"].size(), hides_of_300.size());
  int pieces_in_parts = 0;
  for (const auto& part : report_300["parts_cut"]) pieces_in_parts += part.value("pieces", 0);
  EXPECT_EQ(pieces_in_parts, 4);
}

}  // namespace
}  // namespace lastcut::daemon::testing
