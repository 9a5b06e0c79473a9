// lastcutd's operator page with the real binaries: the daemon on a scratch spool with a simulated
// plotter, the page read over real TCP on 127.0.0.1. Proves: the page and its overview are
// served, a dropped scan's stages arrive as live events, hostile requests (path traversal plain,
// encoded and absolute, oversized bodies and headers, slow clients, actions without or with a
// wrong token, a malformed hide) are each refused with the right status and one log line while
// the daemon goes on, a held job is requeued with the token and cut, and a paused cutter starts no
// batch, across a restart too, until it is resumed.
#include <gtest/gtest.h>

#include <thread>

#include <nlohmann/json.hpp>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/support/loopback_port.hpp"
#include "tests/web/web_client.hpp"

namespace lastcut::daemon::testing {
namespace {

using web_testing::http;
using web_testing::raw_http;

const std::string kToken = "5f0c2a3b9d8e7f60-anna";

struct PageRig {
  explicit PageRig(const std::string& name, RigOptions options = {}) : port(lastcut::test::free_loopback_port()) {
    options.extra_paths += "hides = \"hides\"\n";
    options.extra_config += "[web]\nlisten = \"127.0.0.1:" + std::to_string(port) + "\"\nassets = \"" +
                            std::string(LASTCUT_SOURCE_DIR) + "/daemon/web/assets\"\nrequests_per_s = 1000\n"
                            "[web.tokens]\nanna = \"" + kToken + "\"\n";
    rig = std::make_unique<DaemonRig>(name, options);
    rig->start_cutters();
    rig->start_daemon();
    EXPECT_TRUE(wait_until([&] { return http(port, "GET", "/api/overview").status == 200; }, 20))
        << read_text(rig->daemon_log());
  }
  int refusals() const { return count_occurrences(read_text(rig->daemon_log()), "web: refused"); }
  int port;
  std::unique_ptr<DaemonRig> rig;
};

TEST(OperatorPage, ServesThePageItsFilesAndTheOverview) {
  PageRig page("web-serves");
  const auto index = http(page.port, "GET", "/");
  EXPECT_EQ(index.status, 200);
  EXPECT_NE(index.body.find("<title>lastcut"), std::string::npos);
  EXPECT_NE(index.headers.find("Content-Security-Policy: default-src 'self'"), std::string::npos) << index.headers;
  const auto script = http(page.port, "GET", "/assets/app.js");
  EXPECT_EQ(script.status, 200);
  EXPECT_NE(script.headers.find("Content-Type: text/javascript"), std::string::npos);
  const auto overview = http(page.port, "GET", "/api/overview");
  ASSERT_EQ(overview.status, 200);
  const auto json = nlohmann::json::parse(overview.body);
  EXPECT_EQ(json["mode"], "spool");
  EXPECT_NE(json["headline"].get<std::string>().find("spool"), std::string::npos);
  EXPECT_EQ(json["can_act"], true);
  EXPECT_EQ(page.refusals(), 0);
  EXPECT_EQ(page.rig->stop_daemon(), 0);
}

TEST(OperatorPage, AScanDroppedAppearsAsLiveEventsThroughItsStages) {
  PageRig page("web-live");
  web_testing::EventReader reader(page.port);
  ASSERT_TRUE(wait_until([&] { return reader.connected(); }, 10));
  const auto staging = page.rig->root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(40, "left", 5), staging / "live.stl", "live");
  drop(staging / "live.stl", page.rig->watch(), "live.stl");
  ASSERT_TRUE(wait_until([&] { return page.rig->settled(1); }, 120)) << read_text(page.rig->daemon_log());
  // The last event may trail the spool's move by a moment.
  wait_until([&] {
    for (const auto& event : reader.events())
      if (event.kind == "job" && event.data.find("\"stage\":\"cut\"") != std::string::npos) return true;
    return false;
  }, 5);
  std::vector<std::string> stages;
  bool cutter_sending = false;
  for (const auto& event : reader.events()) {
    const auto data = nlohmann::json::parse(event.data);
    if (event.kind == "job" && data["scan"] == "live.stl") {
      const std::string stage = data["stage"];
      if (stages.empty() || stages.back() != stage) stages.push_back(stage);
    }
    if (event.kind == "cutter" && data["state"] == "sending") cutter_sending = true;
  }
  EXPECT_EQ(stages, (std::vector<std::string>{"claimed", "computed", "batched", "sending", "cut"}));
  EXPECT_TRUE(cutter_sending);
  // The day's figures: the one batch cut, with its job, pieces and yield.
  const auto overview = nlohmann::json::parse(http(page.port, "GET", "/api/overview").body);
  ASSERT_EQ(overview["cut_last_24h"].size(), 1u) << overview.dump(1);
  const auto& cut = overview["cut_last_24h"][0];
  EXPECT_EQ(cut["jobs"], 1);
  EXPECT_GE(cut["pieces"].get<int>(), 2) << "a medial and a lateral mold";
  EXPECT_GT(cut["utilisation"].get<double>(), 0.05);
  EXPECT_LE(cut["utilisation"].get<double>(), 1.0);
  EXPECT_TRUE(cut["cut_at"].get<std::string>().ends_with("Z"));
  EXPECT_EQ(page.rig->stop_daemon(), 0);
}

TEST(OperatorPage, HostileRequestsAreRefusedWithOneLineEachAndTheDaemonGoesOn) {
  PageRig page("web-hostile");
  struct Case {
    std::string what, request;
    int status;
  };
  const std::string head = " HTTP/1.1\r\nHost: 127.0.0.1\r\nConnection: close\r\n";
  const std::vector<Case> cases = {
      {"traversal", "GET /assets/../../../etc/passwd" + head + "\r\n", 400},
      {"encoded traversal", "GET /assets/%2e%2e/%2e%2e/etc/passwd" + head + "\r\n", 400},
      {"encoded slash", "GET /api/jobs/..%2f..%2fetc/files/passwd" + head + "\r\n", 400},
      {"absolute path", "GET //etc/passwd" + head + "\r\n", 400},
      {"job file outside its folder", "GET /api/jobs/x/files/molds/..%2f..%2fstate.json" + head + "\r\n", 400},
      {"hidden file", "GET /assets/.git" + head + "\r\n", 400},
      {"unknown page", "GET /admin" + head + "\r\n", 404},
      {"wrong method", "DELETE /api/overview" + head + "\r\n", 405},
      {"requeue without a token", "POST /api/jobs/20261128-000000-001/requeue" + head + "Content-Length: 0\r\n\r\n", 401},
      {"requeue with a wrong token",
       "POST /api/jobs/20261128-000000-001/requeue" + head + "Authorization: Bearer not-the-token-at-all\r\nContent-Length: 0\r\n\r\n", 403},
      {"requeue of no job", "POST /api/jobs/20261128-000000-001/requeue" + head + "Authorization: Bearer " + kToken +
                                "\r\nContent-Length: 0\r\n\r\n", 409},
      {"malformed hide", "POST /api/cutters/cutter-1/hides/bad.dxf" + head + "Authorization: Bearer " + kToken +
                             "\r\nContent-Length: 11\r\n\r\nnot a hide\n", 422},
      {"hide for no cutter", "POST /api/cutters/nobody/hides/bad.dxf" + head + "Authorization: Bearer " + kToken +
                                 "\r\nContent-Length: 11\r\n\r\nnot a hide\n", 422},
      {"oversized body", "POST /api/cutters/cutter-1/hides/big.dxf" + head + "Authorization: Bearer " + kToken +
                             "\r\nContent-Length: 209715200\r\n\r\n" + std::string(65536, 'x'), 413},
      {"oversized header", "GET /" + head + "X-Filler: " + std::string(20000, 'a') + "\r\n\r\n", 400},
  };
  int expected_refusals = 0;
  for (const Case& c : cases) {
    const auto answer = raw_http(page.port, c.request);
    EXPECT_EQ(answer.status, c.status) << c.what << ": " << answer.headers << "\n" << answer.body;
    ++expected_refusals;
    EXPECT_EQ(page.refusals(), expected_refusals) << c.what << "\n" << read_text(page.rig->daemon_log());
  }
  EXPECT_EQ(count_entries(page.rig->root() / "hides"), 0) << "a refused hide leaves nothing on the table";
  EXPECT_NE(read_text(page.rig->daemon_log()).find("cutter \"nobody\" is not configured"), std::string::npos);

  // Slow clients: ten connections that send half a request and stall hold no one else up.
  std::vector<std::thread> slow;
  for (int i = 0; i < 10; ++i)
    slow.emplace_back([&] { raw_http(page.port, "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nX-Slow:", 8); });
  std::this_thread::sleep_for(std::chrono::milliseconds(300));
  const auto start = std::chrono::steady_clock::now();
  EXPECT_EQ(http(page.port, "GET", "/api/overview").status, 200);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
  for (auto& thread : slow) thread.join();

  ASSERT_TRUE(page.rig->daemon()->running());
  EXPECT_EQ(http(page.port, "GET", "/").status, 200);
  EXPECT_EQ(page.rig->stop_daemon(), 0);
}

TEST(OperatorPage, AHeldJobIsRequeuedWithTheTokenAndCut) {
  RigOptions options;
  options.sim_faults = {{"cutter-1", "drop-at-line=20"}};
  PageRig page("web-requeue", options);
  const auto staging = page.rig->root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(41, "right", 6), staging / "held.stl", "held");
  drop(staging / "held.stl", page.rig->watch(), "held.stl");
  ASSERT_TRUE(wait_until([&] { return page.rig->jobs("held").size() == 1; }, 120)) << read_text(page.rig->daemon_log());
  const std::string id = page.rig->jobs("held").begin()->first;

