// The daemon's configuration: the shipped files are valid, and every kind of mistake is
// refused with the key path and the line.
#include <gtest/gtest.h>

#include "daemon/config/config_loader.hpp"
#include "tests/support/minimal_daemon_config.hpp"
#include "daemon_harness.hpp"
#include "drivers/cutter.hpp"

namespace lastcut::daemon {
namespace {

const std::filesystem::path kSource = LASTCUT_SOURCE_DIR;

std::string minimal(const std::string& extra_cutter_keys = "", const std::string& extra_top = "") {
  return extra_top + "\n" + lastcut::testing::kMinimalDaemonConfig + extra_cutter_keys;
}

ConfigLoadResult load_text(const std::string& text) {
  // One folder per test: CTest runs the tests of this file as parallel processes.
  const auto folder =
      testing::scratch_folder(std::string("config-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  testing::write_text(folder / "lastcut.toml", text);
  return load_daemon_config(folder / "lastcut.toml");
}

TEST(DaemonConfig, ShippedExampleIsValidAndDocumentsTheDefaults) {
  const auto result = load_daemon_config(kSource / "config/lastcut.toml");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->cutters.size(), 2u);
  EXPECT_EQ(result.config->jobs.duplicate_policy, DuplicatePolicy::Skip);
  EXPECT_EQ(result.config->paths.spool_dir, "/var/spool/lastcut");
}

TEST(DaemonConfig, DemoConfigurationIsValidWithPathsFromItsFolder) {
  const auto result = load_daemon_config(kSource / "config/demo/lastcut.toml");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->paths.watch_dir, (kSource / "demo/incoming").lexically_normal());
  EXPECT_EQ(result.config->cutters.at("cutter-1").link.port, (kSource / "demo/cutter-1.tty").lexically_normal().string());
}

TEST(DaemonConfig, RelativePathsAreTakenFromTheFilesFolder) {
  const auto result = load_text(minimal());
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_TRUE(result.config->paths.spool_dir.is_absolute());
  EXPECT_EQ(result.config->paths.spool_dir.filename(), "spool");
}

TEST(DaemonConfig, UnknownKeyIsReportedWithPathAndLine) {
  const auto result = load_text(minimal("baud_rate = 9600\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.baud_rate (line 16): unknown key"), std::string::npos) << result.error;
}

TEST(DaemonConfig, UnknownTableIsReported) {
  const auto result = load_text(minimal("", "[watchh]\nmode = \"poll\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("watchh (line 1): unknown key"), std::string::npos) << result.error;
}

TEST(DaemonConfig, WrongTypesAndRangesAreRefused) {
  auto result = load_text(minimal("baud = \"fast\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.baud (line 16): must be a whole number"), std::string::npos) << result.error;
  result = load_text(minimal("timeout_s = -1\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.timeout_s (line 16): -1 is outside"), std::string::npos) << result.error;
  result = load_text(minimal("protocol = \"gerber\"\n"));
  ASSERT_FALSE(result.config);  // duplicate key: a TOML error with its line
  EXPECT_NE(result.error.find("line 16"), std::string::npos) << result.error;
}

// A strip material may name the cutter its part of a job of several materials goes to (a configured
// one); the pen draws sew lines unless [jobs] draw_sew_lines says no.
TEST(DaemonConfig, AStripMaterialsCutterAndTheSewLinesAreRead) {
  const auto shipped = load_daemon_config(kSource / "config/lastcut.toml");
  ASSERT_TRUE(shipped.config) << shipped.error;
  EXPECT_TRUE(shipped.config->jobs.draw_sew_lines);
  EXPECT_TRUE(shipped.config->materials.count("lining"));
  std::string text = minimal();
  text.replace(text.find("width_mm = 500"), 14, "width_mm = 500\ncutter = \"a\"");
  text.replace(text.find("default_cutter = \"a\""), 20, "default_cutter = \"a\"\ndraw_sew_lines = false");
  auto result = load_text(text);
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->materials.at("calf").cutter, "a");
  EXPECT_FALSE(result.config->jobs.draw_sew_lines);
  const std::string material_cutter = "width_mm = 500\ncutter = \"a\"";
  text.replace(text.find(material_cutter), material_cutter.size(), "width_mm = 500\ncutter = \"b\"");
  result = load_text(text);
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("materials.calf.cutter: \"b\" is not a [cutters.*] table"), std::string::npos) << result.error;
}

TEST(DaemonConfig, TheHoleLimitIsReadAndRangeChecked) {
  EXPECT_EQ(load_daemon_config(kSource / "config/lastcut.toml").config->jobs.max_hole_across_mm, 30.0);
  std::string text = minimal();
  text.replace(text.find("default_cutter = \"a\""), 20, "default_cutter = \"a\"\nmax_hole_across_mm = 42.5");
  auto result = load_text(text);
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->jobs.max_hole_across_mm, 42.5);
  text.replace(text.find("42.5"), 4, "-3");
  result = load_text(text);
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("jobs.max_hole_across_mm (line 9): -3 is outside"), std::string::npos) << result.error;
}

