#include "daemon/watch/file_kind.hpp"

#include <algorithm>
#include <cctype>

#include "daemon/spool/job_ticket.hpp"

namespace lastcut::daemon {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

}  // namespace

FileKind classify_file_name(const std::string& file_name) {
  const std::string name = lower(file_name);
  if (name.empty() || name[0] == '.' || name.back() == '~' || ends_with(name, ".tmp") || ends_with(name, ".part") ||
      ends_with(name, ".crdownload") || ends_with(name, ".swp")) {
    return FileKind::Temporary;
  }
  if (is_sidecar_name(name)) return FileKind::Sidecar;
  for (const char* extension : {".stl", ".obj", ".ply", ".off"}) {
    if (ends_with(name, extension)) return FileKind::Scan;
  }
  return FileKind::Unsupported;
}

}  // namespace lastcut::daemon
