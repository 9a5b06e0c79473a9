#pragma once
// Which axes a G-code program moves, against the axes a grbl controller has.
//
// Why: grbl 1.1 has X, Y and Z only and answers a line with an A word by error:20 when it gets
// there, after the pieces before it are cut (a tangential-knife file on a 3-axis table stopped
// at line 31). Checking the whole file against the axis count the controller reported ($I) turns
// that into a refusal before the first line, with nothing cut.
#include <string>
#include <vector>

namespace lastcut::drivers::grbl {

// Axis letters of a controller with `axis_count` axes, in grbl/grblHAL order: 3 -> "XYZ", 4 -> "XYZA".
std::string axis_letters(int axis_count);

// "" when every axis word (X Y Z A B C U V W outside comments) of `lines` is among the controller's
// axes; else one line naming the first offending line and axis, e.g.
// "line 31 moves the A axis, but the controller has 3 axes (X Y Z)".
std::string check_axis_words(const std::vector<std::string>& lines, int axis_count);

}  // namespace lastcut::drivers::grbl
