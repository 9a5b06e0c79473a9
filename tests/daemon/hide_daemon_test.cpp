// lastcutd cutting leather hides, end to end with the real binaries (docs/hides.md): generated
// lasts with sidecars (two orders - one pair as two lasts, one as a mirrored pair - and single
// feet) wait for material kind "hide"; hide files (DXF with a hole and a low-grade zone, JSON with
// a hole) are dropped for simulated HPGL cutters on pseudo-terminals. Proves: every hide's cut file
// reaches its cutter once (bytes compared), every placed piece passes the independent checker on
// the written layout, an order's pieces lie on one hide, the pieces that did not fit wait and
// `lastcut status` says so, and a hide whose cut was interrupted by SIGKILL is held after the
// restart and never sent again.
// The hides are sized from the pieces' own bounding boxes, so the outcome does not depend on how well
// the nester packs: each has room for its pieces side by side, and the one that must leave an
// order waiting has less area than that order's pieces.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <thread>

#include "daemon_rig.hpp"
#include "engine/nest/nest_json.hpp"
#include "tests/daemon/hide_samples.hpp"

namespace lastcut::daemon::testing {
namespace {

nlohmann::json hide_batch(const DaemonRig& rig, const std::string& file) { return spool_hide_batch(rig.spool(), file); }

std::string stage_of(const DaemonRig& rig, const std::string& file) { return spool_hide_stage(rig.spool(), file); }

std::filesystem::path items_of(const DaemonRig& rig, const std::string& id) {
  return rig.spool() / "work" / id / "items.json";
}

// Every placement of the batch's written layout passes the independent checker; returns its placements.
std::size_t check_written_layout(const DaemonRig& rig, const std::string& batch_id, std::size_t zones) {
  return check_hide_layout(rig.spool() / "batches" / batch_id / "layout.json", zones);
}

bool all_computed(const DaemonRig& rig, const std::vector<std::string>& scans) {
  const auto work = rig.jobs("work");
  int computed = 0;
  for (const auto& [id, state] : work)
    for (const std::string& scan : scans)
      if (state.value("scan", "") == scan && state.value("stage", "") == "computed") ++computed;
  return computed == static_cast<int>(scans.size());
}

TEST(DaemonHides, WaitingPiecesAreCutFromHidesOnceAcrossAKill) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.sim_faults = {{"cutter-2", "stall-at-line=20"}};  // the hide's cut hangs: lastcutd is killed meanwhile
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config = leather_hide_material("cutter-1");
  DaemonRig rig("hides-e2e", options);
  const auto hides = rig.root() / "hides";
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  rig.start_cutters();
  rig.start_daemon();

  const auto drop_last = [&](const std::string& name, int size, const std::string& side, const std::string& ticket) {
    write_variant(small_last(size, side == "right" ? "right" : "left", 7), staging / name, name);
    write_text(rig.watch() / (std::filesystem::path(name).stem().string() + ".job.toml"),
               "material = \"leather\"\nside = \"" + side + "\"\n" + ticket);
    drop(staging / name, rig.watch(), name);
  };
  const auto drop_hide = [&](const std::filesystem::path& made, const std::string& sidecar) {
    if (!sidecar.empty()) write_text(hides / (made.stem().string() + ".toml"), sidecar);
    drop(made, hides, made.filename().string());
  };

