// SIGHUP (daemon/station/config_reload.hpp): what applies while running and what waits for a
// restart, the same on a spool and on a ledger node.
#include <gtest/gtest.h>

#include "daemon/station/config_reload.hpp"

namespace lastcut::daemon {
namespace {

TEST(ConfigReload, TheBatchRuleAppliesAtOnceAndPathsWaitForARestart) {
  auto running = std::make_shared<DaemonConfig>();
  running->paths.watch_dir = "/srv/in";
  running->batch.window_s = 0;
  DaemonConfig next = *running;
  next.paths.watch_dir = "/srv/elsewhere";
  next.batch.window_s = 30;
  next.batch.max_pieces = 12;
  RunningConfig config(running);
  EXPECT_EQ(config.reload(next), "paths.watch changed: kept the running value until restart");
  EXPECT_EQ(config.get()->paths.watch_dir, "/srv/in");
  EXPECT_DOUBLE_EQ(config.get()->batch.window_s, 30);
  EXPECT_EQ(config.get()->batch.max_pieces, 12);
}

TEST(ConfigReload, TheLedgerTableWaitsForARestart) {
  auto running = std::make_shared<DaemonConfig>();
  running->ledger = LedgerConfig{};
  running->ledger->node = "station-1";
  DaemonConfig next = *running;
  next.ledger->node = "station-2";
  next.jobs.duplicate_policy = DuplicatePolicy::Hold;
  RunningConfig config(running);
  EXPECT_EQ(config.reload(next), "[ledger] changed: kept the running value until restart");
  EXPECT_EQ(config.get()->ledger->node, "station-1");
  EXPECT_EQ(config.get()->jobs.duplicate_policy, DuplicatePolicy::Hold);
  EXPECT_EQ(config.reload(*config.get()), "");  // nothing changed: nothing to say
}

}  // namespace
}  // namespace lastcut::daemon
