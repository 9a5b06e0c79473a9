// lastcutd: the unattended watch-folder daemon. Scans dropped into the watch folder become
// molds, nested layouts and cut files, sent to the configured cutters; every job stays in the
// spool (done/, failed/, held/). See docs/daemon.md. With [ledger] it runs as one node of a shop
// sharing a PostgreSQL job ledger instead (docs/multi-station.md).
//
//   lastcutd --config /etc/lastcut/lastcut.toml      run (under systemd: Type=notify)
//   lastcutd --check-config FILE                      validate a configuration and exit
//
// Exit codes: 0 clean stop, 1 start failed (--check-config: [ledger] unusable), 78 (EX_CONFIG) bad configuration.
#include <poll.h>

#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <tuple>
#include <vector>

#include <CLI/CLI.hpp>
#include <spdlog/spdlog.h>

#include "daemon/config/config_loader.hpp"
#include "daemon/job/observer_list.hpp"
#include "daemon/ledger/ledger_check.hpp"
#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/spool_store/spool_store.hpp"
#include "daemon/service/operator_log.hpp"
#include "daemon/station/station.hpp"
#include "daemon/service/signal_events.hpp"
#include "daemon/service/systemd_notify.hpp"
#include "daemon/status/mqtt_client.hpp"
#include "daemon/status/mqtt_status.hpp"
#include "daemon/web/live_events.hpp"
#include "daemon/web/web_server.hpp"

