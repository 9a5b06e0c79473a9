// Leather hides on the ledger, end to end with the real binaries (issues #13 and #15): two real
// lastcutd nodes on a PostgreSQL ledger and a mosquitto broker started by the test - station-a
// (compute + station, cutter-a: a simulated HPGL plotter on a pty, the hides folder beside it) and
// compute-b (compute only). Generated lasts with sidecars (order 100 as a left and a right last,
// order 200 as a mirrored pair, a single foot) wait for material kind "hide"; hide files (DXF with a
// hole and low-grade zones, JSON with a hole) are dropped for cutter-a. Proves: the jobs of a hide
// material never go on a strip; every hide's cut file reaches the cutter once (bytes compared);
// every placed piece passes the independent checker on the layout in the shared folder; an order
// lies on one hide; the order that did not fit waits with its reason, in the ledger and in
// `lastcut status`; an order that allows splitting is cut over two hides, each piece once, the
// shop's jobs.parts and events saying so (the second test); a bad hide file is refused with one line into failed/ while the node runs on;
// a hide whose cut was interrupted by a SIGKILL of its station is held and never sent again; job
// events over MQTT name the scan, order and batch, the hold included.
// The hides are sized from the pieces' own bounding boxes (tests/daemon/hide_samples.hpp), so the
// outcome does not depend on how well the nester packs.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <set>
#include <thread>

#include <nlohmann/json.hpp>

#include "engine/core/dxf_document.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/daemon/daemon_rig.hpp"
#include "tests/daemon/hide_samples.hpp"
#include "tests/ledger/ledger_shop.hpp"

namespace lastcut::daemon::testing {
namespace {

ShopOptions shop_options() {
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"compute-b", {"compute"}}};
  options.cutters = {{"cutter-a", "hpgl", "station-a"}};
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config = leather_hide_material("cutter-a");
  return options;
}

class LedgerHides : public ::testing::Test {
 protected:
  // One shop folder per test.
  LedgerHides()
      : shop_(std::string("ledger-hides-") + ::testing::UnitTest::GetInstance()->current_test_info()->name(),
              shop_options()),
        staging_(shop_.root() / "staging") {
    std::filesystem::create_directories(staging_);
  }

  // A generated last with its sidecar, dropped into station-a's watch folder.
  void drop_last(const std::string& name, int size, const std::string& side, const std::string& ticket) {
    write_variant(small_last(size, side == "right" ? "right" : "left", 7), staging_ / name, name);
    write_text(shop_.watch("station-a") / (std::filesystem::path(name).stem().string() + ".job.toml"),
               "material = \"leather\"\nside = \"" + side + "\"\n" + ticket);
    drop(staging_ / name, shop_.watch("station-a"), name);
  }
  void drop_hide(const std::filesystem::path& made, const std::string& sidecar) {
    const auto hides = shop_.node_dir("station-a") / "hides";
    if (!sidecar.empty()) write_text(hides / (made.stem().string() + ".toml"), sidecar);
    drop(made, hides, made.filename().string());
  }
  std::string job_of(const std::string& scan) const {
    return shop_.value("SELECT id FROM jobs WHERE scan_name = '" + scan + "'");
  }
  std::string job_state(const std::string& scan) const {
    return shop_.value("SELECT state FROM jobs WHERE scan_name = '" + scan + "'");
  }
  bool computed(const std::vector<std::string>& scans) const {
    for (const std::string& scan : scans)
      if (job_state(scan) != "computed") return false;
    return true;
  }
  std::filesystem::path items_of(const std::string& scan) const {
    return shop_.shared_dir() / "jobs" / shop_.value("SELECT scan_sha256 FROM jobs WHERE scan_name = '" + scan + "'") /
           "items.json";
  }
  // The newest batch nested on hide `name`, and its state.
  std::string batch_of_hide(const std::string& name) const {
    return shop_.value("SELECT b.id FROM batches b JOIN hides h ON h.id = b.hide_id WHERE h.name = '" + name +
                       "' ORDER BY b.id DESC LIMIT 1");
  }
  std::string batch_state(const std::string& batch) const {
    return batch.empty() ? "" : shop_.value("SELECT state FROM batches WHERE id = " + batch);
  }
  std::filesystem::path batch_dir(const std::string& batch) const { return shop_.shared_dir() / "batches" / batch; }
  std::string cut_file(const std::string& batch) const {
    return read_text(shop_.shared_dir() / shop_.value("SELECT cut_file FROM batches WHERE id = " + batch));
  }

