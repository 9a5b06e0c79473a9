#pragma once
// Which foot a last is for. The medial (big-toe) side of a left last is -Y in the canonical
// frame (sole on z = 0, +X from heel to toe, +Z up); of a right last, +Y.
#include <string_view>

namespace lastcut {

enum class FootSide { Left, Right };

constexpr std::string_view to_string(FootSide side) { return side == FootSide::Left ? "left" : "right"; }
// The halves of a symmetric last whose foot was not named (engine/orient/orient_last.hpp): seen from
// above with the toe pointing away, side_a is the half on the left (+Y), side_b the one on the right.
// Named left, side_b is the medial half; named right, side_a is.
inline constexpr const char* kNeutralHalfPlusY = "side_a";
inline constexpr const char* kNeutralHalfMinusY = "side_b";

// +1 when the medial side is +Y, -1 when it is -Y.
constexpr double medial_y_sign(FootSide side) { return side == FootSide::Left ? -1.0 : 1.0; }

}  // namespace lastcut
