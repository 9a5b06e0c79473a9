#pragma once
// Numbers as decimal text for the files lastcut writes (OBJ, OFF, SVG), without printf.
// Why: std::to_chars is locale-independent (a German locale can never turn 1.5 into "1,5") and
// several times faster than snprintf; writing a 100k-triangle half as OBJ and SVG spent more time
// in printf than ARAP spent flattening it. The text is the same as printf's "%.*f" (both round
// correctly from the binary value).
#include <string>

namespace lastcut {

// Appends `value` with exactly `decimals` digits after the point (0..17), e.g. "-12.500".
void append_fixed(std::string& out, double value, int decimals);
// Appends an integer, e.g. "42".
void append_integer(std::string& out, long long value);
// `value` with `decimals` digits after the point, as a new string.
std::string fixed_text(double value, int decimals);

}  // namespace lastcut
