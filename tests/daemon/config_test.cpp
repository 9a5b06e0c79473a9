// The daemon's configuration: the shipped files are valid, and every kind of mistake is
// refused with the key path and the line.
#include <gtest/gtest.h>

#include "daemon/config/config_loader.hpp"
#include "daemon_harness.hpp"

namespace lastcut::daemon {
namespace {

const std::filesystem::path kSource = LASTCUT_SOURCE_DIR;

std::string minimal(const std::string& extra_cutter_keys = "", const std::string& extra_top = "") {
  return extra_top + R"(
[paths]
watch = "in"
spool = "spool"
machines = "machines"
[jobs]
default_material = "calf"
default_cutter = "a"
[materials.calf]
width_mm = 500
length_mm = 900
[cutters.a]
protocol = "grbl"
port = "/dev/ttyUSB0"
machine = "grbl-drag-knife"
)" + extra_cutter_keys;
}

ConfigLoadResult load_text(const std::string& text) {
  const auto folder = testing::scratch_folder("config");
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
  EXPECT_EQ(result.config->cutters.at("cutter-1").port, (kSource / "demo/cutter-1.tty").lexically_normal().string());
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