  const auto overview = nlohmann::json::parse(http(page.port, "GET", "/api/overview").body);
  bool listed = false;
  for (const auto& job : overview["jobs"])
    if (job["id"] == id && job["list"] == "held" && !job["reason"].get<std::string>().empty()) listed = true;
  EXPECT_TRUE(listed) << overview.dump(1);
  const auto detail = nlohmann::json::parse(http(page.port, "GET", "/api/jobs/" + id).body);
  EXPECT_EQ(detail["state"]["stage"], "held");

  EXPECT_EQ(http(page.port, "POST", "/api/jobs/" + id + "/requeue").status, 401);
  EXPECT_EQ(page.rig->jobs("held").size(), 1u) << "refused: still held";
  page.rig->stop_cutters();
  Process cutter({binary("lastcut-sim").string(), "hpgl", "--link", (page.rig->root() / "cutter-1.tty").string(),
                  "--record", (page.rig->root() / "record2").string(), "--time-scale", "0"},
                 page.rig->root() / "sim2.log");
  const auto requeued = http(page.port, "POST", "/api/jobs/" + id + "/requeue", "Authorization: Bearer " + kToken + "\r\n");
  EXPECT_EQ(requeued.status, 200) << requeued.body;
  EXPECT_NE(read_text(page.rig->daemon_log()).find("(token anna) requeued job " + id), std::string::npos);
  EXPECT_TRUE(wait_until([&] { return page.rig->jobs("done").count(id) == 1; }, 60)) << read_text(page.rig->daemon_log());
  EXPECT_EQ(page.rig->stop_daemon(), 0);
  cutter.stop();
}

