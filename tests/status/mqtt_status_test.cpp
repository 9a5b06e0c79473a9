// lastcutd's live status with a real mosquitto broker (tests/support/mosquitto_broker.hpp), the
// real lastcutd and a simulated grbl table on a pty (tests/daemon/daemon_rig.hpp). The spool is
// the independent truth: every job's event sequence must equal its state.json history, and the
// cutter's progress must match what the simulated table received.
#include <gtest/gtest.h>

#include <csignal>

#include <nlohmann/json.hpp>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/support/mosquitto_broker.hpp"

namespace lastcut::daemon::testing {
namespace {

using lastcut::test::MosquittoBroker;
using lastcut::test::MqttMessage;
using lastcut::test::MqttSubscriber;

RigOptions rig_options(const MosquittoBroker& broker, const std::string& extra = "") {
  RigOptions options;
  options.grbl_cutters = {"cutter-1"};
  options.extra_config = "[status]\nmqtt_url = \"" + broker.url() + "\"\nstation = \"station-a\"\n" + extra;
  return options;
}

// (stage, note) of each entry of a job's state.json history.
std::vector<std::pair<std::string, std::string>> history_of(const nlohmann::json& state) {
  std::vector<std::pair<std::string, std::string>> steps;
  for (const auto& entry : state["history"]) steps.emplace_back(entry.value("stage", ""), entry.value("note", ""));
  return steps;
}

std::vector<std::pair<std::string, std::string>> events_of(const MqttSubscriber& subscriber, const std::string& job) {
  std::vector<std::pair<std::string, std::string>> steps;
  for (const MqttMessage& message : subscriber.on("lastcut/job/" + job + "/event")) {
    EXPECT_FALSE(message.retained) << "job events are not retained";
    const auto event = nlohmann::json::parse(message.payload);
    EXPECT_EQ(event.value("job", ""), job);
    EXPECT_EQ(event.value("station", ""), "station-a");
    steps.emplace_back(event.value("stage", ""), event.value("note", ""));
  }
  return steps;
}

nlohmann::json last_json(const MqttSubscriber& subscriber, const std::string& topic) {
  auto message = subscriber.last(topic);
  return message ? nlohmann::json::parse(message->payload, nullptr, false) : nlohmann::json();
}

std::string last_payload(const MqttSubscriber& subscriber, const std::string& topic) {
  auto message = subscriber.last(topic);
  return message ? message->payload : "<none>";
}

void drop_last(DaemonRig& rig, const std::string& name, int seed) {
  const auto staging = rig.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(40, "left", 1), staging / name, std::to_string(seed));
  drop(staging / name, rig.watch(), name);
}

// The retained topics as a subscriber arriving now sees them: online, the cutter's state and
// progress of the batch `batch` (100 %: as many lines as the simulated table received).
void expect_current_retained(const MosquittoBroker& broker, DaemonRig& rig, const std::string& batch) {
  MqttSubscriber late(broker.port());
  ASSERT_TRUE(late.wait_subscribed(10));
  ASSERT_TRUE(late.wait_until([&] { return late.last("lastcut/cutter/cutter-1/progress").has_value(); }, 10));
  const auto online = late.last("lastcut/station/station-a/online");
  ASSERT_TRUE(online);
  EXPECT_TRUE(online->retained);
  EXPECT_EQ(online->payload, "true");
  const auto state = late.last("lastcut/cutter/cutter-1/state");
  ASSERT_TRUE(state);
  EXPECT_TRUE(state->retained);
  EXPECT_EQ(nlohmann::json::parse(state->payload)["state"], "idle");
  // An idle cutter has no batch: its retained batch topic is cleared.
  EXPECT_FALSE(late.last("lastcut/cutter/cutter-1/batch").has_value());
  const auto progress = last_json(late, "lastcut/cutter/cutter-1/progress");
  EXPECT_TRUE(late.last("lastcut/cutter/cutter-1/progress")->retained);
  EXPECT_EQ(progress["batch"], batch);
  EXPECT_EQ(progress["percent"], 100);
  EXPECT_EQ(progress["lines_sent"], progress["lines_total"]);
  rig.stop_cutters();
  const std::string received = rig.received("cutter-1");
  EXPECT_EQ(progress["lines_total"].get<int>(), count_occurrences(received, "\n")) << "lines the table received";
  EXPECT_EQ(progress["bytes_total"].get<std::size_t>(), received.size());
}

TEST(StatusMqtt, JobEventsInOrderAndTheCutterStateRetained) {
  MosquittoBroker broker(scratch_folder("mqtt-events-broker"));
  ASSERT_EQ(broker.start(), "");
  MqttSubscriber watcher(broker.port());
  ASSERT_TRUE(watcher.wait_subscribed(10));
  DaemonRig rig("mqtt-events", rig_options(broker));
  rig.start_cutters();
  rig.start_daemon();
  ASSERT_TRUE(watcher.wait_until([&] { return last_payload(watcher, "lastcut/station/station-a/online") == "true"; }, 10));

  drop_last(rig, "one.stl", 1);
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 60)) << read_text(rig.daemon_log());
  const auto done = rig.jobs("done");
  ASSERT_EQ(done.size(), 1u) << read_text(rig.daemon_log());
  const std::string job = done.begin()->first;
  const nlohmann::json state = done.begin()->second;
  const auto history = history_of(state);
  ASSERT_TRUE(watcher.wait_until([&] { return events_of(watcher, job).size() >= history.size(); }, 10));
  EXPECT_EQ(events_of(watcher, job), history) << "one event per state change, in order";
  EXPECT_EQ(history.back().first, "cut");

  // While cutting the state said so, with the batch.
  bool seen_sending = false;
  for (const MqttMessage& message : watcher.on("lastcut/cutter/cutter-1/state")) {
    const auto payload = nlohmann::json::parse(message.payload);
    if (payload["state"] == "sending") seen_sending = payload["batch"] == state["batch"];
  }
  EXPECT_TRUE(seen_sending);
  ASSERT_TRUE(watcher.wait_until(
      [&] { return last_json(watcher, "lastcut/cutter/cutter-1/state").value("state", "") == "idle"; }, 10));
  expect_current_retained(broker, rig, state["batch"].get<std::string>());
  // The material's last nesting, retained: the strip batch of the calf roll with its pieces.
  ASSERT_TRUE(watcher.wait_until([&] { return last_json(watcher, "lastcut/material/calf/nesting").is_object(); }, 10));
  const auto nesting = last_json(watcher, "lastcut/material/calf/nesting");
  EXPECT_EQ(nesting.value("batch", ""), state["batch"].get<std::string>());
  EXPECT_EQ(nesting.value("pieces_placed", 0), state.value("pieces", -1));
  EXPECT_EQ(nesting.value("hide", "?"), "");
  EXPECT_GT(nesting.value("utilisation", 0.0), 0.0);
  MqttSubscriber late(broker.port(), "lastcut/material/#");  // subscribed after: gets the retained message
  ASSERT_TRUE(late.wait_until([&] { return late.last("lastcut/material/calf/nesting").has_value(); }, 10));
  EXPECT_TRUE(late.last("lastcut/material/calf/nesting")->retained);

  // A clean stop says offline itself.
  EXPECT_EQ(rig.stop_daemon(), 0);
  EXPECT_EQ(last_payload(watcher, "lastcut/station/station-a/online"), "false");
  EXPECT_EQ(count_occurrences(read_text(rig.daemon_log()), "did not confirm station"), 0);
}

