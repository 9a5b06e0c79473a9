// The watch folder on real files: only complete, regular scan files are handed over; temporary
// names, symlinks, folders and other types are left alone; a cut-off STL waits for the grace
// time and then comes with the reason; inotify and polling find the same files.
#include <gtest/gtest.h>

#include <thread>

#include "daemon/watch/file_kind.hpp"
#include "daemon/watch/hot_folder.hpp"
#include "daemon/watch/scan_completeness.hpp"
#include "daemon_harness.hpp"

namespace lastcut::daemon {
namespace {

using testing::write_text;

std::string binary_stl(uint32_t announced, uint32_t held) {
  std::string bytes(80, ' ');
  for (int i = 0; i < 4; ++i) bytes.push_back(static_cast<char>((announced >> (8 * i)) & 0xff));
  bytes.append(50 * held, '\0');
  return bytes;
}

WatchConfig fast_watch(WatchMode mode) {
  WatchConfig config;
  config.mode = mode;
  config.poll_interval_s = 0.05;
  config.rescan_interval_s = 30;
  config.stable_checks = 2;
  config.stable_interval_s = 0.05;
  config.incomplete_grace_s = 0.5;
  return config;
}

// Ticks the folder until `count` scans are ready or 5 s pass.
std::vector<ReadyScan> collect(HotFolder& folder, std::size_t count, double timeout_s = 5) {
  std::vector<ReadyScan> all;
  testing::wait_until(
      [&] {
        folder.read_events();
        for (auto& ready : folder.collect_ready(HotFolder::Clock::now())) {
          folder.forget(ready.scan.filename().string());
          all.push_back(ready);
        }
        return all.size() >= count;
      },
      timeout_s);
  return all;
}

TEST(FileKind, NamesAreClassified) {
  EXPECT_EQ(classify_file_name("last.STL"), FileKind::Scan);
  EXPECT_EQ(classify_file_name("last.obj"), FileKind::Scan);
  EXPECT_EQ(classify_file_name("derby-set.DXF"), FileKind::Scan);  // a pattern set is a job too
  EXPECT_EQ(classify_file_name("last.job.toml"), FileKind::Sidecar);
  for (const char* name : {".last.stl", "last.stl.tmp", "last.stl.part", "last.stl~", "x.crdownload"}) {
    EXPECT_EQ(classify_file_name(name), FileKind::Temporary) << name;
  }
  EXPECT_EQ(classify_file_name("notes.txt"), FileKind::Unsupported);
}

TEST(ScanCompleteness, BinaryStlSizeMustMatchItsTriangleCount) {
  const auto folder = testing::scratch_folder("complete");
  write_text(folder / "ok.stl", binary_stl(10, 10));
  write_text(folder / "cut.stl", binary_stl(5000, 120));
  write_text(folder / "ascii.stl", "solid a\nfacet normal 0 0 1\nendfacet\nendsolid a\n");
  write_text(folder / "half.obj", "v 0 0 0\nv 1 0");
  write_text(folder / "empty.stl", "");
  EXPECT_EQ(scan_incompleteness(folder / "ok.stl"), "");
  EXPECT_EQ(scan_incompleteness(folder / "ascii.stl"), "");
  EXPECT_EQ(scan_incompleteness(folder / "cut.stl"),
            "the file is cut off (binary STL announces 5000 triangles, holds 120)");
  EXPECT_NE(scan_incompleteness(folder / "half.obj"), "");
  EXPECT_EQ(scan_incompleteness(folder / "empty.stl"), "the file is empty");
  write_text(folder / "set.dxf", "  0\nSECTION\n  0\nENDSEC\n  0\nEOF\n");
  write_text(folder / "half.dxf", "  0\nSECTION\n  0\nENDS");
  EXPECT_EQ(scan_incompleteness(folder / "set.dxf"), "");
  EXPECT_EQ(scan_incompleteness(folder / "half.dxf"), "the file is cut off (a DXF file ends with EOF)");
}

class HotFolderModes : public ::testing::TestWithParam<WatchMode> {};

TEST_P(HotFolderModes, OnlyCompleteRegularScansAreHandedOver) {
  const auto folder = testing::scratch_folder(GetParam() == WatchMode::Poll ? "hot-poll" : "hot-inotify");
  const auto watch = folder / "in";
  HotFolder hot(watch, fast_watch(GetParam()));
  ASSERT_EQ(hot.start().error(), "");
  EXPECT_EQ(hot.event_fd() >= 0, GetParam() != WatchMode::Poll);
  write_text(watch / "a.stl", binary_stl(3, 3));
  write_text(watch / "a.job.toml", "order = \"1\"\n");
  write_text(watch / ".b.stl", binary_stl(3, 3));
  write_text(watch / "c.stl.part", binary_stl(3, 3));
  write_text(watch / "notes.txt", "hello\n");
  std::filesystem::create_directory(watch / "d.stl");
  write_text(folder / "outside.stl", binary_stl(3, 3));
  std::filesystem::create_symlink(folder / "outside.stl", watch / "link.stl");
  const auto ready = collect(hot, 1);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].scan.filename(), "a.stl");
  EXPECT_EQ(ready[0].sidecar.filename(), "a.job.toml");
  EXPECT_EQ(ready[0].incompleteness, "");
  // The daemon moves a taken file away; nothing else comes, however long we look.
  std::filesystem::remove(watch / "a.stl");
  EXPECT_TRUE(collect(hot, 1, 0.5).empty());
}

