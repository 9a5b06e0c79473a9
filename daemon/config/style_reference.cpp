#include "daemon/config/style_reference.hpp"

#include <stdlib.h>

#include <filesystem>
#include <string>
#include <system_error>

#include "daemon/config/style_forme.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"

namespace lastcut::daemon {
namespace {

namespace fs = std::filesystem;

// A folder of its own under the system's temp folder for a generated reference last, removed with it:
// the style folder may be read-only (/etc/lastcut/styles).
class ScratchFolder {
 public:
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "lastcut-style-reference-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) throw EngineError("cannot make a scratch folder like " + pattern);
    path_ = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;  // a leftover scratch file is harmless
    fs::remove_all(path_, ignored);
  }
  ScratchFolder(const ScratchFolder&) = delete;
  ScratchFolder& operator=(const ScratchFolder&) = delete;
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

ScanResult segmented(const fs::path& scan, FootSide side) {
  ScanOptions options;
  options.side = side;
  return scan_to_molds(scan, options);
}

// The style's reference last through the scan-to-molds pipeline, its halves named by its side.
ScanResult segmented_reference(const StyleFolder& folder) {
  if (!folder.generated_reference) return segmented(folder.reference_scan, folder.reference_side);
  const ScratchFolder scratch;
  write_stl_binary(scratch.path() / "reference.stl", generate_last(*folder.generated_reference).mesh);
  return segmented(scratch.path() / "reference.stl", folder.reference_side);
}

}  // namespace

ScanResult prepare_style_reference(StyleFolder& folder) {
  ScanResult reference = segmented_reference(folder);
  if (const Status lifted = lift_forme_style(folder, reference); !lifted) throw EngineError(lifted.error());
  return reference;
}

}  // namespace lastcut::daemon