namespace {

constexpr int kExitConfig = 78;
// EX_SOFTWARE: an internal error stopped the daemon (systemd restarts it; 78 it does not).
constexpr int kExitInternal = 70;

int check_config(const std::string& file) {
  const auto result = lastcut::daemon::load_daemon_config(file);
  if (!result.config) {
    std::fprintf(stderr, "%s\n", result.error.c_str());
    return kExitConfig;
  }
  const auto& config = *result.config;
  std::printf("%s: valid; watch %s, spool %s, %zu material(s), %zu cutter(s)\n", file.c_str(),
              config.paths.watch_dir.c_str(), config.paths.spool_dir.c_str(), config.materials.size(),
              config.cutters.size());
  if (config.status.enabled) {
    // A broker that is away is no configuration error (lastcutd retries), so the exit stays 0.
    const lastcut::Status reached = lastcut::daemon::check_broker(config.status, 3.0);
    const std::string answer =
        reached ? "reachable, station " + config.status.station : "NOT reachable: " + reached.error();
    std::printf("status: MQTT broker %s %s\n", config.status.mqtt_url.c_str(), answer.c_str());
  }
  if (config.ledger) {
    const auto ledger = lastcut::ledger::check_ledger(config.ledger->url, config.ledger->node);
    if (!ledger) {
      std::fprintf(stderr, "%s\n", ledger.error().c_str());
      return 1;
    }
    std::printf("%s\n", ledger->c_str());
  }
  return 0;
}

void reload(const std::string& file, lastcut::daemon::JobFlow& station, lastcut::daemon::SystemdNotifier& notifier,
            const lastcut::daemon::StatusConfig& running_status) {
  notifier.reloading();
  const auto result = lastcut::daemon::load_daemon_config(file);
  if (!result.config) {
    spdlog::error("reload refused, the running configuration stays: {}", result.error);
  } else {
    lastcut::daemon::set_operator_log_level(result.config->log.level);
    const std::string kept = station.reload(std::make_shared<lastcut::daemon::DaemonConfig>(*result.config));
    spdlog::info("configuration reloaded from {}{}", file, kept.empty() ? "" : "; " + kept);
    const auto& next = result.config->status;
    if (std::tie(next.enabled, next.mqtt_url, next.station, next.topic_prefix, next.username, next.password,
                 next.ca_file, next.keepalive_s, next.queue_limit) !=
        std::tie(running_status.enabled, running_status.mqtt_url, running_status.station, running_status.topic_prefix,
                 running_status.username, running_status.password, running_status.ca_file,
                 running_status.keepalive_s, running_status.queue_limit)) {
      spdlog::warn("[status] changed: the running MQTT status stays until lastcutd is restarted");
    }
  }
  notifier.ready();
}

// The flow is one Station (daemon/station/station.hpp), on its own file spool (SpoolStore) or as a node
// of a shop on a shared PostgreSQL ledger (LedgerNode): the loop drives either the same way.
int serve(const std::string& file, lastcut::daemon::JobFlow& station, lastcut::daemon::SignalEvents& signals,
          lastcut::daemon::SystemdNotifier& notifier, const lastcut::daemon::StatusConfig& running_status,
          lastcut::daemon::StatusObserver* observer) {
  station.set_observer(observer);
  if (lastcut::Status started = station.start(); !started) {
    spdlog::critical("lastcutd cannot start: {}", started.error());
    return 1;
  }
  notifier.ready();
  spdlog::info("lastcutd ready{}", notifier.watchdog_enabled() ? " (systemd watchdog on)" : "");

  std::string reported_stuck;
  auto next_status = std::chrono::steady_clock::now();
  for (;;) {
    pollfd fds[2] = {{signals.fd(), POLLIN, 0}, {station.event_fd(), POLLIN, 0}};
    ::poll(fds, station.event_fd() >= 0 ? 2 : 1, 100);
    bool stop = false;
    for (auto event = signals.read(); event != lastcut::daemon::SignalEvent::None; event = signals.read()) {
      if (event == lastcut::daemon::SignalEvent::Stop) stop = true;
      else reload(file, station, notifier, running_status);
    }
    if (stop) break;
    station.read_events();
    const auto now = std::chrono::steady_clock::now();
    station.tick(now);
    const std::string stuck = station.stuck(now);
    if (stuck.empty()) {
      notifier.feed_watchdog(now);
      if (!reported_stuck.empty()) spdlog::info("station moving again");
    } else if (stuck != reported_stuck) {
      spdlog::critical("{}: no longer feeding the systemd watchdog, lastcutd will be restarted", stuck);
    }
    reported_stuck = stuck;
    if (now >= next_status) {
      notifier.status(station.status_line());
      next_status = now + std::chrono::seconds(2);
    }
  }
  notifier.stopping();
  spdlog::info("lastcutd stopping: finishing or holding the jobs in hand");
  station.stop();
  return 0;
}

int run(const std::string& file) {
  // Before any thread starts, so that every thread inherits the blocked signals.
  lastcut::daemon::SignalEvents signals;
  const auto loaded = lastcut::daemon::load_daemon_config(file);
  if (!loaded.config) {
    std::fprintf(stderr, "lastcutd: configuration refused:\n%s\n", loaded.error.c_str());
    return kExitConfig;
  }
  lastcut::daemon::setup_operator_log(loaded.config->log.level);
  spdlog::info("lastcutd starting with {}", file);
  lastcut::daemon::SystemdNotifier notifier;
  // Live status first and stopped last, so that it sees recovery and the final state of the cutters.
  std::unique_ptr<lastcut::daemon::MqttStatus> live_status;
  if (loaded.config->status.enabled) {
    std::vector<std::string> cutters;
    for (const auto& [name, cutter] : loaded.config->cutters) {
      // A ledger node shows only the cutters cabled to it; the others belong to their own stations.
      if (!loaded.config->ledger || loaded.config->ledger->owns_cutter(name)) cutters.push_back(name);
    }
    live_status = std::make_unique<lastcut::daemon::MqttStatus>(loaded.config->status, cutters);
    if (lastcut::Status started = live_status->start(); !started) {
      spdlog::critical("lastcutd cannot start: {}", started.error());
      return 1;
    }
  }
  const auto config = std::make_shared<lastcut::daemon::DaemonConfig>(*loaded.config);
  // The cutters an operator paused from the page, before the page and the station that use them.
  lastcut::daemon::CutterPauses pauses(config->paths.spool_dir / "paused-cutters.json");
  // The operator's page next, so that it too sees recovery; stopped after the station.
  lastcut::daemon::LiveEvents live_events;
  std::unique_ptr<lastcut::daemon::WebServer> web;
  if (config->web) {
    web = std::make_unique<lastcut::daemon::WebServer>(config, live_events, pauses);
    if (lastcut::Status started = web->start(); !started) {
      spdlog::critical("lastcutd cannot start: {}", started.error());
      if (live_status) live_status->stop();
      return 1;
    }
  }
  lastcut::daemon::ObserverList observers;
  observers.add(live_status.get());
  if (web) observers.add(&live_events);
  std::unique_ptr<lastcut::daemon::JobFlow> flow;
  // One station; its store is the shop's ledger with [ledger], else this station's own spool.
  const bool on_ledger = config->ledger.has_value();
  flow = std::make_unique<lastcut::daemon::Station>(
      config, [on_ledger](const lastcut::daemon::RunningConfig& running) -> std::unique_ptr<lastcut::daemon::StationStore> {
        if (on_ledger) return std::make_unique<lastcut::daemon::LedgerNode>(running);
        return std::make_unique<lastcut::daemon::SpoolStore>(running);
      },
      &pauses);
  int code = 0;
  try {
    code = serve(file, *flow, signals, notifier, loaded.config->status, observers.empty() ? nullptr : &observers);
  } catch (const std::exception& error) {
    // A bug in the loop's own steps (the engine's are caught per job). Stop in order, holding the jobs
    // in hand, rather than abort; systemd starts lastcutd again (Restart=on-failure).
    spdlog::critical("lastcutd stops on an internal error, please report it: {}", error.what());
    notifier.stopping();
    code = kExitInternal;
  }
  flow.reset();
  if (web) web->stop();
  if (live_status) live_status->stop();
  spdlog::info("lastcutd stopped");
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"lastcutd: watch-folder daemon turning shoe-last scans into cut jobs"};
  std::string config_file = "/etc/lastcut/lastcut.toml";
  std::string check_file;
  app.add_option("-c,--config", config_file, "configuration file (TOML)");
  app.add_option("--check-config", check_file, "validate this configuration file and exit");
  CLI11_PARSE(app, argc, argv);
  if (!check_file.empty()) return check_config(check_file);
  return run(config_file);
}
