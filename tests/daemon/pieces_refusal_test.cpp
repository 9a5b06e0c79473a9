// Bad pattern sets and bad style sidecars dropped into a running lastcutd (issue 35): each pattern
// set the reader refuses fails its job with the reader's one line, the file kept in failed/; a style
// name that is a path is refused at intake; a style the shop does not have, a broken style folder and
// a style that does not fit the scan hold their job with one line; the daemon keeps running, cuts a
// pattern set of two configured materials dropped among them in two parts, one per material, and a good
// pattern set dropped after them. Runs under the sanitizers in CI.
#include <gtest/gtest.h>

#include "daemon_rig.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/pattern/aama_test_files.hpp"

namespace lastcut::daemon::testing {
namespace {

using lastcut::test::HandDxf;
using lastcut::test::one_piece_file;
using lastcut::test::square;

PatternPiece square_piece(const std::string& name, const std::string& category) {
  PatternPiece piece;
  piece.name = name;
  piece.category = category;
  piece.cut_line_mm = square(120.0);
  return piece;
}

TEST(DaemonPieces, BadPatternSetsAndStylesAreRefusedOrHeldWithOneLine) {
  const auto styles = scratch_folder("pieces-refused-styles");
  std::filesystem::copy(std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby", styles / "derby");
  std::filesystem::copy(std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby", styles / "broken");
  write_text(styles / "broken" / "style.toml", read_text(styles / "broken" / "style.toml") + "colour = \"red\"\n");
  std::filesystem::copy(std::filesystem::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "derby", styles / "far");
  std::string far = read_text(styles / "far" / "style.toml");  // the vamp's label 60 mm above the last
  far.replace(far.find("label = [239.45, 4.98, 38.27]"), 29, "label = [239.45, 4.98, 98.27]");
  write_text(styles / "far" / "style.toml", far);

  RigOptions options;
  options.extra_paths = "styles = \"" + styles.string() + "\"\n";
  options.extra_config = "[materials.lining]\nwidth_mm = 800\nlength_mm = 1200\nspacing_mm = 2\n";
  DaemonRig rig("pieces-refused", options);
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  rig.start_cutters();
  rig.start_daemon();

  const auto closed = [](HandDxf& d) { d.polyline("1", square(100.0), true); };
  const std::map<std::string, std::string> patterns = {
      {"open.dxf", one_piece_file(4, [](HandDxf& d) { d.polyline("1", square(100.0), false); })},
      {"no-blocks.dxf", HandDxf().header(4).section("ENTITIES").polyline("1", square(100.0), true).end_section().eof().str()},
      {"furlong.dxf", one_piece_file(0, [&](HandDxf& d) { closed(d); d.text("1", "Units: FURLONG"); })},
      {"two.dxf", one_piece_file(4, [&](HandDxf& d) { closed(d); d.text("1", "Quantity: two"); })},
  };
  for (const auto& [name, text] : patterns) {
    write_text(staging / name, text);
    drop(staging / name, rig.watch(), name);
  }
  write_aama_dxf(staging / "mixed.dxf", {square_piece("vamp", "calf"), square_piece("lining", "lining")});
  drop(staging / "mixed.dxf", rig.watch(), "mixed.dxf");
  const std::map<std::string, std::string> styled = {
      {"path.stl", "style = \"../derby\"\n"}, {"oxford.stl", "style = \"oxford\"\n"},
      {"broken.stl", "style = \"broken\"\n"}, {"far.stl", "style = \"far\"\nside = \"right\"\n"}};
  for (const auto& [name, sidecar] : styled) {
    write_variant(small_last(40, "right", 7), staging / name, name);
    write_text(rig.watch() / (std::filesystem::path(name).stem().string() + ".job.toml"), sidecar);
    drop(staging / name, rig.watch(), name);
  }
  const auto settled = [&](const std::string& file) {
    const std::string folder = rig.find_job(file).folder;
    return folder == "failed" || folder == "held" || folder == "done";
  };
  ASSERT_TRUE(wait_until([&] {
    for (const auto& entry : patterns) if (!settled(entry.first)) return false;
    for (const auto& entry : styled) if (!settled(entry.first)) return false;
    return settled("mixed.dxf");
  }, 120)) << read_text(rig.daemon_log());

  const std::map<std::string, std::pair<std::string, std::string>> expected = {
      {"open.dxf", {"failed", "open.dxf: piece \"vamp\": its cut line on layer 1 is open"}},
      {"no-blocks.dxf", {"failed", "no-blocks.dxf: no piece blocks (DXF-AAMA places each piece as a BLOCK with an INSERT)"}},
      {"furlong.dxf", {"failed", "furlong.dxf: unknown units \"Units: FURLONG\" (METRIC, MM, CM, ENGLISH or INCH)"}},
      {"two.dxf", {"failed", "two.dxf: piece \"vamp\": quantity 'two' is not a positive count"}},
      {"path.stl", {"failed", "sidecar path.job.toml: style \"../derby\" is not a style's folder name (letters, digits, '-', '_', '.'; no path)"}},
      {"oxford.stl", {"held", "style \"oxford\": no such style in " + styles.string()}},
      {"broken.stl", {"held", "style \"broken\": "}},
      {"far.stl", {"held", "style \"far\" does not fit this last: the label of piece vamp is not on the reference last's upper"}},
  };
  for (const auto& [file, outcome] : expected) {
    const DaemonRig::FoundJob job = rig.find_job(file);
    const nlohmann::json& state = job.state;
    const std::string& folder = job.folder;
    EXPECT_EQ(folder, outcome.first) << file;
    const std::string reason = state.value("reason", "");
    EXPECT_EQ(reason.find('\n'), std::string::npos) << reason;
    EXPECT_EQ(reason.rfind(outcome.second, 0), 0u) << file << ": " << reason;
    EXPECT_TRUE(std::filesystem::exists(rig.spool() / folder / state.value("id", "") / file)) << file << " is kept";
  }
  EXPECT_NE(rig.find_job("broken.stl").state.value("reason", "").find("colour"), std::string::npos);

  // Two materials, two parts: the calf vamp and the lining, each nested and cut on its own material;
  // the job is done once both are cut.
  const DaemonRig::FoundJob mixed = rig.find_job("mixed.dxf");
  ASSERT_EQ(mixed.folder, "done") << read_text(rig.daemon_log());
  ASSERT_EQ(mixed.state["parts"].size(), 2u) << mixed.state.dump();
  EXPECT_EQ(mixed.state["parts"][0].value("material", ""), "calf");
  EXPECT_EQ(mixed.state["parts"][1].value("material", ""), "lining");
  const auto report = nlohmann::json::parse(read_text(rig.spool() / "done" / mixed.id / "report.json"));
  ASSERT_EQ(report["parts_cut"].size(), 2u) << report.dump();
  EXPECT_EQ(report["parts_cut"][0].value("material", ""), "calf");
  EXPECT_EQ(report["parts_cut"][1].value("material", ""), "lining");
  EXPECT_NE(report["parts_cut"][0].value("batch", ""), report["parts_cut"][1].value("batch", ""));
  for (const auto& part : report["parts_cut"]) {
    const auto batch = nlohmann::json::parse(read_text(rig.spool() / "batches" / part.value("batch", "") / "batch.json"));
    EXPECT_EQ(batch.value("material", ""), part.value("material", ""));
    EXPECT_EQ(batch.value("stage", ""), "cut");
    EXPECT_EQ(batch.value("pieces", 0), 1);
  }

  // Still running: a good pattern set is cut.
  write_aama_dxf(staging / "good.dxf", {square_piece("vamp", "calf")});
  drop(staging / "good.dxf", rig.watch(), "good.dxf");
  EXPECT_TRUE(wait_until([&] { return rig.find_job("good.dxf").folder == "done"; }, 60)) << read_text(rig.daemon_log());
  EXPECT_EQ(rig.stop_daemon(), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
