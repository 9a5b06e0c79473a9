// grbl reply parsing, code tables and program splitting: the pure parts of the grbl driver.
#include <gtest/gtest.h>

#include "drivers/grbl/axis_words.hpp"
#include "drivers/grbl/grbl_codes.hpp"
#include "drivers/grbl/grbl_job.hpp"
#include "drivers/grbl/grbl_replies.hpp"
#include "drivers/grbl/motion_watch.hpp"

namespace lastcut::drivers::grbl {
namespace {

TEST(GrblReplies, ClassifiesEveryKindOfLine) {
  EXPECT_EQ(classify_reply("ok").kind, ReplyKind::Ok);
  const Reply error = classify_reply("error:22");
  EXPECT_EQ(error.kind, ReplyKind::Error);
  EXPECT_EQ(error.code, 22);
  const Reply alarm = classify_reply("ALARM:1");
  EXPECT_EQ(alarm.kind, ReplyKind::Alarm);
  EXPECT_EQ(alarm.code, 1);
  const Reply hold = classify_reply("<Hold:0|MPos:1.000,2.000,0.000|Bf:15,128|FS:0,0>");
  EXPECT_EQ(hold.kind, ReplyKind::Status);
  EXPECT_EQ(hold.state, "Hold");
  EXPECT_EQ(hold.substate, 0);
  const Reply idle = classify_reply("<Idle|MPos:0.000,0.000,0.000|FS:0,0>");
  EXPECT_EQ(idle.state, "Idle");
  EXPECT_EQ(idle.substate, -1);
  EXPECT_EQ(classify_reply("Grbl 1.1h ['$' for help]").kind, ReplyKind::Banner);
  EXPECT_EQ(classify_reply("GrblHAL 1.1f ['$' or '$HELP' for help]").kind, ReplyKind::Banner);
  EXPECT_EQ(classify_reply("[MSG:Caution: Unlocked]").kind, ReplyKind::Feedback);
  EXPECT_EQ(classify_reply("$110=5000.000").kind, ReplyKind::Setting);
  EXPECT_EQ(classify_reply("").kind, ReplyKind::Empty);
}

TEST(GrblReplies, KeepsThePositionFieldOfAStatusReport) {
  EXPECT_EQ(classify_reply("<Run|MPos:34.980,103.300,1.108|FS:600,0|Pn:PXYZRHS>").position, "MPos:34.980,103.300,1.108");
  EXPECT_EQ(classify_reply("<Idle|WPos:1.000,2.000,0.000|Bf:15,128>").position, "WPos:1.000,2.000,0.000");
  EXPECT_EQ(classify_reply("<Idle|Bf:15,128|FS:0,0>").position, "");
}

// The watch that turns "answers but no longer moves" into a stopped job (the grbl simulator's
// stepper interrupt died that way: Run for minutes at one position).
TEST(GrblMotionWatch, OnlyTimeWithoutAnySignOfProgressIsAStall) {
  MotionWatch watch(10, 0);
  watch.on_status("Run", "MPos:1.000,0.000,0.000", 1);
  EXPECT_FALSE(watch.stalled(10.5));
  EXPECT_TRUE(watch.stalled(11.5)) << "Run at one position for 10.5 s";
  EXPECT_EQ(watch.last_seen(), "Run at MPos:1.000,0.000,0.000");

  watch.on_status("Run", "MPos:1.001,0.000,0.000", 12);  // it moved
  EXPECT_FALSE(watch.stalled(21.5));
  watch.on_acknowledged(21);  // a line taken
  EXPECT_FALSE(watch.stalled(30.5));
  watch.on_status("Idle", "MPos:1.001,0.000,0.000", 31);  // a state change
  EXPECT_FALSE(watch.stalled(40.5));
  EXPECT_TRUE(watch.stalled(41.5));
}

TEST(GrblMotionWatch, AnOperatorHoldIsNotAStallAndZeroTurnsTheWatchOff) {
  MotionWatch watch(10, 0);
  for (int t = 0; t <= 100; t += 5) watch.on_status("Hold", "MPos:1.000,0.000,0.000", t);
  EXPECT_FALSE(watch.stalled(101));
  MotionWatch off(0, 0);
  off.on_status("Run", "MPos:1.000,0.000,0.000", 0);
  EXPECT_FALSE(off.stalled(1e6));
}

TEST(GrblReplies, ReadsTheReceiveBufferFromTheOptionsLine) {
  EXPECT_EQ(classify_reply("[OPT:V,15,128]").rx_buffer_bytes, 128);
  EXPECT_EQ(classify_reply("[OPT:V,15,128]").axis_count, -1);  // grbl 1.1: no axis field
  EXPECT_EQ(classify_reply("[OPT:VNMHSL,35,1024,3,0]").rx_buffer_bytes, 1024);  // grblHAL
  EXPECT_EQ(classify_reply("[OPT:VNMHSL,35,1024,4,0]").axis_count, 4);
  EXPECT_EQ(classify_reply("[OPT:V,15]").rx_buffer_bytes, -1);
  EXPECT_EQ(classify_reply("[OPT:V,15,abc]").rx_buffer_bytes, -1);
}

TEST(GrblReplies, RejectsMalformedAndBinaryLines) {
  EXPECT_EQ(classify_reply("error:").kind, ReplyKind::Garbage);
  EXPECT_EQ(classify_reply("error:2x").kind, ReplyKind::Garbage);
  EXPECT_EQ(classify_reply("ALARM:").kind, ReplyKind::Garbage);
  EXPECT_EQ(classify_reply("okay").kind, ReplyKind::Garbage);
  EXPECT_EQ(classify_reply("<Dancing|MPos:0,0,0>").kind, ReplyKind::Garbage);
  EXPECT_EQ(classify_reply(std::string("\xff\xfe\x01ok", 5)).kind, ReplyKind::Garbage);
}

// A tangential-knife file (A axis) on grbl 1.1 (X Y Z) is refused before the first line; the
// words of comments and of arcs (I J K) and feeds are not axes.
TEST(GrblAxisWords, RefusesAnAxisTheControllerDoesNotHave) {
  const std::vector<std::string> tangential = {"G21 G90", "(knife A angle)", "G0 X1 Y2 ; A is the knife", "G1 X3 A45.5 F600"};
  EXPECT_EQ(check_axis_words(tangential, 3), "line 4 moves the A axis, but the controller has 3 axes (X Y Z)");
  EXPECT_EQ(check_axis_words(tangential, 4), "");
  EXPECT_EQ(check_axis_words({"G2 X1 Y1 I0.5 J0 F300", "M8", "$110=5000"}, 3), "");
  EXPECT_EQ(check_axis_words({"g1 x1 c -90"}, 4), "line 1 moves the C axis, but the controller has 4 axes (X Y Z A)");
  EXPECT_EQ(axis_letters(5), "XYZAB");
}

TEST(GrblCodes, ExplainsErrorsAndAlarms) {
  EXPECT_NE(error_meaning(22).find("feed rate"), std::string::npos);
  EXPECT_NE(error_meaning(9).find("alarm"), std::string::npos);
  EXPECT_NE(alarm_meaning(1).find("Hard limit"), std::string::npos);
  EXPECT_NE(alarm_meaning(3).find("Reset while in motion"), std::string::npos);
  EXPECT_EQ(error_meaning(99), "unknown error code 99");
}

TEST(GrblProgram, KeepsLinesByteExactAndDropsBlankOnes) {
  const auto lines = program_lines("G21\r\nG90\n\n   \nG1 X1 F100 ; cut\nM2");
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "G21");
  EXPECT_EQ(lines[2], "G1 X1 F100 ; cut");
  EXPECT_EQ(lines[3], "M2");
}

}  // namespace
}  // namespace lastcut::drivers::grbl