// The events seen so far of one kind whose JSON has `key` = `value`.
int events_with(const web_testing::EventReader& reader, const std::string& kind, const std::string& key,
                const std::string& value) {
  int count = 0;
  for (const auto& event : reader.events())
    if (event.kind == kind && nlohmann::json::parse(event.data).value(key, "") == value) ++count;
  return count;
}

TEST(OperatorPage, APausedCutterStartsNoBatchAcrossARestartUntilResumed) {
  PageRig page("web-pause");
  const std::string auth = "Authorization: Bearer " + kToken + "\r\n";
  EXPECT_EQ(http(page.port, "POST", "/api/cutters/cutter-1/pause").status, 401);
  EXPECT_EQ(http(page.port, "POST", "/api/cutters/cutter-1/pause", "Authorization: Bearer wrong-token-0123456789\r\n").status, 403);
  const auto unknown = http(page.port, "POST", "/api/cutters/nobody/pause", auth);
  EXPECT_EQ(unknown.status, 404);
  EXPECT_EQ(unknown.body, "pause refused: no cutter nobody in this station's configuration\n");
  EXPECT_EQ(http(page.port, "POST", "/api/cutters/cutter-1/resume", auth).body, "resume refused: cutter cutter-1 is not paused\n");
  const auto paused = http(page.port, "POST", "/api/cutters/cutter-1/pause", auth);
  ASSERT_EQ(paused.status, 200) << paused.body;
  const auto again = http(page.port, "POST", "/api/cutters/cutter-1/pause", auth);
  EXPECT_EQ(again.status, 409);
  EXPECT_EQ(again.body, "pause refused: cutter cutter-1 is already paused (by anna)\n");
  EXPECT_NE(read_text(page.rig->daemon_log()).find("(token anna): cutter cutter-1 paused"), std::string::npos);

  // Restarted while paused (as systemd would after a crash): still paused.
  EXPECT_EQ(page.rig->stop_daemon(), 0);
  page.rig->start_daemon();
  ASSERT_TRUE(wait_until([&] { return http(page.port, "GET", "/api/overview").status == 200; }, 20));
  EXPECT_NE(read_text(page.rig->daemon_log()).find("cutter cutter-1: paused (by anna) before this start"), std::string::npos);
  const auto overview = nlohmann::json::parse(http(page.port, "GET", "/api/overview").body);
  EXPECT_EQ(overview["paused_cutters"], (nlohmann::json{{"cutter-1", "anna"}}));

  web_testing::EventReader reader(page.port);
  ASSERT_TRUE(wait_until([&] { return reader.connected(); }, 10));
  const auto staging = page.rig->root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(42, "left", 5), staging / "paused.stl", "paused");
  drop(staging / "paused.stl", page.rig->watch(), "paused.stl");
  ASSERT_TRUE(wait_until([&] { return events_with(reader, "job", "stage", "batched") == 1; }, 120))
      << read_text(page.rig->daemon_log());
  // Nested and queued, but the paused cutter does not take it.
  std::this_thread::sleep_for(std::chrono::seconds(4));
  EXPECT_EQ(events_with(reader, "job", "stage", "sending"), 0);
  EXPECT_EQ(events_with(reader, "cutter", "state", "sending"), 0);
  EXPECT_TRUE(page.rig->jobs("done").empty());

  const auto resumed = http(page.port, "POST", "/api/cutters/cutter-1/resume", auth);
  EXPECT_EQ(resumed.status, 200) << resumed.body;
  EXPECT_EQ(resumed.body, "cutter cutter-1 resumed (paused by anna, resumed by anna): its batches are cut again\n");
  EXPECT_TRUE(wait_until([&] { return page.rig->jobs("done").size() == 1; }, 60)) << read_text(page.rig->daemon_log());
  const std::string log = read_text(page.rig->daemon_log());
  EXPECT_NE(log.find("cutter cutter-1: resumed"), std::string::npos) << log;
  EXPECT_EQ(nlohmann::json::parse(http(page.port, "GET", "/api/overview").body)["paused_cutters"], nlohmann::json::object());
  EXPECT_EQ(page.rig->stop_daemon(), 0);
}

