#pragma once
// SpoolCutStore: one cutter's batches on the spool of one station, for its CutterWorker
// (daemon/station/cutter_worker.hpp). The main thread queues the ids of nested batches; the worker
// claims them oldest first. batches/BID/batch.json and the state.json of each job in work/ say how
// far a batch got, written durably before the next step: `sending` before the first byte (so a
// crash holds it at recovery), then done/ or held/ together with the move out of work/. Queued
// batches stay in the spool when the daemon stops; recovery queues them again at the next start.
#include <deque>
#include <functional>
#include <mutex>
#include <string>

#include "daemon/spool/spool.hpp"
#include "daemon/station/cut_store.hpp"

namespace lastcut::daemon {

class SpoolCutStore : public CutStore {
 public:
  // `computed` hears of a job whose part was cut and whose next part now waits to be nested.
  SpoolCutStore(std::string cutter, const Spool& spool, std::function<void(const std::string&)> computed)
      : cutter_(std::move(cutter)), spool_(spool), computed_(std::move(computed)) {}

  // Main thread: a batch nested for this cutter (batch.json `queued`).
  void enqueue(const std::string& batch_id);
  std::size_t queued() const;

  std::optional<std::string> next_batch() override;
  Result<std::optional<CutOrder>> claim() override;
  Status mark_sending(const CutOrder& order) override;
  CutEnd record_end(const CutOrder& order, CutEnd end, const std::string& reason,
                    const std::vector<std::string>& cutter_answer) override;

 private:
  // A claimed batch goes back unsent, first in line.
  void give_back(const CutOrder& order);

  std::string cutter_;
  const Spool& spool_;
  std::function<void(const std::string&)> computed_;
  mutable std::mutex mutex_;
  std::deque<std::string> queue_;
};

}  // namespace lastcut::daemon
