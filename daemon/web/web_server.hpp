#pragma once
// WebServer: the operator's page that lastcutd serves when the configuration has [web]
// (docs/operator-page.md). It shows the store's overview (the same StoreView `lastcut status`
// reads: the station's spool, or the whole shop from the ledger), follows the station's changes
// live over Server-Sent Events (LiveEvents), serves a job's files by id, and takes the actions
// an operator needs without a shell: requeue a held job, put a hide on a cutter's table, pause and
// resume a cutter of this station (CutterPauses), cancel a batch that waits for its cutter. Actions
// need a token from [web.tokens]; every refusal is one log line. It runs on its own threads (the
// HTTP library's pool) and only reads the store or writes where an operator's command would, so
// the station never waits for it.
#include <memory>

#include "daemon/config/daemon_config.hpp"
#include "daemon/station/cutter_pauses.hpp"
#include "daemon/web/live_events.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

class WebServer {
 public:
  // `events` and `pauses` outlive the server.
  WebServer(std::shared_ptr<const DaemonConfig> config, LiveEvents& events, CutterPauses& pauses);
  ~WebServer();
  WebServer(const WebServer&) = delete;
  WebServer& operator=(const WebServer&) = delete;

  // Binds [web].listen and starts serving; why not when the address cannot be bound.
  Status start();
  // The port bound (the configured one, or the one the system chose for port 0).
  int port() const;
  // Ends every live stream and stops serving; returns when the server's threads are done.
  void stop();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace lastcut::daemon
