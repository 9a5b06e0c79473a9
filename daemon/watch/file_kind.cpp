#include "daemon/watch/file_kind.hpp"

#include <algorithm>
#include <cctype>

#include "daemon/job/job_ticket.hpp"

namespace lastcut::daemon {
namespace {

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return std::tolower(c); });
  return text;
}

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool temporary_name(const std::string& name) {
  return name.empty() || name[0] == '.' || name.back() == '~' || ends_with(name, ".tmp") || ends_with(name, ".part") ||
         ends_with(name, ".crdownload") || ends_with(name, ".swp");
}

}  // namespace

FileKind classify_hide_file_name(const std::string& file_name) {
  const std::string name = lower(file_name);
  if (temporary_name(name)) return FileKind::Temporary;
  if (ends_with(name, ".toml")) return FileKind::Sidecar;
  if (ends_with(name, ".dxf") || ends_with(name, ".json")) return FileKind::Scan;
  return FileKind::Unsupported;
}

std::filesystem::path hide_sidecar(const std::filesystem::path& hide_file) {
  const std::filesystem::path sidecar = hide_file.parent_path() / (hide_file.stem().string() + ".toml");
  std::error_code error;
  return std::filesystem::is_regular_file(sidecar, error) ? sidecar : std::filesystem::path();
}

FileKind classify_file_name(const std::string& file_name) {
  const std::string name = lower(file_name);
  if (temporary_name(name)) return FileKind::Temporary;
  if (is_sidecar_name(name)) return FileKind::Sidecar;
  // A DXF is a pattern set (DXF-AAMA) a pattern room sends: a job of its own, like a scan.
  for (const char* extension : {".stl", ".obj", ".ply", ".off", ".dxf"}) {
    if (ends_with(name, extension)) return FileKind::Scan;
  }
  return FileKind::Unsupported;
}

}  // namespace lastcut::daemon
