// lastcutd cutting leather hides, end to end with the real binaries (docs/hides.md): generated
// lasts with sidecars (two orders - one pair as two lasts, one as a mirrored pair - and single
// feet) wait for material kind "hide"; hide files (DXF with a hole and a low-grade zone, JSON with
// a hole) are dropped for simulated HPGL cutters on pseudo-terminals. Proves: every hide's cut file
// reaches its cutter once (bytes compared), every placed piece passes the independent checker on
// the written layout, an order's pieces lie on one hide, the pieces that did not fit wait and
// `lastcut status` says so, and a hide whose cut was interrupted by SIGKILL is held after the
// restart and never sent again.
// The hides are sized from the pieces' own areas, so the outcome does not depend on how well the
// nester packs: a hide holds 1.7-2.5 times what it must take, and less than what it must not.
#include <gtest/gtest.h>

#include <cmath>
#include <csignal>
#include <thread>

#include "daemon_rig.hpp"
#include "engine/core/dxf_document.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::daemon::testing {
namespace {

std::vector<Point2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// The job whose scan had this name, in any folder, with its folder.
std::pair<std::string, std::string> find_job(const DaemonRig& rig, const std::string& scan) {
  for (const char* folder : {"done", "failed", "held", "work"})
    for (const auto& [id, state] : rig.jobs(folder))
      if (state.value("scan", "") == scan) return {id, folder};
  return {};
}

// Area (mm^2) of a job's pieces, from its items.json in work/.
double job_area_mm2(const DaemonRig& rig, const std::string& id) {
  const auto items = items_from_json(read_json_file(rig.spool() / "work" / id / "items.json"), id);
  double area = 0;
  for (const NestItem& item : items) area += item.demand * std::abs(signed_area(item.shape));
  return area;
}

// The hide batch holding hide file `file`: batch.json, or null while it is not there.
nlohmann::json hide_batch(const DaemonRig& rig, const std::string& file) {
  std::error_code error;
  for (std::filesystem::directory_iterator it(rig.spool() / "batches", error), end; !error && it != end;
       it.increment(error)) {
    auto batch = nlohmann::json::parse(read_text(it->path() / "batch.json"), nullptr, false);
    if (!batch.is_discarded() && batch.contains("hide") && batch["hide"].value("file", "") == file) return batch;
  }
  return nullptr;
}

std::string stage_of(const DaemonRig& rig, const std::string& file) {
  const auto batch = hide_batch(rig, file);
  return batch.is_null() ? "" : batch.value("stage", "");
}

bool all_computed(const DaemonRig& rig, const std::vector<std::string>& scans) {
  const auto work = rig.jobs("work");
  int computed = 0;
  for (const auto& [id, state] : work)
    for (const std::string& scan : scans)
      if (state.value("scan", "") == scan && state.value("stage", "") == "computed") ++computed;
  return computed == static_cast<int>(scans.size());
}

// A hide DXF: a w x h rectangle with its corners cut by 40 mm, a hole, and a grade-1 zone.
void write_hide_dxf(const std::filesystem::path& file, double w, double h, bool zone) {
  DxfDocument dxf(DxfVersion::R12, {{"HIDE", 7}, {"HOLE", 1}, {"ZONE_1", 3}});
  dxf.polyline("HIDE", {{40, 0}, {w - 40, 0}, {w, 40}, {w, h - 40}, {w - 40, h}, {40, h}, {0, h - 40}, {0, 40}}, true);
  dxf.polyline("HOLE", rectangle(w / 2 - 20, h / 2 - 15, w / 2 + 20, h / 2 + 15), true);
  if (zone) dxf.polyline("ZONE_1", rectangle(w - 160, h - 160, w - 40, h - 40), true);
  write_text(file, dxf.str());
}

void write_hide_json(const std::filesystem::path& file, double w, double h) {
  nlohmann::json outer = nlohmann::json::array(), hole = nlohmann::json::array();
  for (const Point2& p : rectangle(0, 0, w, h)) outer.push_back({p.x(), p.y()});
  for (const Point2& p : rectangle(w - 60, 20, w - 20, 50)) hole.push_back({p.x(), p.y()});
  nlohmann::json bin;
  bin["id"] = 0;
  bin["shape"]["type"] = "polygon";
  bin["shape"]["data"]["outer"] = outer;
  bin["shape"]["data"]["inner"] = nlohmann::json::array({hole});
  write_text(file, nlohmann::json{{"bins", nlohmann::json::array({bin})}}.dump());
}

// Every placement of the batch's written layout passes the independent checker; returns its placements.
std::size_t check_written_layout(const DaemonRig& rig, const std::string& batch_id, std::size_t zones) {
  const auto json = read_json_file(rig.spool() / "batches" / batch_id / "layout.json");
  const NestInstance instance = instance_from_layout_json(json);
  const Layout layout = layout_from_json(json);
  const auto problems = check_layout(layout, instance);
  EXPECT_TRUE(problems.empty()) << batch_id << ": " << problems.front();
  for (const NestItem& item : instance.items) EXPECT_EQ(item.min_quality, 2) << "the material's min_quality";
  EXPECT_EQ(instance.bins.size(), 1u);
  EXPECT_EQ(instance.bins[0].zones.size(), zones) << "the low-grade zone is checked";
  EXPECT_EQ(instance.bins[0].holes.size(), 1u) << "the hole is checked";
  return layout.placements.size();
}

TEST(DaemonHides, WaitingPiecesAreCutFromHidesOnceAcrossAKill) {
  RigOptions options;
  options.cutters = {"cutter-1", "cutter-2"};
  options.sim_faults = {{"cutter-2", "stall-at-line=20"}};  // the hide's cut hangs: lastcutd is killed meanwhile
  options.extra_paths = "hides = \"hides\"\n";
  options.extra_config = "[materials.leather]\nkind = \"hide\"\ncutter = \"cutter-1\"\npairs = \"same_hide\"\n"
                         "min_quality = 2\nspacing_mm = 3\nrotation_step_deg = 90\n";
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
  const std::string single_a = find_job(rig, "single-a.stl").first;
  const double side_k = std::sqrt(2.5 * job_area_mm2(rig, single_a) + 1200 + 3200);
  write_hide_dxf(staging / "hide-k.dxf", side_k * 1.3, side_k / 1.3, false);
  drop_hide(staging / "hide-k.dxf", "id = \"K-17\"\ncutter = \"cutter-2\"\nthickness_mm = 1.2\n");
  ASSERT_TRUE(wait_until([&] { return stage_of(rig, "hide-k.dxf") == "sending"; }, 60)) << read_text(rig.daemon_log());
  rig.kill_daemon();
  const std::string batch_k = hide_batch(rig, "hide-k.dxf").value("id", "");
  const std::string log_before = read_text(rig.daemon_log());
  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return stage_of(rig, "hide-k.dxf") == "held"; }, 30)) << read_text(rig.daemon_log());
  EXPECT_EQ(find_job(rig, "single-a.stl").second, "held");
  EXPECT_NE(hide_batch(rig, "hide-k.dxf").value("reason", "").find("pieces may be partly cut"), std::string::npos);

  // 2. Two orders: 100 as a left and a right last, 200 as one last cut as a mirrored pair.
  drop_last("o100-left.stl", 40, "left", "order = \"100\"\n");
  drop_last("o100-right.stl", 40, "right", "order = \"100\"\n");
  drop_last("o200-pair.stl", 41, "pair", "order = \"200\"\n");
  const std::vector<std::string> orders = {"o100-left.stl", "o100-right.stl", "o200-pair.stl"};
  ASSERT_TRUE(wait_until([&] { return all_computed(rig, orders); }, 120)) << read_text(rig.daemon_log());
  const double o100 = job_area_mm2(rig, find_job(rig, "o100-left.stl").first) +
                      job_area_mm2(rig, find_job(rig, "o100-right.stl").first);
  const double o200 = job_area_mm2(rig, find_job(rig, "o200-pair.stl").first);
  // Room for the larger order with 85 % spare, but not for both: one order waits.
  ASSERT_LT(1.85 * std::max(o100, o200), o100 + o200);
  const double side_1 = std::sqrt(1.85 * std::max(o100, o200) + 1200 + 14400 + 3200);  // + hole, zone, corners
  write_hide_dxf(staging / "hide-1.dxf", side_1 * 1.4, side_1 / 1.4, true);
  drop_hide(staging / "hide-1.dxf", "id = \"CALF-0001\"\nmaterial = \"leather\"\n");
  ASSERT_TRUE(wait_until([&] { const auto s = stage_of(rig, "hide-1.dxf"); return s == "cut" || s == "empty"; }, 60))
      << read_text(rig.daemon_log());
  ASSERT_EQ(stage_of(rig, "hide-1.dxf"), "cut") << hide_batch(rig, "hide-1.dxf").dump(1);

  // 3. A single foot arrives; the JSON hide holds it but not the waiting order.
  drop_last("single-b.stl", 38, "right", "");
  ASSERT_TRUE(wait_until([&] { return all_computed(rig, {"single-b.stl"}); }, 60)) << read_text(rig.daemon_log());
  const double single_b = job_area_mm2(rig, find_job(rig, "single-b.stl").first);
  ASSERT_LT(1.7 * single_b, std::min(o100, o200));
  const double side_2 = std::sqrt(1.7 * single_b + 1200);
  write_hide_json(staging / "hide-2.json", side_2 * 1.3, side_2 / 1.3);
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
  EXPECT_NE(status.find("1 job(s) of leather waiting for a hide"), std::string::npos) << status;
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
  EXPECT_EQ(log_after.find("cutting batch " + batch_k, log_before.size()), std::string::npos) << "sent again after the restart";
  EXPECT_NE(log_before.find("cutting batch " + batch_k), std::string::npos);

  std::map<std::string, std::string> batch_of_job;
  for (const char* file : {"hide-1.dxf", "hide-2.json"}) {
    const auto batch = hide_batch(rig, file);
    const std::string id = batch.value("id", "");
    const std::string cut = read_text(rig.spool() / "batches" / id / "cut.plt");
    ASSERT_FALSE(cut.empty()) << file;
    EXPECT_EQ(count_occurrences(on_cutter_1, cut), 1) << file;
    EXPECT_EQ(count_occurrences(on_cutter_2, cut), 0) << file;
    EXPECT_EQ(batch.value("cutter", ""), "cutter-1");
    EXPECT_EQ(static_cast<int>(check_written_layout(rig, id, std::string(file) == "hide-1.dxf" ? 1 : 0)),
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
  EXPECT_EQ(hide_batch(rig, "hide-2.json")["hide"].value("id", ""), "hide-2");

  // Jobs: cut whole in done/ on exactly the hide whose batch lists them, or still waiting in work/.
  const auto done = rig.jobs("done");
  const auto work = rig.jobs("work");
  int waiting = 0;
  for (const std::string scan : {"o100-left.stl", "o100-right.stl", "o200-pair.stl", "single-b.stl"}) {
    const auto [id, folder] = find_job(rig, scan);
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
  // The pair of order 100 on one hide (or both waiting); single-b on the JSON hide; one order waits.
  EXPECT_EQ(find_job(rig, "o100-left.stl").second, find_job(rig, "o100-right.stl").second);
  EXPECT_EQ(batch_of_job[find_job(rig, "o100-left.stl").first], batch_of_job[find_job(rig, "o100-right.stl").first]);
  EXPECT_EQ(batch_of_job[find_job(rig, "single-b.stl").first], hide_batch(rig, "hide-2.json").value("id", ""));
  EXPECT_EQ(waiting, find_job(rig, "o100-left.stl").second == "work" ? 2 : 1);
  EXPECT_NE(log_after.find("waiting for a hide of leather: did not fit on hide"), std::string::npos);
}

}  // namespace
}  // namespace lastcut::daemon::testing