TEST(DaemonConfig, EnumerationsAndCrossReferencesAreChecked) {
  std::string text = minimal();
  text.replace(text.find("default_cutter = \"a\""), 20, "default_cutter = \"b\"");
  auto result = load_text(text);
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("jobs.default_cutter: \"b\" is not a [cutters.*] table"), std::string::npos);
  result = load_text(minimal("parity = \"X\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.parity"), std::string::npos);
}

TEST(DaemonConfig, DriverSettingsAreReadAndChecked) {
  auto result = load_text(minimal("data_bits = 7\nstop_bits = 2\nharmless_grbl_errors = [20, 22]\n"
                                  "grbl_settings = [\"$110=5000\", \"$32=0\"]\nhpgl_handshake = \"escb\"\n"
                                  "hpgl_status_queries = false\nmodbus_map = \"map.toml\"\nmodbus_unit_id = 3\n"));
  ASSERT_TRUE(result.config) << result.error;
  const CutterSection& cutter = result.config->cutters.at("a");
  EXPECT_EQ(cutter.link.data_bits, 7);
  EXPECT_EQ(cutter.link.stop_bits, 2);
  EXPECT_EQ(cutter.link.harmless_grbl_errors, (std::vector<int>{20, 22}));
  EXPECT_EQ(cutter.link.grbl_settings, (std::vector<std::string>{"$110=5000", "$32=0"}));
  EXPECT_EQ(cutter.link.hpgl_handshake, "escb");
  EXPECT_FALSE(cutter.link.hpgl_status_queries);
  EXPECT_EQ(std::filesystem::path(cutter.link.modbus_map).filename(), "map.toml");
  EXPECT_TRUE(std::filesystem::path(cutter.link.modbus_map).is_absolute()) << "taken from the file's folder";
  EXPECT_EQ(cutter.link.modbus_unit_id, 3);

  result = load_text(minimal("stop_bits = 3\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.stop_bits (line 16): 3 is outside"), std::string::npos) << result.error;
  result = load_text(minimal("harmless_grbl_errors = [\"20\"]\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.harmless_grbl_errors"), std::string::npos) << result.error;
  result = load_text(minimal("grbl_settings = [\"G0X10\"]\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("is not a grbl setting line"), std::string::npos) << result.error;
  result = load_text(minimal("hpgl_handshake = \"dtr\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.hpgl_handshake"), std::string::npos) << result.error;
  result = load_text(minimal("hpgl_status_queries = \"yes\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("must be true or false"), std::string::npos) << result.error;
}

TEST(DaemonConfig, GrblStreamingKeysReachTheDriver) {
  auto result = load_text(minimal("grbl_streaming = \"send-wait\"\ngrbl_rx_buffer_bytes = 1024\nstatus_poll_s = 0.5\n"
                                  "parity = \"E\"\n"));
  ASSERT_TRUE(result.config) << result.error;
  // What the dispatcher hands to the driver: the section's settings plus the job's name and id.
  const drivers::CutterConfig driver{result.config->cutters.at("a").link, "a", "B1"};
  EXPECT_EQ(driver.grbl_streaming, "send-wait");
  EXPECT_EQ(driver.grbl_rx_buffer_bytes, 1024);
  EXPECT_EQ(driver.status_poll_s, 0.5);
  EXPECT_EQ(driver.parity, 'E');

  result = load_text(minimal("grbl_streaming = \"fast\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.grbl_streaming (line 16): \"fast\" is not one of counting, send-wait"),
            std::string::npos)
      << result.error;
  result = load_text(minimal("grbl_rx_buffer_bytes = -1\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.grbl_rx_buffer_bytes (line 16): -1 is outside 0 .. 65536"), std::string::npos)
      << result.error;
  result = load_text(minimal("status_poll_s = 0\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a.status_poll_s (line 16): 0 is outside 0.01 .. 60"), std::string::npos)
      << result.error;
  result = load_text(minimal("parity = \"X\"\n"));
  EXPECT_NE(result.error.find("cutters.a.parity (line 16): \"X\" is not one of N, E, O"), std::string::npos)
      << result.error;
}

TEST(DaemonConfig, ReviewToleranceIsReadCheckedAndDefaultsToTwoMillimetres) {
  EXPECT_EQ(load_daemon_config(kSource / "config/lastcut.toml").config->review.corner_tolerance_mm, 2.0);
  auto result = load_text(minimal("", "[review]\ncorner_tolerance_mm = 0.5\n"));
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->review.corner_tolerance_mm, 0.5);
  EXPECT_EQ(load_text(minimal()).config->review.corner_tolerance_mm, 2.0);
  result = load_text(minimal("", "[review]\ncorner_tolerance = 1.0\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("review.corner_tolerance (line 2): unknown key"), std::string::npos) << result.error;
  result = load_text(minimal("", "[review]\ncorner_tolerance_mm = -1\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("review.corner_tolerance_mm"), std::string::npos) << result.error;
}

TEST(DaemonConfig, QualityLimitsAreReadCheckedAndTheShippedOnesAreTheDefaults) {
  const MoldQualityLimits defaults;
  const MoldQualityLimits shipped = load_daemon_config(kSource / "config/lastcut.toml").config->quality;
  EXPECT_EQ(shipped.max_D_angle, defaults.max_D_angle);
  EXPECT_EQ(shipped.max_D_area, defaults.max_D_area);
  EXPECT_EQ(shipped.max_stretch, defaults.max_stretch);
  EXPECT_EQ(shipped.max_p95_stretch, defaults.max_p95_stretch);
  EXPECT_EQ(shipped.require_converged, defaults.require_converged);
  EXPECT_EQ(shipped.max_length_excess_pct, defaults.max_length_excess_pct);
  auto result = load_text(minimal("", "[quality]\nmax_d_angle = 3\nrequire_converged = false\n"));
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_EQ(result.config->quality.max_D_angle, 3.0);
  EXPECT_FALSE(result.config->quality.require_converged);
  result = load_text(minimal("", "[quality]\nmax_dangle = 3\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("quality.max_dangle (line 2): unknown key"), std::string::npos) << result.error;
  result = load_text(minimal("", "[quality]\nmax_d_area = 1.5\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("quality.max_d_area (line 2): 1.5 is outside 2 .. 10"), std::string::npos) << result.error;
  result = load_text(minimal("", "[quality]\nrequire_converged = \"yes\"\n"));
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("quality.require_converged (line 2): must be true or false"), std::string::npos)
      << result.error;
}

TEST(DaemonConfig, ShippedExampleListsEveryCutterKey) {
  // config/lastcut.toml documents every key; the option table is what the reader accepts.
  const std::string text = testing::read_text(kSource / "config/lastcut.toml");
  const std::string guide = testing::read_text(kSource / "docs/daemon.md");
  for (const drivers::CutterOption& option : drivers::cutter_options()) {
    const std::string key(option.key);
    EXPECT_NE(text.find("\n" + key + " = "), std::string::npos) << key << " missing from config/lastcut.toml";
    EXPECT_NE(guide.find("`" + key + "`"), std::string::npos) << key << " missing from docs/daemon.md";
  }
}

TEST(DaemonConfig, OnlyLoopbackNetworkCuttersAreAccepted) {
  std::string text = minimal();
  text.replace(text.find("/dev/ttyUSB0"), 12, "tcp://10.0.0.5:23");
  const auto result = load_text(text);
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("127.0.0.1"), std::string::npos) << result.error;
}

TEST(DaemonConfig, MissingRequiredKeysAreNamed) {
  const auto result = load_text("[paths]\nwatch = \"in\"\n");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("paths.spool: missing (required)"), std::string::npos) << result.error;
  EXPECT_NE(result.error.find("jobs: missing table"), std::string::npos) << result.error;
}

TEST(DaemonConfig, SyntaxErrorGivesTheLine) {
  const auto result = load_text("[paths\nwatch = 1\n");
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("line 1"), std::string::npos) << result.error;
}

}  // namespace
}  // namespace lastcut::daemon

namespace lastcut::daemon {
namespace {

// [paths] hides and [materials.X] kind = "hide" (docs/hides.md): read, and every mistake refused.
TEST(DaemonConfig, HideMaterialsAndTheHidesFolder) {
  const std::string hide_material = "[materials.leather]\nkind = \"hide\"\ncutter = \"a\"\npairs = \"any\"\nmin_quality = 2\n";
  std::string text = minimal(hide_material);
  text.replace(text.find("machines = \"machines\"\n"), 22, "machines = \"machines\"\nhides = \"hides\"\nhide_stock = \"stock\"\n");
  auto result = load_text(text);
  ASSERT_TRUE(result.config) << result.error;
  const MaterialConfig& leather = result.config->materials.at("leather");
  EXPECT_EQ(leather.kind, MaterialKind::Hide);
  EXPECT_EQ(leather.cutter, "a");
  EXPECT_FALSE(leather.pairs_same_hide);
  EXPECT_EQ(leather.min_quality, 2);
  EXPECT_EQ(leather.toe_min_quality, 0) << "the toe rule is off unless asked for";
  EXPECT_DOUBLE_EQ(leather.toe_fraction, 0.4);
  EXPECT_DOUBLE_EQ(leather.grain_tolerance_deg, 0);
  EXPECT_TRUE(leather.mirror_pairs) << "pairs mirrored about the backbone unless asked not to";
  EXPECT_EQ(result.config->materials.at("calf").kind, MaterialKind::Strip);
  EXPECT_EQ(result.config->paths.hides_dir.filename(), "hides");
  EXPECT_TRUE(result.config->paths.hides_dir.is_absolute());
  EXPECT_EQ(result.config->paths.hide_stock_dir.filename(), "stock");

  const auto refused = [&](const std::string& config_text, const std::string& expected) {
    const auto loaded = load_text(config_text);
    ASSERT_FALSE(loaded.config) << expected;
    EXPECT_NE(loaded.error.find(expected), std::string::npos) << loaded.error;
  };
  refused(minimal(hide_material), "materials.leather: kind = \"hide\" needs paths.hides");
  std::string with_size = text;
  with_size.replace(with_size.find("kind = \"hide\"\n"), 14, "kind = \"hide\"\nwidth_mm = 800\n");
  refused(with_size, "materials.leather.width_mm (line");
  std::string bad_pairs = text;
  bad_pairs.replace(bad_pairs.find("pairs = \"any\""), 13, "pairs = \"both\"");
  refused(bad_pairs, "materials.leather.pairs: \"both\" is not same_hide or any");
  std::string bad_kind = text;
  bad_kind.replace(bad_kind.find("kind = \"hide\""), 13, "kind = \"roll\"");
  refused(bad_kind, "materials.leather.kind: \"roll\" is not strip or hide");
  std::string bad_cutter = text;
  bad_cutter.replace(bad_cutter.find("cutter = \"a\"\npairs"), 12, "cutter = \"z\"");
  refused(bad_cutter, "materials.leather.cutter: \"z\" is not a [cutters.*] table");
  std::string strip_pairs = text;
  strip_pairs.replace(strip_pairs.find("length_mm = 900\n"), 16, "length_mm = 900\npairs = \"any\"\n");
  refused(strip_pairs, "materials.calf.pairs (line");
  std::string same_folder = text;
  same_folder.replace(same_folder.find("hides = \"hides\""), 15, "hides = \"in\"");
  refused(same_folder, "paths.hides: must be a folder of its own");
  std::string leather_rules = text;
  leather_rules.replace(leather_rules.find("min_quality = 2\n"), 16,
                        "min_quality = 2\ntoe_min_quality = 3\ntoe_fraction = 0.3\ngrain_tolerance_deg = 15\n"
                        "mirror_pairs = false\n");
  const auto with_rules = load_text(leather_rules);
  ASSERT_TRUE(with_rules.config) << with_rules.error;
  EXPECT_EQ(with_rules.config->materials.at("leather").toe_min_quality, 3);
  EXPECT_DOUBLE_EQ(with_rules.config->materials.at("leather").toe_fraction, 0.3);
  EXPECT_DOUBLE_EQ(with_rules.config->materials.at("leather").grain_tolerance_deg, 15);
  EXPECT_FALSE(with_rules.config->materials.at("leather").mirror_pairs);
  std::string bad_grain = text;
  bad_grain.replace(bad_grain.find("min_quality = 2\n"), 16, "min_quality = 2\ngrain_tolerance_deg = 120\n");
  refused(bad_grain, "materials.leather.grain_tolerance_deg");
  std::string strip_toe = text;
  strip_toe.replace(strip_toe.find("length_mm = 900\n"), 16, "length_mm = 900\ntoe_min_quality = 3\n");
  refused(strip_toe, "materials.calf.toe_min_quality (line");
  std::string strip_mirror = text;
  strip_mirror.replace(strip_mirror.find("length_mm = 900\n"), 16, "length_mm = 900\nmirror_pairs = true\n");
  refused(strip_mirror, "materials.calf.mirror_pairs (line");
}

}  // namespace
}  // namespace lastcut::daemon