TEST(StatusMqtt, ACutInterruptedByAnAlarmLeavesTheCutterHeld) {
  MosquittoBroker broker(scratch_folder("mqtt-held-broker"));
  ASSERT_EQ(broker.start(), "");
  RigOptions options = rig_options(broker);
  options.sim_faults = {{"cutter-1", "alarm-at-line=20"}};
  DaemonRig rig("mqtt-held", options);
  rig.start_cutters();
  rig.start_daemon();
  drop_last(rig, "alarm.stl", 3);
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 60)) << read_text(rig.daemon_log());
  const auto held = rig.jobs("held");
  ASSERT_EQ(held.size(), 1u) << read_text(rig.daemon_log());
  const nlohmann::json state = held.begin()->second;
  MqttSubscriber late(broker.port());
  ASSERT_TRUE(late.wait_until([&] { return late.last("lastcut/cutter/cutter-1/batch").has_value(); }, 10));
  const auto cutter = last_json(late, "lastcut/cutter/cutter-1/state");
  EXPECT_EQ(cutter["state"], "held") << "until the next batch starts: the hide may be partly cut";
  EXPECT_EQ(cutter["batch"], state["batch"]);
  EXPECT_NE(cutter["reason"].get<std::string>().find("pieces may be partly cut"), std::string::npos) << cutter;
  EXPECT_EQ(late.last("lastcut/cutter/cutter-1/batch")->payload, state["batch"].get<std::string>());
  const auto progress = last_json(late, "lastcut/cutter/cutter-1/progress");
  EXPECT_LT(progress["percent"].get<int>(), 100);
  EXPECT_LT(progress["lines_sent"].get<int>(), progress["lines_total"].get<int>());
}

