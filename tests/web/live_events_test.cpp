// LiveEvents: numbered frames in a bounded ring; a watcher that fell behind, or that comes with a
// number of an earlier run, is told to resync; closing wakes every watcher.
#include <gtest/gtest.h>

#include <thread>

#include "daemon/web/live_events.hpp"

namespace lastcut::daemon {
namespace {

using namespace std::chrono_literals;

JobEvent event(const std::string& id, JobStage stage) {
  JobEvent e;
  e.job_id = id;
  e.scan_name = id + ".stl";
  e.stage = stage;
  return e;
}

TEST(LiveEvents, FramesAfterTheNumberSeen) {
  LiveEvents events(8);
  events.job_changed(event("a", JobStage::Claimed));
  events.job_changed(event("a", JobStage::Computed));
  const auto all = events.next(0, 0ms);
  ASSERT_EQ(all.frames.size(), 2u);
  EXPECT_FALSE(all.resync);
  EXPECT_EQ(all.last_id, 2u);
  EXPECT_EQ(all.frames[0].rfind("id: 1\nevent: job\ndata: {", 0), 0u);
  EXPECT_NE(all.frames[1].find("\"stage\":\"computed\""), std::string::npos);
  EXPECT_EQ(all.frames[1].substr(all.frames[1].size() - 2), "\n\n");
  const auto newer = events.next(1, 0ms);
  ASSERT_EQ(newer.frames.size(), 1u);
  EXPECT_TRUE(events.next(2, 0ms).frames.empty());
}

TEST(LiveEvents, AWatcherBehindTheRingResyncs) {
  LiveEvents events(4);
  for (int i = 0; i < 10; ++i) events.job_changed(event("j" + std::to_string(i), JobStage::Claimed));
  const auto behind = events.next(2, 0ms);
  EXPECT_TRUE(behind.resync);
  EXPECT_EQ(behind.frames.size(), 4u);
  EXPECT_EQ(behind.last_id, 10u);
  const auto from_before_a_restart = events.next(500, 0ms);
  EXPECT_TRUE(from_before_a_restart.resync);
  EXPECT_EQ(from_before_a_restart.last_id, 10u);
}

TEST(LiveEvents, KeepsEachCuttersNewestStatus) {
  LiveEvents events;
  CutterStatus status;
  status.cutter = "cutter-1";
  status.state = "sending";
  status.lines_sent = 10;
  status.lines_total = 100;
  events.cutter_changed(status);
  status.lines_sent = 50;
  events.cutter_changed(status);
  const auto cutters = events.cutters();
  EXPECT_EQ(cutters["cutter-1"]["lines_sent"], 50);
  EXPECT_EQ(events.next(0, 0ms).frames.size(), 2u);
}

TEST(LiveEvents, AWaitingWatcherWakesOnAnEventAndOnClose) {
  LiveEvents events;
  std::thread producer([&] {
    std::this_thread::sleep_for(50ms);
    events.job_changed(event("late", JobStage::Cut));
  });
  const auto woke = events.next(0, 5s);
  producer.join();
  EXPECT_EQ(woke.frames.size(), 1u);
  std::thread closer([&] {
    std::this_thread::sleep_for(50ms);
    events.close();
  });
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(events.next(1, 10s).closed);
  EXPECT_LT(std::chrono::steady_clock::now() - start, 5s);
  closer.join();
}

}  // namespace
}  // namespace lastcut::daemon
