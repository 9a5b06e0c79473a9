// The operator page on a ledger shop, in a real browser: two real lastcutd nodes (each compute +
// station with a simulated HPGL plotter) on a PostgreSQL ledger started by the test; station-b's
// page (Debian's chromium driven by operator_page_ledger_browser.js) shows the whole shop, requeues
// a job held on station-a's cutter, and follows a scan dropped on station-a to Done.
#include <gtest/gtest.h>

#include "tests/daemon/daemon_rig.hpp"
#include "tests/ledger/ledger_shop.hpp"

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

}  // namespace
}  // namespace lastcut::daemon::testing