TEST(StatusMqtt, TheLastWillSaysOfflineWhenLastcutdIsKilled) {
  MosquittoBroker broker(scratch_folder("mqtt-will-broker"));
  ASSERT_EQ(broker.start(), "");
  MqttSubscriber watcher(broker.port(), "lastcut/station/#");
  ASSERT_TRUE(watcher.wait_subscribed(10));
  DaemonRig rig("mqtt-will", rig_options(broker));
  rig.start_cutters();
  rig.start_daemon();
  ASSERT_TRUE(watcher.wait_until([&] { return last_payload(watcher, "lastcut/station/station-a/online") == "true"; }, 10));
  rig.kill_daemon();
  ASSERT_TRUE(watcher.wait_until([&] { return last_payload(watcher, "lastcut/station/station-a/online") == "false"; }, 10))
      << read_text(broker.log_file());
  MqttSubscriber late(broker.port(), "lastcut/station/#");
  ASSERT_TRUE(late.wait_until([&] { return late.last("lastcut/station/station-a/online").has_value(); }, 10));
  EXPECT_TRUE(late.last("lastcut/station/station-a/online")->retained);
  EXPECT_EQ(late.last("lastcut/station/station-a/online")->payload, "false");
}

TEST(StatusMqtt, ABrokerRestartNeitherStopsTheCutNorLosesTheStatus) {
  MosquittoBroker broker(scratch_folder("mqtt-restart-broker"));
  ASSERT_EQ(broker.start(), "");
  // Room for 3 job events while the broker is away: the oldest ones are dropped and counted.
  DaemonRig rig("mqtt-restart", rig_options(broker, "queue_limit = 3\n"));
  rig.start_cutters();
  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("connected to MQTT broker") != std::string::npos; }, 10));
  broker.stop();
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("lost") != std::string::npos; }, 10));

  drop_last(rig, "during.stl", 2);
  ASSERT_TRUE(wait_until([&] { return rig.settled(1); }, 60)) << read_text(rig.daemon_log());
  const auto done = rig.jobs("done");
  ASSERT_EQ(done.size(), 1u) << "the cut goes on without the broker: " << read_text(rig.daemon_log());
  const std::string job = done.begin()->first;
  const nlohmann::json state = done.begin()->second;
  const auto history = history_of(state);
  ASSERT_GT(history.size(), 3u);

  // The daemon paused while the broker comes back, so that the watcher hears every queued event.
  rig.daemon()->signal(SIGSTOP);
  ASSERT_EQ(broker.start(), "");
  MqttSubscriber watcher(broker.port());
  const bool subscribed = watcher.wait_subscribed(10);
  rig.daemon()->signal(SIGCONT);
  ASSERT_TRUE(subscribed);
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("back;") != std::string::npos; }, 40))
      << read_text(rig.daemon_log());
  const std::string log = read_text(rig.daemon_log());
  EXPECT_EQ(count_occurrences(log, "status: MQTT broker " + broker.url() + " lost"), 1) << log;
  EXPECT_EQ(count_occurrences(log, " back;"), 1) << log;
  EXPECT_NE(log.find(std::to_string(history.size() - 3) + " job event(s) dropped"), std::string::npos) << log;
  // The newest three events arrive after the restart, in order.
  ASSERT_TRUE(watcher.wait_until([&] { return events_of(watcher, job).size() >= 3; }, 10));
  EXPECT_EQ(events_of(watcher, job), decltype(history)(history.end() - 3, history.end()));
  expect_current_retained(broker, rig, state["batch"].get<std::string>());
}

