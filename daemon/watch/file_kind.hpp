#pragma once
// What a name in the watch folder is: a scan (or a DXF-AAMA pattern set, .dxf) to take, a sidecar that travels with a scan, or
// something the daemon leaves alone (hidden or temporary names that uploaders use while writing:
// .*, *.tmp, *.part, *~; names of other types).
#include <filesystem>
#include <string>

namespace lastcut::daemon {

enum class FileKind { Scan, Sidecar, Temporary, Unsupported };

FileKind classify_file_name(const std::string& file_name);
// The same for the hides folder: Scan stands for a hide file (.dxf, .json), Sidecar for NAME.toml.
FileKind classify_hide_file_name(const std::string& file_name);
// The sidecar of a hide file: NAME.toml beside NAME.dxf / NAME.json; empty path when none exists.
std::filesystem::path hide_sidecar(const std::filesystem::path& hide_file);

}  // namespace lastcut::daemon
