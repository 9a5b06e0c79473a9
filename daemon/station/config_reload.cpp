#include "daemon/station/config_reload.hpp"

namespace lastcut::daemon {
namespace {

bool same_ledger(const std::optional<LedgerConfig>& a, const std::optional<LedgerConfig>& b) {
  if (a.has_value() != b.has_value()) return false;
  if (!a) return true;
  return a->url == b->url && a->node == b->node && a->roles == b->roles && a->shared_dir == b->shared_dir &&
         a->lease_s == b->lease_s && a->heartbeat_s == b->heartbeat_s && a->cutters == b->cutters;
}

}  // namespace

ReloadedConfig merge_reloaded_config(const DaemonConfig& running, const DaemonConfig& next) {
  std::string kept;
  const auto keep = [&](bool changed, const char* what) {
    if (changed) kept += std::string(kept.empty() ? "" : ", ") + what;
  };
  keep(next.paths.watch_dir != running.paths.watch_dir, "paths.watch");
  keep(next.paths.spool_dir != running.paths.spool_dir, "paths.spool");
  keep(next.paths.hides_dir != running.paths.hides_dir, "paths.hides");
  keep(next.watch.mode != running.watch.mode, "watch.mode");
  keep(next.jobs.compute_workers != running.jobs.compute_workers, "jobs.compute_workers");
  bool same_cutters = next.cutters.size() == running.cutters.size();
  for (const auto& [name, section] : next.cutters) same_cutters = same_cutters && running.cutters.count(name);
  keep(!same_cutters, "the list of cutters");
  keep(!same_ledger(next.ledger, running.ledger), "[ledger]");
  auto merged = std::make_shared<DaemonConfig>(next);
  merged->paths = running.paths;
  merged->watch = running.watch;
  merged->jobs.compute_workers = running.jobs.compute_workers;
  if (!same_cutters) merged->cutters = running.cutters;
  merged->ledger = running.ledger;
  return {merged, kept.empty() ? "" : kept + " changed: kept the running value until restart"};
}

}  // namespace lastcut::daemon
