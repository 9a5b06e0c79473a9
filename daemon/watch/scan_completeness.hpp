#pragma once
// A cheap check that a scan file is complete before the daemon takes it, for uploaders that
// pause mid-copy (network shares): the size of a binary STL must be 84 + 50 x triangles, an
// ASCII STL must end with "endsolid", a PLY must have its header, OBJ/OFF must end with a
// newline. The full parse happens later in the engine; this only decides "wait a bit more".
#include <filesystem>
#include <string>

namespace lastcut::daemon {

// Empty when the file looks complete, otherwise the reason in an operator's words
// ("the file is cut off (binary STL announces 5000 triangles, holds 120)").
std::string scan_incompleteness(const std::filesystem::path& scan);

}  // namespace lastcut::daemon