  LedgerShop shop_;
  std::filesystem::path staging_;
};

TEST_F(LedgerHides, WaitingPiecesAreCutFromHidesOnceAcrossAKill) {
  ASSERT_EQ(shop_.start_services(), "");
  lastcut::test::MqttSubscriber watcher(shop_.broker().port());
  ASSERT_TRUE(watcher.wait_subscribed(10));
  ASSERT_EQ(shop_.start_cutter("cutter-a"), "");
  ASSERT_EQ(shop_.start_node("station-a"), "");
  ASSERT_EQ(shop_.start_node("compute-b"), "");

  // 1. Order 100 as a left and a right last: computed, then they wait for a hide (no strip takes them).
  drop_last("o100-left.stl", 40, "left", "order = \"100\"\n");
  drop_last("o100-right.stl", 40, "right", "order = \"100\"\n");
  ASSERT_TRUE(wait_until([&] { return computed({"o100-left.stl", "o100-right.stl"}); }, 120)) << shop_.log_tails();
  std::this_thread::sleep_for(std::chrono::seconds(2));  // twice the batch window: a strip batch would be made now
  EXPECT_EQ(shop_.count("SELECT count(*) FROM batches"), 0) << "hide jobs wait for a hide, never go on a strip";

  // 2. A bad hide file (an open outline) is refused with its one line; the node runs on.
  {
    DxfDocument dxf(DxfVersion::R12, {{"HIDE", 7}});
    dxf.polyline("HIDE", {{0, 0}, {600, 0}, {600, 400}, {0, 400}}, false);
    write_text(staging_ / "open.dxf", dxf.str());
  }
  drop_hide(staging_ / "open.dxf", "id = \"BAD-1\"\n");
  const auto failed = shop_.spool("station-a") / "failed";
  ASSERT_TRUE(wait_until([&] { return std::filesystem::exists(failed / "open.dxf.reason"); }, 30)) << shop_.log_tails();
  const std::string refusal = read_text(failed / "open.dxf.reason");
  EXPECT_NE(refusal.find("open"), std::string::npos) << refusal;
  EXPECT_EQ(std::count(refusal.begin(), refusal.end(), '\n'), 1) << "one line: " << refusal;
  EXPECT_NE(read_text(shop_.log_file("station-a")).find("open.dxf: refused"), std::string::npos);
  EXPECT_TRUE(std::filesystem::exists(failed / "open.dxf"));
  EXPECT_EQ(shop_.count("SELECT count(*) FROM hides"), 0);

  // 3. A DXF hide with a hole, two low-grade zones and a backbone, with room for order 100's four halves.
  const auto [length_1, width_1] = piece_box_mm(items_of("o100-left.stl"));
  const auto [length_1r, width_1r] = piece_box_mm(items_of("o100-right.stl"));
  write_hide_dxf(staging_ / "hide-1.dxf", 2 * std::max(length_1, length_1r) + 110, 2 * std::max(width_1, width_1r) + 30,
                 true);
  drop_hide(staging_ / "hide-1.dxf", "id = \"CALF-0001\"\nmaterial = \"leather\"\ncutter = \"cutter-a\"\n");
  ASSERT_TRUE(wait_until([&] { return batch_state(batch_of_hide("CALF-0001")) == "cut"; }, 90)) << shop_.log_tails();
  const std::string batch_1 = batch_of_hide("CALF-0001");
  EXPECT_EQ(shop_.value("SELECT state FROM hides WHERE name = 'CALF-0001'"), "used");

  // 4. Order 200 (one last as a mirrored pair: four halves) and a single foot; the JSON hide (no
  // sidecar: the only hide material, its cutter) has room for two halves and less area than order
  // 200's four: the single is cut, order 200 waits and says why.
  drop_last("o200-pair.stl", 41, "pair", "order = \"200\"\n");
  drop_last("single-b.stl", 38, "right", "");
  ASSERT_TRUE(wait_until([&] { return computed({"o200-pair.stl", "single-b.stl"}); }, 120)) << shop_.log_tails();
  const auto [length_b, width_b] = piece_box_mm(items_of("single-b.stl"));
  const double w2 = length_b + 45, h2 = 2 * width_b + 24;
  ASSERT_LT(w2 * h2, pieces_area_mm2(items_of("o200-pair.stl")));
  write_hide_json(staging_ / "hide-2.json", w2, h2);
  drop_hide(staging_ / "hide-2.json", "");
  ASSERT_TRUE(wait_until([&] { return batch_state(batch_of_hide("hide-2")) == "cut"; }, 90)) << shop_.log_tails();
  const std::string batch_2 = batch_of_hide("hide-2");
  EXPECT_EQ(job_state("single-b.stl"), "done");
  EXPECT_EQ(job_state("o200-pair.stl"), "computed");
  const std::string waiting = shop_.value("SELECT reason FROM jobs WHERE scan_name = 'o200-pair.stl'");
  EXPECT_EQ(waiting.rfind("waiting for a hide of leather: did not fit on hide", 0), 0u) << waiting;
  const auto status_log = shop_.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", shop_.config_file("compute-b").string()},
                        status_log),
            0);
  const std::string status = read_text(status_log);
  EXPECT_NE(status.find("1 job(s) of leather waiting for a hide, 4 pieces"), std::string::npos) << status;  // a mirrored pair: 2 x 2 halves
  EXPECT_NE(status.find("waiting for a hide of leather: did not fit on hide"), std::string::npos) << status;
  EXPECT_NE(status.find("hide CALF-0001"), std::string::npos) << status;

  // 5. A hide for order 200 whose cut hangs at line 20: station-a is killed while sending it. The
  // batch is held (by compute-b's sweep or station-a's restart) and never sent again.
  shop_.stop_cutter("cutter-a");
  ASSERT_EQ(shop_.start_cutter("cutter-a", "stall-at-line=20"), "");
  const auto [length_3, width_3] = piece_box_mm(items_of("o200-pair.stl"));
  write_hide_dxf(staging_ / "hide-3.dxf", 2 * length_3 + 110, 2 * width_3 + 30, false);
  drop_hide(staging_ / "hide-3.dxf", "id = \"K-17\"\nthickness_mm = 1.2\n");
  ASSERT_TRUE(wait_until([&] { return batch_state(batch_of_hide("K-17")) == "sending"; }, 90)) << shop_.log_tails();
  const std::string batch_3 = batch_of_hide("K-17");
  shop_.kill_node("station-a");
  shop_.stop_cutter("cutter-a");
  ASSERT_EQ(shop_.start_cutter("cutter-a"), "");
  ASSERT_EQ(shop_.start_node("station-a"), "");
  ASSERT_TRUE(wait_until([&] { return batch_state(batch_3) == "held"; }, 30)) << shop_.log_tails();
  EXPECT_EQ(job_state("o200-pair.stl"), "held");
  std::this_thread::sleep_for(std::chrono::seconds(2));  // a station that wrongly re-sent would start now
  EXPECT_EQ(shop_.stop_node("station-a"), 0);
  EXPECT_EQ(shop_.stop_node("compute-b"), 0);
  shop_.stop_cutter("cutter-a");

  // Bytes: hides 1 and 2 reached the cutter once each, in its first run; hide 3 only in part, in its
  // second (the stall), and never in the third (after the restart).
  const auto runs = shop_.received_per_run("cutter-a");
  ASSERT_EQ(runs.size(), 3u);
  for (const std::string& batch : {batch_1, batch_2}) {
    const std::string cut = cut_file(batch);
    ASSERT_FALSE(cut.empty()) << batch;
    EXPECT_EQ(count_occurrences(runs[0], cut), 1) << "batch " << batch;
    EXPECT_EQ(count_occurrences(runs[1] + runs[2], cut), 0) << "batch " << batch;
  }
  const std::string cut_3 = cut_file(batch_3);
  ASSERT_GT(cut_3.size(), 200u);
  EXPECT_EQ(count_occurrences(runs[1], cut_3), 0) << "the stalled cut never completed";
  // What reached the stalled cutter is a beginning of it: as much as the link carried before the kill,
  // which comes as soon as the batch says "sending" (measured: 8 lines of 20 in one run of ten).
  EXPECT_LT(runs[1].size(), cut_3.size());
  EXPECT_EQ(cut_3.compare(0, runs[1].size(), runs[1]), 0) << "the stalled cutter received " << runs[1].substr(0, 200);
  EXPECT_EQ(runs[2].find(cut_3.substr(0, 100)), std::string::npos) << "sent again after the restart";

  // Layouts: every placed piece passes the independent checker; the report and the offcut are there.
  EXPECT_EQ(static_cast<long long>(check_hide_layout(batch_dir(batch_1) / "layout.json", 2)),
            shop_.count("SELECT pieces FROM batches WHERE id = " + batch_1));
  EXPECT_EQ(static_cast<long long>(check_hide_layout(batch_dir(batch_2) / "layout.json", 0)),
            shop_.count("SELECT pieces FROM batches WHERE id = " + batch_2));
  for (const std::string& batch : {batch_1, batch_2, batch_3}) {
    const auto report = read_json_file(batch_dir(batch) / "hide-report.json");
    EXPECT_EQ(report.value("pieces_placed", -1), shop_.count("SELECT pieces FROM batches WHERE id = " + batch));
    EXPECT_NEAR(report.value("utilisation_of_usable_area", -1.0),
                std::stod(shop_.value("SELECT utilisation FROM batches WHERE id = " + batch)), 1e-9);
    EXPECT_NE(read_text(batch_dir(batch) / "offcut.dxf").find("OFFCUT"), std::string::npos);
  }
  EXPECT_EQ(read_json_file(batch_dir(batch_3) / "hide-report.json").value("thickness_mm", 0.0), 1.2);

  // Jobs: order 100 on hide 1 (one hide for the order), the single on hide 2, order 200 held on hide 3.
  const auto batch_of_job = [&](const std::string& scan) {
    return shop_.value("SELECT batch_id FROM jobs WHERE scan_name = '" + scan + "'");
  };
  EXPECT_EQ(batch_of_job("o100-left.stl"), batch_1);
  EXPECT_EQ(batch_of_job("o100-right.stl"), batch_1);
  EXPECT_EQ(batch_of_job("single-b.stl"), batch_2);
  EXPECT_EQ(batch_of_job("o200-pair.stl"), batch_3);
  EXPECT_EQ(job_state("o100-left.stl"), "done");
  EXPECT_EQ(job_state("o100-right.stl"), "done");
  EXPECT_EQ(shop_.count("SELECT count(*) FROM job_events WHERE event = 'waiting' AND job_id = " + job_of("o200-pair.stl")), 1);

  // MQTT: the cut of order 100 was told with its scan, order, cutter and hide batch.
  int told = 0;
  for (const std::string scan : {"o100-left.stl", "o100-right.stl"}) {
    for (const auto& message : watcher.on("lastcut/job/" + job_of(scan) + "/event")) {
      const auto event = nlohmann::json::parse(message.payload, nullptr, false);
      if (event.is_discarded() || event.value("stage", "") != "cut") continue;
      EXPECT_EQ(event.value("scan", ""), scan);
      EXPECT_EQ(event.value("order", ""), "100");
      EXPECT_EQ(event.value("cutter", ""), "cutter-a");
      EXPECT_EQ(event.value("batch", ""), batch_1);
      ++told;
    }
  }
  EXPECT_EQ(told, 2);
  // ... and the hold of order 200, by whichever node found the station gone (compute-b's sweep or
  // station-a's restart), with the hide's batch and the reason.
  int held_told = 0;
  for (const auto& message : watcher.on("lastcut/job/" + job_of("o200-pair.stl") + "/event")) {
    const auto event = nlohmann::json::parse(message.payload, nullptr, false);
    if (event.is_discarded() || event.value("stage", "") != "held") continue;
    EXPECT_EQ(event.value("scan", ""), "o200-pair.stl");
    EXPECT_EQ(event.value("order", ""), "200");
    EXPECT_EQ(event.value("batch", ""), batch_3);
    EXPECT_NE(event.value("reason", "").find("while sending batch " + batch_3), std::string::npos) << message.payload;
    ++held_told;
  }
  EXPECT_EQ(held_told, 1);
}

