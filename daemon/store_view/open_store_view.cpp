// The StoreView a configuration names: the shop's ledger with [ledger], else the station's spool.
#include "daemon/config/config_loader.hpp"
#include "daemon/store_view/store_view.hpp"

namespace lastcut::daemon {

std::unique_ptr<StoreView> open_store_view(const DaemonConfig& config) {
  if (config.ledger) {
    std::vector<std::string> hide_materials;
    for (const auto& [name, material] : config.materials)
      if (material.kind == MaterialKind::Hide) hide_materials.push_back(name);
    return make_ledger_view(*config.ledger, std::move(hide_materials));
  }
  return make_spool_view(config.paths.spool_dir.string());
}

Result<std::unique_ptr<StoreView>> open_store_view(const std::string& config_file, const std::string& spool_dir) {
  if (!spool_dir.empty()) return make_spool_view(spool_dir);
  const auto loaded = load_daemon_config(config_file);
  if (!loaded.config) return Status::failure(loaded.error);
  return open_store_view(*loaded.config);
}

}  // namespace lastcut::daemon
