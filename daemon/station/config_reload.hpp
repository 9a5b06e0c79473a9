#pragma once
// SIGHUP on any station (spool or ledger node): which part of a new, already validated
// configuration applies while running. What the running threads and folders were built from waits
// for a restart: the paths, the watch mode, the number of compute workers, the set of cutters and
// the [ledger] table (the node's name, roles, database and shared folder); everything else (batch
// rule, materials, cutter settings, review tolerance, ...) applies at once.
#include <memory>
#include <mutex>
#include <string>

#include "daemon/config/daemon_config.hpp"

namespace lastcut::daemon {

struct ReloadedConfig {
  std::shared_ptr<const DaemonConfig> config;  // `next`, with the restart-only parts of `running`
  std::string kept;  // "" when all of `next` applies; else "paths.watch, ... changed: kept the running value until restart"
};

ReloadedConfig merge_reloaded_config(const DaemonConfig& running, const DaemonConfig& next);

}  // namespace lastcut::daemon

namespace lastcut::daemon {

// The configuration a station runs with, read by all its threads and replaced by SIGHUP.
class RunningConfig {
 public:
  explicit RunningConfig(std::shared_ptr<const DaemonConfig> config) : config_(std::move(config)) {}
  std::shared_ptr<const DaemonConfig> get() const {
    std::lock_guard lock(mutex_);
    return config_;
  }
  // The named cutter's current section: empty ({}) once a reload removed it.
  CutterSection cutter_section(const std::string& name) const {
    const auto current = get();
    const auto it = current->cutters.find(name);
    return it != current->cutters.end() ? it->second : CutterSection{};
  }
  // Applies what applies while running; returns the line of what waits for a restart.
  std::string reload(const DaemonConfig& next) {
    std::lock_guard lock(mutex_);
    ReloadedConfig merged = merge_reloaded_config(*config_, next);
    config_ = std::move(merged.config);
    return merged.kept;
  }

 private:
  mutable std::mutex mutex_;
  std::shared_ptr<const DaemonConfig> config_;
};

}  // namespace lastcut::daemon
