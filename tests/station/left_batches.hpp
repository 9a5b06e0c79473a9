#pragma once
// Batches the shared behaviour suite writes into a store itself, as something other than the running
// lastcutd leaves them (a crash, a hand edit, a node that vanished): see StationUnderTest::leave_batch.
#include <filesystem>
#include <string>

#include "tests/station/station_under_test.hpp"

namespace lastcut::daemon::testing {

// Into the spool folder `spool`: batches/BID/ (batch.json, cut.plt) and work/ID/ (the scan,
// state.json `batched`). `serial` makes the ids (ids of 2020, older than any the daemon makes).
// Returns the batch's id.
std::string leave_spool_batch(const std::filesystem::path& spool, int serial, LeftBatch kind, const std::string& scan,
                              const std::string& cut_program);

// Into the ledger at `url` over a connection of the test's own: a batch row (its cut file under
// `shared_dir`/batches/ID/), a job row `batched` in it, and for LeftBatch::Untrusted the batch's
// lease, held by "station-gone" and run out. Returns the batch's id.
std::string leave_ledger_batch(const std::string& url, const std::filesystem::path& shared_dir, LeftBatch kind,
                               const std::string& scan, const std::string& cut_program);

}  // namespace lastcut::daemon::testing
