// [status]: the broker URL, the table's keys (refused in one line naming key and line), the
// topic names and payloads of the live status. No network here; mqtt_status_test.cpp has the broker.
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>

#include "daemon/config/config_loader.hpp"
#include "tests/support/minimal_daemon_config.hpp"
#include "daemon/config/mqtt_url.hpp"
#include "daemon/status/status_topics.hpp"

namespace lastcut::daemon {
namespace {

// A valid configuration of 14 lines; a [status] table appended starts on line 15.
const std::string kBase = lastcut::testing::kMinimalDaemonConfig;

ConfigLoadResult load_with(const std::string& extra) {
  const auto folder = std::filesystem::path(LASTCUT_BINARY_DIR) / "test-scratch" /
                      (std::string("status-config-") + ::testing::UnitTest::GetInstance()->current_test_info()->name());
  std::filesystem::create_directories(folder);
  std::ofstream(folder / "lastcut.toml") << kBase << extra;
  return load_daemon_config(folder / "lastcut.toml");
}

int lines_of(const std::string& text) { return static_cast<int>(std::count(text.begin(), text.end(), '\n')); }

TEST(StatusUrl, HostAndPortAndSchemeAreRead) {
  std::string why;
  auto plain = parse_mqtt_url("mqtt://broker.shop", why);
  ASSERT_TRUE(plain) << why;
  EXPECT_EQ(plain->host, "broker.shop");
  EXPECT_EQ(plain->port, 1883);
  EXPECT_FALSE(plain->tls);
  auto secure = parse_mqtt_url("mqtts://10.0.0.7", why);
  ASSERT_TRUE(secure) << why;
  EXPECT_EQ(secure->port, 8883);
  EXPECT_TRUE(secure->tls);
  auto v6 = parse_mqtt_url("mqtt://[::1]:1884", why);
  ASSERT_TRUE(v6) << why;
  EXPECT_EQ(v6->host, "::1");
  EXPECT_EQ(v6->port, 1884);
  auto highest = parse_mqtt_url("mqtt://h:65535", why);
  ASSERT_TRUE(highest) << why;
  EXPECT_EQ(highest->port, 65535);
}

TEST(StatusUrl, AnythingElseIsRefusedWithAReason) {
  for (const char* bad : {"http://h:1883", "tcp://h", "mqtt://", "mqtt://h:0", "mqtt://h:65536", "mqtt://h:12a",
                          "mqtt://h:", "mqtt://h/topic", "mqtt://user@h", "mqtt://[::1", "mqtt://[::1]x",
                          "mqtt://h st:1883", "broker:1883", ""}) {
    std::string why;
    EXPECT_FALSE(parse_mqtt_url(bad, why)) << bad;
    EXPECT_FALSE(why.empty()) << bad;
  }
}

TEST(StatusConfig, NoTableMeansNoMqtt) {
  const auto result = load_with("");
  ASSERT_TRUE(result.config) << result.error;
  EXPECT_FALSE(result.config->status.enabled);
}

TEST(StatusConfig, KeysAreReadAndTheStationDefaultsToTheHostName) {
  auto result = load_with("[status]\nmqtt_url = \"mqtt://127.0.0.1:1999\"\n");
  ASSERT_TRUE(result.config) << result.error;
  const StatusConfig& status = result.config->status;
  EXPECT_TRUE(status.enabled);
  EXPECT_EQ(status.host, "127.0.0.1");
  EXPECT_EQ(status.port, 1999);
  char host[256] = {};
  ASSERT_EQ(::gethostname(host, sizeof host - 1), 0);
  EXPECT_EQ(status.station, host);
  EXPECT_EQ(status.topic_prefix, "lastcut");

  result = load_with("[status]\nmqtt_url = \"mqtts://broker\"\nstation = \"room-2\"\ntopic_prefix = \"shop/lastcut\"\n"
                     "username = \"u\"\npassword = \"p\"\nca_file = \"ca.pem\"\nkeepalive_s = 30\nqueue_limit = 50\n");
  ASSERT_TRUE(result.config) << result.error;
  const StatusConfig& full = result.config->status;
  EXPECT_TRUE(full.tls);
  EXPECT_EQ(full.port, 8883);
  EXPECT_EQ(full.station, "room-2");
  EXPECT_EQ(full.topic_prefix, "shop/lastcut");
  EXPECT_EQ(full.username, "u");
  EXPECT_EQ(full.password, "p");
  EXPECT_TRUE(std::filesystem::path(full.ca_file).is_absolute()) << "taken from the file's folder";
  EXPECT_EQ(full.keepalive_s, 30);
  EXPECT_EQ(full.queue_limit, 50);
}

TEST(StatusConfig, MistakesAreRefusedInOneLineEach) {
  const int table_line = lines_of(kBase) + 1;
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"[status]\nmqtt_url = \"http://broker\"\n", "status.mqtt_url: \"http://broker\" must start with mqtt://"},
      {"[status]\nmqtt_url = \"mqtt://b\"\ncolour = \"red\"\n",
       "status.colour (line " + std::to_string(table_line + 2) + "): unknown key"},
      {"[status]\nstation = \"x\"\n", "status.mqtt_url: missing (required)"},
      {"[status]\nmqtt_url = \"mqtt://b\"\nstation = \"room/2\"\n", "status.station: \"room/2\" must not contain"},
      {"[status]\nmqtt_url = \"mqtt://b\"\ntopic_prefix = \"a/#\"\n", "status.topic_prefix"},
      {"[status]\nmqtt_url = \"mqtt://b\"\nca_file = \"ca.pem\"\n", "status.ca_file: only used with an mqtts:// URL"},
      {"[status]\nmqtt_url = \"mqtt://b\"\nkeepalive_s = 1\n",
       "status.keepalive_s (line " + std::to_string(table_line + 2) + "): 1 is outside 5 .. 3600"},
  };
  for (const auto& [extra, expected] : cases) {
    const auto result = load_with(extra);
    ASSERT_FALSE(result.config) << extra;
    EXPECT_NE(result.error.find(expected), std::string::npos) << result.error;
    EXPECT_EQ(result.error.find('\n'), std::string::npos) << "one line: " << result.error;
  }
}

