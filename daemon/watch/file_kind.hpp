#pragma once
// What a name in the watch folder is: a scan to take, a sidecar that travels with a scan, or
// something the daemon leaves alone (hidden or temporary names that uploaders use while writing:
// .*, *.tmp, *.part, *~; names of other types).
#include <string>

namespace lastcut::daemon {

enum class FileKind { Scan, Sidecar, Temporary, Unsupported };

FileKind classify_file_name(const std::string& file_name);

}  // namespace lastcut::daemon