TEST(StatusMqtt, ADaemonStartedBeforeTheBrokerConnectsWhenItComes) {
  MosquittoBroker broker(scratch_folder("mqtt-late-broker"));
  DaemonRig rig("mqtt-late", rig_options(broker));
  rig.start_cutters();
  rig.start_daemon();
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("not reachable") != std::string::npos; }, 10))
      << read_text(rig.daemon_log());
  ASSERT_EQ(broker.start(), "");
  ASSERT_TRUE(wait_until([&] { return read_text(rig.daemon_log()).find("connected to MQTT broker") != std::string::npos; }, 20))
      << read_text(rig.daemon_log());
  MqttSubscriber late(broker.port());
  ASSERT_TRUE(late.wait_until([&] { return last_payload(late, "lastcut/station/station-a/online") == "true"; }, 10));
  EXPECT_TRUE(late.last("lastcut/station/station-a/online")->retained);
  ASSERT_TRUE(late.wait_until([&] { return late.last("lastcut/cutter/cutter-1/state").has_value(); }, 10));
  EXPECT_EQ(last_json(late, "lastcut/cutter/cutter-1/state")["state"], "idle");
  EXPECT_EQ(count_occurrences(read_text(rig.daemon_log()), "not reachable"), 1) << "said once";
}

TEST(StatusMqtt, CheckConfigReportsTheBrokerAndRefusesBadTablesInOneLine) {
  MosquittoBroker broker(scratch_folder("mqtt-check-broker"));
  ASSERT_EQ(broker.start(), "");
  DaemonRig rig("mqtt-check", rig_options(broker));
  const auto out = rig.root() / "check.log";
  const auto check = [&] {
    std::filesystem::remove(out);
    return run_command({binary("lastcutd").string(), "--check-config", rig.config_file().string()}, out);
  };
  EXPECT_EQ(check(), 0);
  EXPECT_NE(read_text(out).find("status: MQTT broker " + broker.url() + " reachable, station station-a"),
            std::string::npos)
      << read_text(out);
  broker.stop();
  EXPECT_EQ(check(), 0) << "a broker that is away is no configuration error";
  EXPECT_NE(read_text(out).find("status: MQTT broker " + broker.url() + " NOT reachable: Connection refused"),
            std::string::npos)
      << read_text(out);

  const std::string good = read_text(rig.config_file());
  for (const auto& [extra, expected] : std::vector<std::pair<std::string, std::string>>{
           {"colour = \"red\"\n", "status.colour (line"}, {"", "status.mqtt_url: \"mqtt//x\" must start with"}}) {
    std::string text = good + extra;
    if (extra.empty()) text.replace(text.find(broker.url()), broker.url().size(), "mqtt//x");
    write_text(rig.config_file(), text);
    EXPECT_EQ(check(), 78);
    const std::string said = read_text(out);
    EXPECT_NE(said.find(expected), std::string::npos) << said;
    EXPECT_EQ(count_occurrences(said, "\n"), 1) << "one line: " << said;
  }
}