TEST(StatusConfig, CutterNamesMustBeTopicLevels) {
  std::string text = "[cutters.\"a+b\"]\nprotocol = \"grbl\"\nport = \"/dev/ttyUSB1\"\nmachine = \"m\"\n"
                     "[status]\nmqtt_url = \"mqtt://b\"\n";
  const auto result = load_with(text);
  ASSERT_FALSE(result.config);
  EXPECT_NE(result.error.find("cutters.a+b: a cutter name in MQTT topics must not contain"), std::string::npos)
      << result.error;
}

TEST(StatusTopics, NamesFollowThePrefix) {
  const StatusTopics topics("shop/lastcut");
  EXPECT_EQ(topics.station_online("room-2"), "shop/lastcut/station/room-2/online");
  EXPECT_EQ(topics.cutter_state("c1"), "shop/lastcut/cutter/c1/state");
  EXPECT_EQ(topics.cutter_batch("c1"), "shop/lastcut/cutter/c1/batch");
  EXPECT_EQ(topics.cutter_progress("c1"), "shop/lastcut/cutter/c1/progress");
  EXPECT_EQ(topics.job_event("20261125-070000-001"), "shop/lastcut/job/20261125-070000-001/event");
}

TEST(StatusTopics, ProgressCountsLinesWhenTheDriverDoesElseBytes) {
  CutterStatus grbl{"c1", "sending", "B1", "", 37, 120, 5000, 9000};
  auto payload = cutter_progress_payload(grbl, "t");
  EXPECT_EQ(payload["percent"], 37 * 100 / 120);  // 30: lines, not bytes (55)
  EXPECT_EQ(payload["lines_sent"], 37);
  EXPECT_EQ(payload["batch"], "B1");
  CutterStatus hpgl{"c2", "sending", "B2", "", 0, 0, 999, 1000};
  EXPECT_EQ(cutter_progress_payload(hpgl, "t")["percent"], 99);  // rounded down: not done before it is
  EXPECT_EQ(cutter_progress_payload(CutterStatus{"c3"}, "t")["percent"], 0);
}

TEST(StatusTopics, AJobEventCarriesTheLastStepOfTheHistory) {
  JobState state;
  state.id = "J1";
  state.scan_name = "last.stl";
  state.ticket.order = "4711";
  state.ticket.cutter = "c1";
  state.advance(JobStage::Claimed, "taken from the watch folder");
  state.advance(JobStage::Held, "cutter c1 stopped");
  state.reason = "cutter c1 stopped";
  const auto event = job_event_payload(job_event_of(state), "room-2");
  EXPECT_EQ(event["job"], "J1");
  EXPECT_EQ(event["stage"], "held");
  EXPECT_EQ(event["note"], "cutter c1 stopped");
  EXPECT_EQ(event["reason"], "cutter c1 stopped");
  EXPECT_EQ(event["order"], "4711");
  EXPECT_EQ(event["station"], "room-2");
  EXPECT_EQ(event["at"], state.history.back()["at"]);
}

}  // namespace
}  // namespace lastcut::daemon