TEST_F(LedgerHides, AnOrderThatAllowsSplittingIsCutOverTwoHidesEachPieceOnce) {
  ASSERT_EQ(shop_.start_services(), "");
  ASSERT_EQ(shop_.start_cutter("cutter-a"), "");
  ASSERT_EQ(shop_.start_node("station-a"), "");
  ASSERT_EQ(shop_.start_node("compute-b"), "");
  // Order 300 (a mirrored pair, four halves) may split; order 400, the same, may not.
  drop_last("o300-pair.stl", 41, "pair", "order = \"300\"\nsplit_over_hides = true\n");
  ASSERT_TRUE(wait_until([&] { return computed({"o300-pair.stl"}); }, 120)) << shop_.log_tails();
  drop_last("o400-pair.stl", 41, "pair", "order = \"400\"\n");
  ASSERT_TRUE(wait_until([&] { return computed({"o400-pair.stl"}); }, 120)) << shop_.log_tails();
  const std::map<std::string, int> pieces_300 = pieces_by_label(items_of("o300-pair.stl"));
  const std::map<std::string, int> pieces_400 = pieces_by_label(items_of("o400-pair.stl"));
  ASSERT_EQ(pieces_300.size(), 4u);

  // Hide A, room for two halves and less area than a pair: some of order 300, none of order 400.
  const auto [length, width] = piece_box_mm(items_of("o300-pair.stl"));
  ASSERT_LT((length + 45) * (2 * width + 24), pieces_area_mm2(items_of("o300-pair.stl")));
  write_hide_json(staging_ / "hide-a.json", length + 45, 2 * width + 24);
  drop_hide(staging_ / "hide-a.json", "");
  ASSERT_TRUE(wait_until([&] { return batch_state(batch_of_hide("hide-a")) == "cut"; }, 90)) << shop_.log_tails();
  const std::string o300 = job_of("o300-pair.stl");
  ASSERT_TRUE(wait_until([&] { return job_state("o300-pair.stl") == "computed"; }, 10)) << shop_.log_tails();
  EXPECT_EQ(job_state("o400-pair.stl"), "computed");
  const long long placed_a = shop_.count("SELECT (parts -> 0 ->> 'pieces')::integer FROM jobs WHERE id = " + o300);
  EXPECT_GE(placed_a, 1);
  EXPECT_EQ(shop_.count("SELECT part FROM jobs WHERE id = " + o300), 1);
  EXPECT_EQ(shop_.count("SELECT pieces FROM jobs WHERE id = " + o300), 4 - placed_a) << "the rest is its part now";
  EXPECT_EQ(shop_.value("SELECT detail FROM job_events WHERE event = 'split' AND job_id = " + o300),
            std::to_string(placed_a) + " of 4 pieces of leather on hide hide-a; " + std::to_string(4 - placed_a) +
                " wait for the next hide");

  // Hides of room for a pair each, one at a time, until both orders are cut.
  std::vector<std::string> hide_names = {"hide-a"};
  for (int n = 1; job_state("o300-pair.stl") != "done" || job_state("o400-pair.stl") != "done"; ++n) {
    ASSERT_LE(n, 4) << "four hides of room for a pair each and the orders are not cut";
    const std::string name = "hide-b" + std::to_string(n);
    write_hide_json(staging_ / (name + ".json"), 2 * length + 110, 2 * width + 30);
    drop_hide(staging_ / (name + ".json"), "");
    ASSERT_TRUE(wait_until([&] { const auto s = batch_state(batch_of_hide(name)); return s == "cut" || s == "dissolved"; }, 90))
        << shop_.log_tails();
    hide_names.push_back(name);
    ASSERT_TRUE(wait_until([&] {
      for (const char* scan : {"o300-pair.stl", "o400-pair.stl"})
        if (job_state(scan) != "done" && job_state(scan) != "computed") return false;
      return true;
    }, 10));
  }
  // The overview counts order 300 among the jobs of each hide that cut a part of it, hide A included
  // (the job has left that batch for its next part).
  const auto overview_log = shop_.root() / "overview.json";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--json", "--config", shop_.config_file("compute-b").string()},
                        overview_log),
            0);
  const auto overview = nlohmann::json::parse(read_text(overview_log), nullptr, false);
  ASSERT_FALSE(overview.is_discarded()) << read_text(overview_log);
  const long long batch_a = std::stoll(batch_of_hide("hide-a"));
  int counted = 0;
  for (const auto& batch : overview["cut_last_24h"])
    if (batch.value("id", 0LL) == batch_a) counted = batch.value("jobs", -1);
  EXPECT_EQ(counted, 1) << overview["cut_last_24h"].dump();

  EXPECT_EQ(shop_.stop_node("station-a"), 0);
  EXPECT_EQ(shop_.stop_node("compute-b"), 0);
  shop_.stop_cutter("cutter-a");

  // Every half of both orders cut exactly once over the hides' layouts; order 400 on one hide.
  const std::string received = shop_.received_per_run("cutter-a").at(0);
  std::map<std::string, std::filesystem::path> layouts;
  for (const std::string& name : hide_names) {
    const std::string batch = batch_of_hide(name);
    if (batch_state(batch) != "cut") continue;
    EXPECT_EQ(count_occurrences(received, cut_file(batch)), 1) << name;
    layouts[name] = batch_dir(batch) / "layout.json";
  }
  const std::set<std::string> hides_of_300 = check_orders_over_hides(layouts, pieces_300, pieces_400, "hide-a");
  EXPECT_EQ(shop_.count("SELECT count(*) FROM job_events WHERE event = 'cut' AND job_id = " + o300),
            static_cast<long long>(hides_of_300.size()));
}

}  // namespace
}  // namespace lastcut::daemon::testing
