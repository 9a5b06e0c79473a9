#pragma once
// The batching rule of every station, on a spool or on the shop's ledger ([batch] window_s and
// max_pieces, docs/daemon.md): computed jobs of one material and cutter are nested together;
// taken oldest first, a group closes as soon as its pieces reach max_pieces (so a batch never
// grows past what the table holds by more than its last job), and the group still open is due
// once its oldest job has waited window_s. window_s = 0 nests every job alone at once, however
// many wait together;
// max_pieces = 0 sets no piece limit. A pure function of the waiting jobs and the clock: the
// spool calls it each turn of its main loop, the ledger inside the transaction that forms a batch.
#include <string>
#include <vector>

#include "daemon/config/daemon_config.hpp"

namespace lastcut::daemon {

struct WaitingJob {
  std::string id;
  std::string material;
  std::string cutter;
  int pieces = 1;       // the job's pieces (molds x quantity); 0 counts as 1
  double waited_s = 0;  // since it was computed
};

struct DueBatch {
  std::string material;
  std::string cutter;
  std::vector<std::string> job_ids;  // oldest first
  int pieces = 0;
};

// `waiting` oldest first. The due batches, groups in the order of their oldest job; `force` makes
// every open group due (a stopping station, a test).
std::vector<DueBatch> due_batches(const std::vector<WaitingJob>& waiting, const BatchConfig& rule, bool force = false);

}  // namespace lastcut::daemon
