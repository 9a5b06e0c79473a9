// The operator page on a ledger shop, in a real browser: two real lastcutd nodes (each compute +
// station with a simulated HPGL plotter) on a PostgreSQL ledger started by the test; station-b's
// page (Debian's chromium driven by operator_page_ledger_browser.js) shows the whole shop, requeues
// a job held on station-a's cutter, and follows a scan dropped on station-a to Done. Over plain
// HTTP: each station pauses only its own cutters, and a batch waiting for a paused cutter is
// cancelled from the other station's page (the ledger's row lock against the claim).
#include <gtest/gtest.h>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/ledger/ledger_shop.hpp"
#include "tests/web/web_client.hpp"

namespace lastcut::daemon::testing {
namespace {

TEST(LedgerOperatorPage, OneNodesPageShowsAndActsOnTheWholeShop) {
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"station-b", {"compute", "station"}}};
  options.cutters = {{"cutter-a", "hpgl", "station-a"}, {"cutter-b", "hpgl", "station-b"}};
  options.web_token = "c3d4e5f6a7b8c9d0-shop";
  LedgerShop shop("ledger-web", options);
  ASSERT_EQ(shop.start_services(), "");
  ASSERT_EQ(shop.start_cutter("cutter-a", "drop-at-line=20"), "");
  ASSERT_EQ(shop.start_cutter("cutter-b"), "");
  ASSERT_EQ(shop.start_node("station-a"), "");
  ASSERT_EQ(shop.start_node("station-b"), "");
  const auto staging = shop.root() / "staging";
  std::filesystem::create_directories(staging);

  // A job held on station-a's cutter (it drops the line), then the cutter works again.
  write_variant(small_last(40, "left", 9), staging / "held-a.stl", "held-a");
  drop(staging / "held-a.stl", shop.watch("station-a"), "held-a.stl");
  ASSERT_TRUE(wait_until([&] { return shop.value("SELECT state FROM jobs WHERE scan_name = 'held-a.stl'") == "held"; }, 120))
      << shop.log_tails();
  shop.stop_cutter("cutter-a");
  ASSERT_EQ(shop.start_cutter("cutter-a"), "");

  // The browser on station-b's page; the scan is dropped on station-a once the page is open.
  write_variant(small_last(41, "right", 9), staging / "shop-scan.stl", "shop-scan");
  const auto log = shop.root() / "browser.log";
  Process browser({"node", std::string(LASTCUT_SOURCE_DIR) + "/tests/web/operator_page_ledger_browser.js",
                   "http://127.0.0.1:" + std::to_string(shop.web_port("station-b")) + "/", options.web_token,
                   "shop-scan.stl", "station-a", "station-b", (shop.root() / "ledger-page.png").string(),
                   std::string(LASTCUT_SOURCE_DIR) + "/tests/node/node_modules"},
                  log);
  ASSERT_TRUE(wait_until([&] { return read_text(log).find("requeued from this page") != std::string::npos || !browser.running(); }, 90))
      << read_text(log);
  drop(staging / "shop-scan.stl", shop.watch("station-a"), "shop-scan.stl");
  EXPECT_EQ(browser.wait(240), 0) << read_text(log) << "\n" << shop.log_tails();
  EXPECT_NE(read_text(shop.log_file("station-b")).find("(token shop) requeued job"), std::string::npos);
  EXPECT_EQ(shop.value("SELECT state FROM jobs WHERE scan_name = 'held-a.stl'"), "done");
  EXPECT_EQ(shop.value("SELECT state FROM jobs WHERE scan_name = 'shop-scan.stl'"), "done");
  EXPECT_EQ(shop.stop_node("station-a"), 0);
  EXPECT_EQ(shop.stop_node("station-b"), 0);
}

