// place_hide (hide_placement.hpp).
#include "daemon/hides/hide_placement.hpp"

#include <cstdio>
#include <sstream>

#include <toml++/toml.h>

#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {

Result<std::string> place_hide(const DaemonConfig& config, const std::filesystem::path& source,
                               const std::string& file_name, const std::string& cutter, const std::string& written_by) {
  if (config.paths.hides_dir.empty()) return Status::failure("the configuration names no paths.hides folder");
  if (!config.cutters.count(cutter)) return Status::failure("cutter \"" + cutter + "\" is not configured");
  const std::string extension = std::filesystem::path(file_name).extension().string();
  if (extension != ".dxf" && extension != ".json")
    return Status::failure("a hide file is .dxf or .json, not \"" + file_name + "\"");
  HideFile hide;
  try {
    hide = read_hide_file(source);
  } catch (const EngineError& failure) {
    return Status::failure(failure.what());
  }
  const auto target = config.paths.hides_dir / file_name;
  const auto sidecar = hide_sidecar_path(target);
  std::error_code error;
  if (std::filesystem::exists(target, error) || std::filesystem::exists(sidecar, error))
    return Status::failure("hide " + file_name + " is already waiting in " + config.paths.hides_dir.string());
  toml::table table;
  table.insert("id", hide.hide_id);
  if (!hide.material.empty()) table.insert("material", hide.material);
  if (hide.thickness_mm) table.insert("thickness_mm", *hide.thickness_mm);
  table.insert("cutter", cutter);
  std::ostringstream text;
  text << "# written by " << written_by << "\n" << table << "\n";
  std::filesystem::create_directories(config.paths.hides_dir, error);
  if (Status written = write_file_durably(sidecar, text.str()); !written) return written;
  if (Status copied = copy_file_durably(source, target); !copied) return copied;
  char area[32];
  std::snprintf(area, sizeof area, "%.2f", hide.area_m2);
  return "hide " + hide.hide_id + " (" + file_name + ", " + area + " m^2) now lies on cutter " + cutter + ": " +
         target.string();
}

}  // namespace lastcut::daemon