TEST(OperatorPage, ABatchWaitingForItsCutterIsCancelledItsJobHeldThenRequeuedAndCut) {
  PageRig page("web-cancel");
  const std::string auth = "Authorization: Bearer " + kToken + "\r\n";
  // Paused, so that the batch waits for it long enough to be cancelled.
  ASSERT_EQ(http(page.port, "POST", "/api/cutters/cutter-1/pause", auth).status, 200);
  const auto staging = page.rig->root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(43, "right", 7), staging / "cancel.stl", "cancel");
  drop(staging / "cancel.stl", page.rig->watch(), "cancel.stl");
  std::string batch;
  ASSERT_TRUE(wait_until([&] {
    const auto overview = nlohmann::json::parse(http(page.port, "GET", "/api/overview").body);
    if (overview["queued_batches"].empty()) return false;
    batch = overview["queued_batches"][0]["id"];
    EXPECT_EQ(overview["queued_batches"][0]["cutter"], "cutter-1");
    EXPECT_EQ(overview["queued_batches"][0]["jobs"], 1);
    return true;
  }, 120)) << read_text(page.rig->daemon_log());

  EXPECT_EQ(http(page.port, "POST", "/api/batches/" + batch + "/cancel").status, 401);
  const auto unknown = http(page.port, "POST", "/api/batches/B-none/cancel", auth);
  EXPECT_EQ(unknown.status, 409);
  EXPECT_TRUE(unknown.body.starts_with("cancel of batch B-none refused: no batch B-none in ")) << unknown.body;
  const auto cancelled = http(page.port, "POST", "/api/batches/" + batch + "/cancel", auth);
  ASSERT_EQ(cancelled.status, 200) << cancelled.body;
  EXPECT_EQ(cancelled.body, "batch " + batch + " cancelled: its 1 job(s) are held\n");
  const auto again = http(page.port, "POST", "/api/batches/" + batch + "/cancel", auth);
  EXPECT_EQ(again.status, 409);
  EXPECT_EQ(again.body, "cancel of batch " + batch + " refused: batch " + batch +
                            " is held: only a batch waiting for its cutter can be cancelled\n");
  EXPECT_NE(read_text(page.rig->daemon_log()).find("(token anna): batch " + batch + " cancelled"), std::string::npos);
  const auto held = page.rig->jobs("held");
  ASSERT_EQ(held.size(), 1u);
  const std::string id = held.begin()->first;
  EXPECT_NE(held.begin()->second.value("reason", "").find("batch " + batch +
                                                         " cancelled by anna before it was cut; requeue the job to nest it again"),
            std::string::npos) << held.begin()->second.dump(1);
  EXPECT_TRUE(nlohmann::json::parse(http(page.port, "GET", "/api/overview").body)["queued_batches"].empty());

  // The cutter, resumed, does not cut the cancelled batch; the requeued job is nested again and cut.
  ASSERT_EQ(http(page.port, "POST", "/api/cutters/cutter-1/resume", auth).status, 200);
  std::this_thread::sleep_for(std::chrono::seconds(2));
  EXPECT_TRUE(page.rig->jobs("done").empty());
  ASSERT_EQ(http(page.port, "POST", "/api/jobs/" + id + "/requeue", auth).status, 200);
  EXPECT_TRUE(wait_until([&] { return page.rig->jobs("done").count(id) == 1; }, 90)) << read_text(page.rig->daemon_log());
  EXPECT_EQ(page.rig->stop_daemon(), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
