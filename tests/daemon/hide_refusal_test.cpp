// Bad hide files dropped into a running lastcutd's hides folder (docs/hides.md): each one ends in
// failed/<batch>/ with its file and batch.json giving the one-line reason, the log says so in one
// line, and the daemon keeps running and taking hides. Runs under the sanitizers in CI.
#include <gtest/gtest.h>

#include "daemon_rig.hpp"
#include "engine/core/dxf_document.hpp"

namespace lastcut::daemon::testing {
namespace {

std::string hide_dxf(const std::vector<std::pair<std::string, std::vector<Point2>>>& rings, bool closed = true) {
  DxfDocument dxf(DxfVersion::R12, {{"HIDE", 7}, {"HOLE", 1}, {"ZONE_1", 3}});
  for (const auto& [layer, points] : rings) dxf.polyline(layer, points, closed);
  return dxf.str();
}

std::vector<Point2> rectangle(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

// failed/ entries by hide file name -> reason.
std::map<std::string, std::string> failed_hides(const DaemonRig& rig) {
  std::map<std::string, std::string> result;
  std::error_code error;
  for (std::filesystem::directory_iterator it(rig.spool() / "failed", error), end; !error && it != end;
       it.increment(error)) {
    const auto batch = nlohmann::json::parse(read_text(it->path() / "batch.json"), nullptr, false);
    if (batch.is_discarded() || !batch.contains("hide")) continue;
    const std::string file = batch["hide"].value("file", "");
    EXPECT_TRUE(std::filesystem::exists(it->path() / file)) << "the hide file is kept in " << it->path();
    result[file] = batch.value("reason", "");
  }
  return result;
}

TEST(DaemonHides, BadHideFilesGoToFailedWithTheReasonAndTheDaemonKeepsRunning) {
  RigOptions options;
  options.extra_paths = "hides = \"hides\"\nhide_stock = \"stock\"\n";
  options.extra_config = "[materials.leather]\nkind = \"hide\"\n";
  DaemonRig rig("hides-refused", options);
  const auto hides = rig.root() / "hides";
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  rig.start_daemon();

  const std::map<std::string, std::string> files = {
      {"open.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}}, false)},
      {"bowtie.dxf", hide_dxf({{"HIDE", {{0, 0}, {1000, 600}, {1000, 0}, {0, 600}}}})},
      {"zone-out.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}, {"ZONE_1", rectangle(900, 500, 1100, 700)}})},
      {"hole-out.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}, {"HOLE", rectangle(-10, 100, 10, 200)}})},
      {"no-outline.dxf", hide_dxf({{"HOLE", rectangle(0, 0, 1000, 600)}})},
      {"tiny.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 100, 100)}})},
      {"garbage.dxf", "not\na drawing\nat all\n"},
      {"units.json", R"({"units": "furlong", "shape": [[0,0],[1000,0],[1000,600],[0,600]]})"},
      {"cut-off.json", R"({"bins": [{"id": 0, "shape": )"},
      {"no-cutter.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}})},
  };
  write_text(hides / "no-cutter.toml", "cutter = \"cutter-9\"\n");
  for (const auto& [name, text] : files) {
    write_text(staging / name, text);
    drop(staging / name, hides, name);
  }
  // The DXF units: written by hand, DxfDocument always writes mm.
  std::string inches = hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}});
  inches.replace(inches.find("$INSUNITS\n70\n4\n"), std::string("$INSUNITS\n70\n4\n").size(), "$INSUNITS\n70\n2\n");
  write_text(staging / "feet.dxf", inches);
  drop(staging / "feet.dxf", hides, "feet.dxf");

  ASSERT_TRUE(wait_until([&] { return failed_hides(rig).size() == files.size() + 1; }, 30))
      << read_text(rig.daemon_log());
  const auto failed = failed_hides(rig);
  const auto reason = [&](const std::string& file) {
    const std::string text = failed.at(file);
    EXPECT_EQ(text.find('\n'), std::string::npos) << text;
    return text;
  };
  const auto ends_with = [](const std::string& text, const std::string& tail) {
    return text.size() >= tail.size() && text.compare(text.size() - tail.size(), tail.size(), tail) == 0;
  };
  EXPECT_TRUE(ends_with(reason("open.dxf"), "open.dxf: the hide outline on layer HIDE is open; close it in the drawing program"))
      << reason("open.dxf");
  EXPECT_TRUE(ends_with(reason("bowtie.dxf"), "bowtie.dxf: the hide outline crosses itself; redraw it as one simple closed line"));
  EXPECT_TRUE(ends_with(reason("zone-out.dxf"),
                        "zone-out.dxf: the zone 1 (grade 1) reaches outside the hide outline (30000 mm^2 outside)"))
      << reason("zone-out.dxf");
  EXPECT_TRUE(ends_with(reason("hole-out.dxf"), "hole-out.dxf: the hole 1 reaches outside the hide outline (1000 mm^2 outside)"))
      << reason("hole-out.dxf");
  EXPECT_TRUE(ends_with(reason("no-outline.dxf"), "no-outline.dxf: no hide outline (a closed polyline on layer HIDE)"));
  EXPECT_TRUE(ends_with(reason("tiny.dxf"),
                        "tiny.dxf: the hide outline encloses 0.01 m^2, outside 0.05..10 m^2; check the drawing's units"))
      << reason("tiny.dxf");
  EXPECT_TRUE(ends_with(reason("garbage.dxf"), "garbage.dxf is not a DXF file: line 1 is not a group code"));
  EXPECT_TRUE(ends_with(reason("units.json"), "units.json: units \"furlong\" are not supported; use mm, cm, m or in"));
  EXPECT_NE(reason("cut-off.json").find("cut-off.json is not valid JSON"), std::string::npos) << reason("cut-off.json");
  EXPECT_TRUE(ends_with(reason("feet.dxf"),
                        "feet.dxf: drawing units $INSUNITS 2 are not supported; save the hide in mm, cm, m or inches"))
      << reason("feet.dxf");
  EXPECT_EQ(reason("no-cutter.dxf"), "hide no-cutter: cutter \"cutter-9\" is not configured");

  // Still running: it answers `lastcut status`, and a good hide after the bad ones is taken (no
  // piece waits, so it lies on its cutter's table waiting for work: daemon/station/hide_policy.hpp). This one comes from the stock of
  // digitized hides through `lastcut hide load`, which refuses what it cannot do with one line.
  ASSERT_TRUE(rig.daemon()->running());
  const auto stock = rig.root() / "stock";
  std::filesystem::create_directories(stock);
  write_text(stock / "good.dxf", hide_dxf({{"HIDE", rectangle(0, 0, 1000, 600)}}));
  write_text(stock / "good.toml", "material = \"leather\"\nthickness_mm = 1.6\n");
  write_text(stock / "open.dxf", files.at("open.dxf"));
  const auto load = [&](const std::string& id, const std::string& cutter) {
    const auto log_file = rig.root() / ("load-" + id + ".txt");
    const int code = run_command({binary("lastcut").string(), "hide", "load", id, "--cutter", cutter, "-c",
                                  rig.config_file().string()}, log_file);
    return std::make_pair(code, read_text(log_file));
  };
  EXPECT_EQ(load("good", "cutter-9"), std::make_pair(1, std::string("lastcut hide load: cutter \"cutter-9\" is not configured\n")));
  EXPECT_EQ(load("missing", "cutter-1"),
            std::make_pair(1, "lastcut hide load: no hide missing (.dxf or .json) in the stock folder " + stock.string() + "\n"));
  EXPECT_EQ(load("open", "cutter-1"),
            std::make_pair(1, "lastcut hide load: " + (stock / "open.dxf").string() +
                                  ": the hide outline on layer HIDE is open; close it in the drawing program\n"));
  const auto loaded = load("good", "cutter-1");
  EXPECT_EQ(loaded.first, 0) << loaded.second;
  EXPECT_NE(loaded.second.find("hide good (good.dxf, 0.60 m^2) now lies on cutter cutter-1"), std::string::npos) << loaded.second;
  const auto status_log = rig.root() / "status.txt";
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("good.dxf, 0.60 m^2, lies on cutter "
                                                                        "cutter-1; the computed") != std::string::npos; }, 30))
      << read_text(rig.daemon_log());
  EXPECT_EQ(run_command({binary("lastcut").string(), "status", "--config", rig.config_file().string()}, status_log), 0);
  EXPECT_NE(read_text(status_log).find("lastcutd: running"), std::string::npos);
  const std::string log = read_text(rig.daemon_log());
  EXPECT_NE(log.find("hide file open.dxf: "), std::string::npos);
  EXPECT_NE(log.find("; moved to failed/"), std::string::npos);
  EXPECT_NE(log.find(": good.dxf, 0.60 m^2, lies on cutter cutter-1"), std::string::npos) << log;
  EXPECT_TRUE(std::filesystem::exists(stock / "good.dxf")) << "the stock copy stays";
  EXPECT_EQ(rig.stop_daemon(), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