TEST_P(HotFolderModes, AGrowingFileWaitsUntilItIsStable) {
  const auto folder = testing::scratch_folder(GetParam() == WatchMode::Poll ? "grow-poll" : "grow-inotify");
  const auto watch = folder / "in";
  HotFolder hot(watch, fast_watch(GetParam()));
  ASSERT_EQ(hot.start().error(), "");
  // Written in pieces like a slow upload: announced 400 triangles, growing.
  std::string bytes = binary_stl(400, 0);
  write_text(watch / "slow.stl", bytes);
  for (int piece = 0; piece < 8; ++piece) {
    hot.read_events();
    EXPECT_TRUE(hot.collect_ready(HotFolder::Clock::now()).empty()) << "taken while growing";
    bytes.append(50 * 50, 'x');
    write_text(watch / "slow.stl", bytes);
    std::this_thread::sleep_for(std::chrono::milliseconds(30));
  }
  const auto ready = collect(hot, 1);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_EQ(ready[0].incompleteness, "");
}

TEST_P(HotFolderModes, ACutOffFileIsHandedOverAfterTheGraceTimeWithTheReason) {
  const auto folder = testing::scratch_folder(GetParam() == WatchMode::Poll ? "cut-poll" : "cut-inotify");
  const auto watch = folder / "in";
  HotFolder hot(watch, fast_watch(GetParam()));
  ASSERT_EQ(hot.start().error(), "");
  write_text(watch / "cut.stl", binary_stl(5000, 120));
  const auto start = std::chrono::steady_clock::now();
  const auto ready = collect(hot, 1);
  ASSERT_EQ(ready.size(), 1u);
  EXPECT_GE(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 0.45);
  EXPECT_NE(ready[0].incompleteness.find("cut off"), std::string::npos);
}

TEST_P(HotFolderModes, FilesPresentAtStartAreFound) {
  const auto folder = testing::scratch_folder(GetParam() == WatchMode::Poll ? "start-poll" : "start-inotify");
  const auto watch = folder / "in";
  std::filesystem::create_directories(watch);
  for (int i = 0; i < 20; ++i) write_text(watch / ("s" + std::to_string(i) + ".stl"), binary_stl(1, 1));
  HotFolder hot(watch, fast_watch(GetParam()));
  ASSERT_EQ(hot.start().error(), "");
  EXPECT_EQ(collect(hot, 20).size(), 20u);
}

INSTANTIATE_TEST_SUITE_P(Watch, HotFolderModes, ::testing::Values(WatchMode::Inotify, WatchMode::Poll));

}  // namespace
}  // namespace lastcut::daemon