TEST(LedgerOperatorPage, EachStationPausesItsOwnCuttersAndAnyStationCancelsAWaitingBatch) {
  using web_testing::http;
  ShopOptions options;
  options.nodes = {{"station-a", {"compute", "station"}}, {"station-b", {"compute", "station"}}};
  options.cutters = {{"cutter-a", "hpgl", "station-a"}, {"cutter-b", "hpgl", "station-b"}};
  options.web_token = "d4e5f6a7b8c9d0e1-shop";
  LedgerShop shop("ledger-cancel", options);
  ASSERT_EQ(shop.start_services(), "");
  ASSERT_EQ(shop.start_cutter("cutter-a"), "");
  ASSERT_EQ(shop.start_cutter("cutter-b"), "");
  ASSERT_EQ(shop.start_node("station-a"), "");
  ASSERT_EQ(shop.start_node("station-b"), "");
  const int page_a = shop.web_port("station-a");
  const int page_b = shop.web_port("station-b");
  const std::string auth = "Authorization: Bearer " + options.web_token + "\r\n";

  const auto elsewhere = http(page_b, "POST", "/api/cutters/cutter-a/pause", auth);
  EXPECT_EQ(elsewhere.status, 409);
  EXPECT_EQ(elsewhere.body, "pause refused: cutter cutter-a is cabled to another station; use that station's page\n");
  ASSERT_EQ(http(page_a, "POST", "/api/cutters/cutter-a/pause", auth).status, 200);
  ASSERT_EQ(http(page_b, "POST", "/api/cutters/cutter-b/pause", auth).status, 200);

  const auto staging = shop.root() / "staging";
  std::filesystem::create_directories(staging);
  write_variant(small_last(42, "left", 11), staging / "cancel-me.stl", "cancel-me");
  drop(staging / "cancel-me.stl", shop.watch("station-a"), "cancel-me.stl");
  std::string batch;
  ASSERT_TRUE(wait_until([&] {
    batch = shop.value("SELECT id FROM batches WHERE state = 'queued'");
    return !batch.empty();
  }, 120)) << shop.log_tails();
  // Station-b's page lists it (the shop's overview) and cancels it.
  EXPECT_TRUE(wait_until([&] {
    const auto overview = nlohmann::json::parse(http(page_b, "GET", "/api/overview").body);
    return !overview["queued_batches"].empty() && overview["queued_batches"][0]["id"] == batch;
  }, 10));
  EXPECT_EQ(http(page_b, "POST", "/api/batches/" + batch + "/cancel").status, 401);
  const auto cancelled = http(page_b, "POST", "/api/batches/" + batch + "/cancel", auth);
  EXPECT_EQ(cancelled.status, 200) << cancelled.body;
  EXPECT_EQ(cancelled.body, "batch " + batch + " cancelled: its 1 job(s) are held\n");
  EXPECT_EQ(http(page_b, "POST", "/api/batches/" + batch + "/cancel", auth).body,
            "cancel of batch " + batch + " refused: batch " + batch +
                " is held: only a batch waiting for its cutter can be cancelled\n");
  EXPECT_EQ(shop.value("SELECT state FROM batches WHERE id = " + batch), "held");
  EXPECT_EQ(shop.value("SELECT state FROM jobs WHERE scan_name = 'cancel-me.stl'"), "held");
  EXPECT_EQ(shop.value("SELECT reason FROM jobs WHERE scan_name = 'cancel-me.stl'"),
            "batch " + batch + " cancelled by shop before it was cut; requeue the job to nest it again");
  EXPECT_NE(read_text(shop.log_file("station-b")).find("(token shop): batch " + batch + " cancelled"), std::string::npos);

  // Resumed, the cutters never cut the cancelled batch; the requeued job is nested again and cut.
  ASSERT_EQ(http(page_a, "POST", "/api/cutters/cutter-a/resume", auth).status, 200);
  ASSERT_EQ(http(page_b, "POST", "/api/cutters/cutter-b/resume", auth).status, 200);
  const std::string job = shop.value("SELECT id FROM jobs WHERE scan_name = 'cancel-me.stl'");
  ASSERT_EQ(http(page_a, "POST", "/api/jobs/" + job + "/requeue", auth).status, 200);
  EXPECT_TRUE(wait_until([&] { return shop.value("SELECT state FROM jobs WHERE scan_name = 'cancel-me.stl'") == "done"; }, 120))
      << shop.log_tails();
  EXPECT_EQ(shop.value("SELECT state FROM batches WHERE id = " + batch), "held") << "never cut";
  EXPECT_EQ(shop.stop_node("station-a"), 0);
  EXPECT_EQ(shop.stop_node("station-b"), 0);
}

}  // namespace
}  // namespace lastcut::daemon::testing
