// A shoe's pieces on the ledger (issue 35), the real binaries: two lastcutd nodes on a PostgreSQL
// ledger and a mosquitto broker started by the test - station-a (compute + station, cutter-1: a
// simulated grbl table for the leather hides, the hides folder beside it) and station-b (compute +
// station, cutter-2: the lining roll). The orders of tests/daemon/piece_orders.hpp are dropped on both
// nodes: a derby pair, a lined derby pair and a loafer pair (the shipped styles) and a DXF-AAMA pattern set
// of a tongue of leather and its linings (the lined derby and the set: jobs of two materials, cut in two parts).
// Hides with poor zones and a backbone are dropped for cutter-1 until every order is cut. Checked on
// the cut files the simulators received, by the independent reading of the G-code: every piece of every
// order cut exactly once and labelled, a pair on one hide, no piece on a zone below its grade, every
// grain within its tolerance of the backbone.
#include <gtest/gtest.h>


#include "tests/daemon/daemon_rig.hpp"
#include "tests/daemon/piece_orders.hpp"
#include "tests/ledger/ledger_shop.hpp"
#include "tests/support/mosquitto_broker.hpp"

namespace lastcut::daemon::testing {
namespace {

ShopOptions shop_options() {
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"station-b", {"compute", "station"}}};
  options.cutters = {{"cutter-1", "grbl", "station-a"}, {"cutter-2", "grbl", "station-b"}};
  options.batch_window_s = 0.5;
  options.max_pieces = 0;
  options.extra_paths = piece_paths_config();
  options.extra_config = piece_materials_config("cutter-1");
  return options;
}