// mqtts:// with the CA of a certificate made here, and a broker that wants a password: the
// client lastcutd publishes with is set up the same way as the one --check-config connects with.
TEST(StatusMqtt, TlsAndPasswordsReachTheBroker) {
  const auto folder = scratch_folder("mqtt-tls-broker");
  const auto openssl = [&](const std::vector<std::string>& args) {
    std::vector<std::string> argv{"/usr/bin/openssl"};
    argv.insert(argv.end(), args.begin(), args.end());
    return run_command(argv, folder / "openssl.log");
  };
  const std::string f = folder.string() + "/";
  ASSERT_EQ(openssl({"req", "-x509", "-newkey", "rsa:2048", "-nodes", "-keyout", f + "ca.key", "-out", f + "ca.pem",
                     "-days", "2", "-subj", "/CN=lastcut test CA"}), 0)
      << "openssl (Debian package openssl): " << read_text(folder / "openssl.log");
  ASSERT_EQ(openssl({"req", "-newkey", "rsa:2048", "-nodes", "-keyout", f + "server.key", "-out", f + "server.csr",
                     "-subj", "/CN=127.0.0.1"}), 0);
  write_text(folder / "san.ext", "subjectAltName=IP:127.0.0.1\n");
  ASSERT_EQ(openssl({"x509", "-req", "-in", f + "server.csr", "-CA", f + "ca.pem", "-CAkey", f + "ca.key",
                     "-CAcreateserial", "-out", f + "server.pem", "-days", "2", "-extfile", f + "san.ext"}), 0)
      << read_text(folder / "openssl.log");
  ASSERT_EQ(run_command({"/usr/bin/mosquitto_passwd", "-b", "-c", f + "passwords", "operator", "s3cret"},
                        folder / "passwd.log"), 0)
      << read_text(folder / "passwd.log");
  MosquittoBroker broker(folder, "cafile " + f + "ca.pem\ncertfile " + f + "server.pem\nkeyfile " + f +
                                     "server.key\nallow_anonymous false\npassword_file " + f + "passwords\n");
  ASSERT_EQ(broker.start(), "");
  const std::string url = "mqtts://127.0.0.1:" + std::to_string(broker.port());
  RigOptions options;
  options.extra_config = "[status]\nmqtt_url = \"" + url + "\"\nstation = \"station-a\"\nca_file = \"" + f +
                         "ca.pem\"\nusername = \"operator\"\npassword = \"s3cret\"\n";
  DaemonRig rig("mqtt-tls", options);
  const auto out = rig.root() / "check.log";
  const auto check = [&] {
    std::filesystem::remove(out);
    return run_command({binary("lastcutd").string(), "--check-config", rig.config_file().string()}, out);
  };
  EXPECT_EQ(check(), 0);
  EXPECT_NE(read_text(out).find("status: MQTT broker " + url + " reachable"), std::string::npos) << read_text(out);
  const std::string good = read_text(rig.config_file());
  std::string wrong = good;
  wrong.replace(wrong.find("s3cret"), 6, "guess");
  write_text(rig.config_file(), wrong);
  EXPECT_EQ(check(), 0);
  EXPECT_NE(read_text(out).find("NOT reachable: Connection Refused: not authorised"), std::string::npos)
      << read_text(out);
  std::string plain = good;  // the TLS port spoken to without TLS: no MQTT answer
  plain.replace(plain.find("mqtts://"), 8, "mqtt://");
  plain.replace(plain.find("ca_file"), 7, "# ca_file");
  write_text(rig.config_file(), plain);
  EXPECT_EQ(check(), 0);
  EXPECT_NE(read_text(out).find("NOT reachable"), std::string::npos) << read_text(out);
}

}  // namespace
}  // namespace lastcut::daemon::testing
