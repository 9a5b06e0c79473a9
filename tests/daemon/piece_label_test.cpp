// The label a cutter operator reads on each piece of a mixed batch: order (or scan name), size,
// foot and half, short enough for a pen.
#include <gtest/gtest.h>

#include "daemon/station/piece_label_text.hpp"

namespace lastcut::daemon {
namespace {

TEST(PieceLabel, NamesOrderSizeFootAndHalf) {
  EXPECT_EQ(piece_label_text({"4711", "order-4711.stl", "EU 44", "left", "medial"}), "#4711 EU44 L med");
  EXPECT_EQ(piece_label_text({"4711", "order-4711.stl", "EU 44", "right", "lateral"}), "#4711 EU44 R lat");
}

TEST(PieceLabel, ScanStemStandsInForAMissingOrder) {
  EXPECT_EQ(piece_label_text({"", "mueller anna.stl", "", "right", "lateral"}), "#mueller-anna R lat");
  EXPECT_EQ(piece_label_text({"", "a-very-long-customer-name_2026-11-21.ply", "", "left", "medial"}),
            "#a-very-long- L med");
  EXPECT_EQ(piece_label_text({"", "", "", "", "medial"}), "#? med");
}

TEST(PieceLabel, UnknownFootAndOtherPartsAreKeptAsTheyAre) {
  EXPECT_EQ(piece_label_text({"88", "x.stl", "", "", "medial"}), "#88 med");
  EXPECT_EQ(piece_label_text({"88", "x.stl", "", "left", "heel cap"}), "#88 L heel-cap");
}

TEST(PieceLabel, TheMirroredPieceOfAPairIsForTheOtherFoot) {
  EXPECT_EQ(opposite_foot("left"), "right");
  EXPECT_EQ(opposite_foot("right"), "left");
  EXPECT_EQ(opposite_foot(""), "");
}

}  // namespace
}  // namespace lastcut::daemon