TEST(LedgerPieces, StylesAndAPatternSetAreCutByMaterialOnTwoStations) {
  LedgerShop shop("ledger-pieces", shop_options());
  ASSERT_EQ(shop.start_services(), "");
  lastcut::test::MqttSubscriber watcher(shop.broker().port(), "lastcut/+/+/nesting");
  ASSERT_TRUE(watcher.wait_subscribed(10));
  for (const char* cutter : {"cutter-1", "cutter-2"}) ASSERT_EQ(shop.start_cutter(cutter), "");
  for (const char* node : {"station-a", "station-b"}) ASSERT_EQ(shop.start_node(node), "");
  const auto staging = shop.root() / "staging";
  const std::vector<PieceOrder> orders = write_piece_orders(staging);
  for (std::size_t k = 0; k < orders.size(); ++k) {  // the derbies at station-a, the loafer and the linings at station-b
    const auto watch = shop.watch(k < 2 ? "station-a" : "station-b");
    write_text(watch / (std::filesystem::path(orders[k].file).stem().string() + ".job.toml"), orders[k].sidecar);
    drop(staging / orders[k].file, watch, orders[k].file);
  }
  const auto state_of = [&](const PieceOrder& order) { return shop.value("SELECT state FROM jobs WHERE scan_name = '" + order.file + "'"); };
  // Every order waits for a hide (computed, its part of leather current) or is cut; order 301 gets there
  // once its linings are cut on station-b.
  const auto leather_settled = [&] {
    for (const PieceOrder& order : orders) {
      const auto row = shop.rows("SELECT state, material FROM jobs WHERE scan_name = '" + order.file + "'");
      if (row.size() != 1 || !(row[0][0] == "done" || (row[0][0] == "computed" && row[0][1] == "leather"))) return false;
    }
    return true;
  };
  const auto all_done = [&] {
    for (const PieceOrder& order : orders)
      if (state_of(order) != "done") return false;
    return true;
  };
  ASSERT_TRUE(wait_until(leather_settled, 180)) << shop.log_tails();
  for (int hide = 1; hide <= 4 && !all_done(); ++hide) {
    const std::string name = "hide-" + std::to_string(hide);
    write_zoned_hide(staging / (name + ".dxf"), kPieceHideWidth_mm, kPieceHideHeight_mm);
    drop(staging / (name + ".dxf"), shop.node_dir("station-a") / "hides", name + ".dxf");
    ASSERT_TRUE(wait_until([&] {
      const std::string state = shop.value("SELECT b.state FROM batches b JOIN hides h ON h.id = b.hide_id WHERE h.name = '" + name +
                                           "' ORDER BY b.id DESC LIMIT 1");
      return state == "cut" && leather_settled();
    }, 120)) << name << shop.log_tails();
  }
  ASSERT_TRUE(wait_until(all_done, 90)) << shop.log_tails();
  for (const char* node : {"station-a", "station-b"}) EXPECT_EQ(shop.stop_node(node), 0);
  for (const char* cutter : {"cutter-1", "cutter-2"}) shop.stop_cutter(cutter);

  std::vector<std::filesystem::path> items_files;
  for (const PieceOrder& order : orders) {
    const auto job_dir = shop.shared_dir() / "jobs" / shop.value("SELECT scan_sha256 FROM jobs WHERE scan_name = '" + order.file + "'");
    for (const auto& file : job_items_files(job_dir)) items_files.push_back(file);
  }
  const std::map<std::string, NestItem> items = items_by_label(items_files);
  CutPieces cut;
  const std::string on_cutter_1 = shop.received("cutter-1"), on_cutter_2 = shop.received("cutter-2");
  for (const auto& row : shop.rows("SELECT id, cut_file, hide_id IS NOT NULL FROM batches WHERE state = 'cut'")) {
    const std::string gcode = read_text(shop.shared_dir() / row[1]);
    const bool on_hide = row[2] == "t";
    EXPECT_EQ(count_occurrences(on_hide ? on_cutter_1 : on_cutter_2, gcode), 1) << "batch " << row[0];
    check_cut_file(gcode, "batch " + row[0], on_hide ? zoned_hide_zones(kPieceHideWidth_mm, kPieceHideHeight_mm) : std::vector<QualityZone>{},
                   items, cut);
  }
  const int pieces = expect_every_order_cut_once(orders, items, cut);

  // MQTT per material and per hide: the last nesting of each (retained), its pieces placed and waiting.
  const auto nesting = [&](const std::string& topic) {
    const auto message = watcher.last(topic);
    return message ? nlohmann::json::parse(message->payload, nullptr, false) : nlohmann::json();
  };
  // The linings of 202 (lined derby: vamp, quarter and tongue linings) and 301 (tongue and linings): 6 + 6
  // pieces, in one or two roll batches.
  EXPECT_EQ(shop.value("SELECT sum(pieces) FROM batches WHERE material = 'lining' AND state = 'cut'"), "12");
  EXPECT_GT(nesting("lastcut/material/lining/nesting").value("pieces_placed", -1), 0);
  EXPECT_EQ(nesting("lastcut/material/leather/nesting").value("pieces_waiting", -1), 0) << "the last hide left nothing waiting";
  int on_hides = 0;
  for (const auto& row : shop.rows("SELECT name FROM hides")) {
    const auto hide = nesting("lastcut/hide/" + row[0] + "/nesting");
    EXPECT_EQ(hide.value("material", ""), "leather") << row[0];
    EXPECT_GT(hide.value("utilisation", 0.0), 0.0) << row[0];
    on_hides += hide.value("pieces_placed", 0);
  }
  EXPECT_EQ(on_hides, pieces - 12);

  // Order 301, one job of two materials: its linings cut on station-b's roll, then its tongues on a hide.
  const std::string job_301 = "(SELECT id FROM jobs WHERE scan_name = 'tongue-301.dxf')";
  EXPECT_EQ(shop.value("SELECT part || ' ' || jsonb_array_length(parts) FROM jobs WHERE id = " + job_301), "1 2");
  EXPECT_EQ(shop.value("SELECT count(*) FROM job_events WHERE event = 'cut' AND job_id = " + job_301), "2");
  EXPECT_EQ(shop.value("SELECT detail FROM job_events WHERE event = 'computed' AND detail <> '' AND job_id = " + job_301),
            "next part 2 of 2: 2 pieces of leather for cutter-1");
}

}  // namespace
}  // namespace lastcut::daemon::testing