  // 1. One single foot, and the hide for it on cutter-2, whose cut hangs: SIGKILL while sending.
  drop_last("single-a.stl", 39, "left", "");
  ASSERT_TRUE(wait_until([&] { return all_computed(rig, {"single-a.stl"}); }, 60)) << read_text(rig.daemon_log());
  const std::string single_a = rig.find_job("single-a.stl").id;
  // Room for the two halves side by side (3 mm spacing), plus 70 mm for the hole.
  const auto [length_a, width_a] = piece_box_mm(items_of(rig, single_a));
  write_hide_dxf(staging / "hide-k.dxf", length_a + 90, 2 * width_a + 30, false);
  drop_hide(staging / "hide-k.dxf", "id = \"K-17\"\ncutter = \"cutter-2\"\nthickness_mm = 1.2\n");
  ASSERT_TRUE(wait_until([&] { return stage_of(rig, "hide-k.dxf") == "sending"; }, 60)) << read_text(rig.daemon_log());
  rig.kill_daemon();
  const std::string batch_k = hide_batch(rig, "hide-k.dxf").value("id", "");
  const std::string log_before = read_text(rig.daemon_log());
  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return stage_of(rig, "hide-k.dxf") == "held"; }, 30)) << read_text(rig.daemon_log());
  EXPECT_TRUE(wait_until([&] { return rig.find_job("single-a.stl").folder == "held"; }, 10));
  EXPECT_NE(hide_batch(rig, "hide-k.dxf").value("reason", "").find("pieces may be partly cut"), std::string::npos);

  // 2. Order 100 as a left and a right last, and a hide with room for its four halves (2 x 2).
  drop_last("o100-left.stl", 40, "left", "order = \"100\"\n");
  drop_last("o100-right.stl", 40, "right", "order = \"100\"\n");
  ASSERT_TRUE(wait_until([&] { return all_computed(rig, {"o100-left.stl", "o100-right.stl"}); }, 120))
      << read_text(rig.daemon_log());
  const auto [length_1, width_1] = piece_box_mm(items_of(rig, rig.find_job("o100-left.stl").id));
  const auto [length_1r, width_1r] = piece_box_mm(items_of(rig, rig.find_job("o100-right.stl").id));
  write_hide_dxf(staging / "hide-1.dxf", 2 * std::max(length_1, length_1r) + 110,
                 2 * std::max(width_1, width_1r) + 30, true);
  drop_hide(staging / "hide-1.dxf", "id = \"CALF-0001\"\nmaterial = \"leather\"\n");
  ASSERT_TRUE(wait_until([&] { const auto s = stage_of(rig, "hide-1.dxf"); return s == "cut" || s == "empty"; }, 60))
      << read_text(rig.daemon_log());
  ASSERT_EQ(stage_of(rig, "hide-1.dxf"), "cut") << hide_batch(rig, "hide-1.dxf").dump(1);

  // 3. Order 200 (one last cut as a mirrored pair: four halves) and a single foot; the JSON hide
  // has room for two halves and less area than order 200's four: the single is cut, order 200 waits.
  drop_last("o200-pair.stl", 41, "pair", "order = \"200\"\n");
  drop_last("single-b.stl", 38, "right", "");
  ASSERT_TRUE(wait_until([&] { return all_computed(rig, {"o200-pair.stl", "single-b.stl"}); }, 120))
      << read_text(rig.daemon_log());
  const auto [length_b, width_b] = piece_box_mm(items_of(rig, rig.find_job("single-b.stl").id));
  const double w2 = length_b + 45, h2 = 2 * width_b + 24;
  ASSERT_LT(w2 * h2, pieces_area_mm2(items_of(rig, rig.find_job("o200-pair.stl").id)));
  write_hide_json(staging / "hide-2.json", w2, h2);
  drop_hide(staging / "hide-2.json", "");  // no sidecar: the only hide material, its cutter
  ASSERT_TRUE(wait_until([&] { const auto s = stage_of(rig, "hide-2.json"); return s == "cut" || s == "empty"; }, 60))
      << read_text(rig.daemon_log());
  ASSERT_EQ(stage_of(rig, "hide-2.json"), "cut") << hide_batch(rig, "hide-2.json").dump(1);

  // `lastcut status` while it runs: the order that did not fit waits for a hide, and says why.
  ASSERT_TRUE(wait_until([&] { return read_text(rig.spool() / "status.json").find("\"leather\": 1") != std::string::npos; }, 10))
      << read_text(rig.spool() / "status.json");
  const auto status_log = rig.root() / "status.txt";
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  const std::string status = read_text(status_log);
  EXPECT_NE(status.find("1 job(s) of leather waiting for a hide, 4 pieces"), std::string::npos) << status;  // a mirrored pair: 2 x 2 halves
  EXPECT_NE(status.find("waiting for a hide of leather: did not fit on hide"), std::string::npos) << status;

  EXPECT_EQ(rig.stop_daemon(), 0);
  rig.stop_cutters();

  // The hides: each cut file reached cutter-1 exactly once; the killed one never reached cutter-1
  // and reached cutter-2 only in part (the stall), never whole.
  const std::string on_cutter_1 = rig.received("cutter-1");
  const std::string on_cutter_2 = rig.received("cutter-2");
  const std::string cut_k = read_text(rig.spool() / "batches" / batch_k / "cut.plt");
  ASSERT_FALSE(cut_k.empty());
  EXPECT_EQ(count_occurrences(on_cutter_2, cut_k), 0);
  EXPECT_EQ(count_occurrences(on_cutter_1, cut_k), 0);
  const std::string log_after = read_text(rig.daemon_log());  // the log is appended across the restart
  ASSERT_EQ(log_after.compare(0, log_before.size(), log_before), 0);
  EXPECT_EQ(log_after.find("batch " + batch_k + ": cutting", log_before.size()), std::string::npos) << "sent again after the restart";
  // (Killed as soon as batch.json said "sending": the log line of the cut may not have come yet.)

  std::map<std::string, std::string> batch_of_job;
  for (const char* file : {"hide-1.dxf", "hide-2.json"}) {
    const auto batch = hide_batch(rig, file);
    const std::string id = batch.value("id", "");
    const std::string cut = read_text(rig.spool() / "batches" / id / "cut.plt");
    ASSERT_FALSE(cut.empty()) << file;
    EXPECT_EQ(count_occurrences(on_cutter_1, cut), 1) << file;
    EXPECT_EQ(count_occurrences(on_cutter_2, cut), 0) << file;
    EXPECT_EQ(batch.value("cutter", ""), "cutter-1");
    EXPECT_EQ(static_cast<int>(check_written_layout(rig, id, std::string(file) == "hide-1.dxf" ? 2 : 0)),
              batch.value("pieces", -1))
        << file;
    const auto report = read_json_file(rig.spool() / "batches" / id / "hide-report.json");
    EXPECT_EQ(report.value("pieces_placed", -1), batch.value("pieces", -2));
    EXPECT_NEAR(report.value("utilisation_of_usable_area", -1.0), batch.value("utilisation", -2.0), 1e-12);
    EXPECT_GT(report.value("offcut_area_m2", 0.0), 0.0);
    EXPECT_LT(report.value("offcut_area_m2", 1e9), report.value("usable_area_m2", 0.0));
    EXPECT_NE(read_text(rig.spool() / "batches" / id / "offcut.dxf").find("OFFCUT"), std::string::npos);
    for (const auto& job : batch["jobs"]) batch_of_job[job.get<std::string>()] = id;
  }
  EXPECT_EQ(hide_batch(rig, "hide-1.dxf")["hide"].value("id", ""), "CALF-0001");
  EXPECT_TRUE(instance_from_layout_json(read_json_file(rig.spool() / "batches" / hide_batch(rig, "hide-1.dxf").value("id", "") /
                                                       "layout.json"))
                  .bins[0]
                  .backbone_deg.has_value())
      << "hide-1's backbone reaches the layout, so the grain is checked";
  EXPECT_EQ(read_json_file(rig.spool() / "batches" / batch_k / "hide-report.json").value("thickness_mm", 0.0), 1.2);
  EXPECT_EQ(hide_batch(rig, "hide-2.json")["hide"].value("id", ""), "hide-2");

  // Jobs: cut whole in done/ on exactly the hide whose batch lists them, or still waiting in work/.
  const auto done = rig.jobs("done");
  const auto work = rig.jobs("work");
  int waiting = 0;
  for (const std::string scan : {"o100-left.stl", "o100-right.stl", "o200-pair.stl", "single-b.stl"}) {
    const auto [id, folder, state] = rig.find_job(scan);
    if (folder == "done") {
      EXPECT_EQ(done.at(id).value("stage", ""), "cut") << scan;
      EXPECT_EQ(done.at(id).value("batch", ""), batch_of_job[id]) << scan;
      EXPECT_EQ(read_text(rig.spool() / "done" / id / "cut.plt"),
                read_text(rig.spool() / "batches" / batch_of_job[id] / "cut.plt"));
    } else {
      ASSERT_EQ(folder, "work") << scan;
      EXPECT_EQ(work.at(id).value("stage", ""), "computed") << scan;
      EXPECT_EQ(work.at(id).value("reason", "").rfind("waiting for a hide of leather: did not fit on hide", 0), 0u);
      EXPECT_EQ(batch_of_job.count(id), 0u);
      ++waiting;
    }
  }
  // Order 100 cut on one hide, single-b on the JSON hide, order 200 waits.
  EXPECT_EQ(rig.find_job("o100-left.stl").folder, "done");
  EXPECT_EQ(rig.find_job("o100-right.stl").folder, "done");
  EXPECT_EQ(batch_of_job[rig.find_job("o100-left.stl").id], hide_batch(rig, "hide-1.dxf").value("id", ""));
  EXPECT_EQ(batch_of_job[rig.find_job("o100-right.stl").id], hide_batch(rig, "hide-1.dxf").value("id", ""));
  EXPECT_EQ(batch_of_job[rig.find_job("single-b.stl").id], hide_batch(rig, "hide-2.json").value("id", ""));
  EXPECT_EQ(rig.find_job("o200-pair.stl").folder, "work");
  EXPECT_EQ(waiting, 1);
  EXPECT_NE(log_after.find("waiting for a hide of leather: did not fit on hide"), std::string::npos);
}

}  // namespace
}  // namespace lastcut::daemon::testing
