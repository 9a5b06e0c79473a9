#pragma once
// The sweep of orphaned outputs in the shared folder: a batch folder (shared/batches/<id>) that no
// ledger row needs any more - its nesting was refused after the lease was lost (the batch was
// dissolved and its jobs regrouped under a new id), or it came back empty - is removed once it is
// older than a grace period, with one log line each. A batch still nesting, queued, being cut or
// done keeps its folder; scratch folders (<id>.part-...) are left alone.
#include <string>
#include <vector>

#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger_node/shared_store.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

// How old an orphaned folder must be (by its modification time) before the sweep removes it.
inline constexpr double kOrphanGrace_s = 600;

// Removes the orphaned batch folders older than `grace_s`; their names (ids), ascending. A
// folder that cannot be removed is logged and tried again at the next sweep.
Result<std::vector<std::string>> remove_orphan_batch_folders(ledger::LedgerClient& client, const SharedStore& shared,
                                                             double grace_s);

}  // namespace lastcut::daemon
