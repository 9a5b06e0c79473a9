#include "tests/station/left_batches.hpp"

#include <cstdio>
#include <functional>

#include <nlohmann/json.hpp>
#include <pqxx/pqxx>

#include "tests/daemon/daemon_harness.hpp"

namespace lastcut::daemon::testing {

std::string leave_spool_batch(const std::filesystem::path& spool, int serial, LeftBatch kind, const std::string& scan,
                              const std::string& cut_program) {
  char id[32], batch_id[32];
  std::snprintf(id, sizeof(id), "20200101-000000-%03d", serial);
  std::snprintf(batch_id, sizeof(batch_id), "B20200101-000001-%03d", serial);
  const auto job_dir = spool / "work" / id;
  std::filesystem::create_directories(job_dir);
  write_text(job_dir / scan, "solid left\nendsolid left\n");
  const nlohmann::json state{{"id", id},          {"scan", scan},  {"stage", "batched"},
                             {"batch", batch_id}, {"pieces", 2},   {"ticket", {{"material", "calf"}, {"cutter", "cutter-1"}}},
                             {"history", nlohmann::json::array()}};
  write_text(job_dir / "state.json", state.dump(2));
  const auto batch_dir = spool / "batches" / batch_id;
  std::filesystem::create_directories(batch_dir);
  write_text(batch_dir / "cut.plt", cut_program);
  const nlohmann::json batch{{"id", batch_id},  {"material", "calf"},     {"cutter", "cutter-1"},
                             {"jobs", {id}},    {"cut_file", "cut.plt"},  {"pieces", 2},
                             {"stage", kind == LeftBatch::Queued ? "queued" : "xyz"}};
  write_text(batch_dir / "batch.json", batch.dump(2));
  return batch_id;
}

std::string leave_ledger_batch(const std::string& url, const std::filesystem::path& shared_dir, LeftBatch kind,
                               const std::string& scan, const std::string& cut_program) {
  pqxx::connection connection(url);
  pqxx::work tx(connection);
  const bool queued = kind == LeftBatch::Queued;
  const auto batch_id = tx.exec_params1(
                              "INSERT INTO batches (cutter, material, state, created_by, pieces)"
                              " VALUES ('cutter-1', 'calf', $1, 'station-gone', 2) RETURNING id",
                              queued ? "queued" : "sending")[0]
                            .as<std::string>();
  const std::string cut_file = "batches/" + batch_id + "/cut.plt";
  std::filesystem::create_directories(shared_dir / "batches" / batch_id);
  write_text(shared_dir / cut_file, cut_program);
  tx.exec_params("UPDATE batches SET cut_file = $2 WHERE id = $1", batch_id, cut_file);
  // Bytes of its own per scan name: 64 hex digits.
  char hash[17];
  std::snprintf(hash, sizeof(hash), "%016zx", std::hash<std::string>{}(scan));
  const std::string sha256 = std::string(hash) + hash + hash + hash;
  tx.exec_params(
      "INSERT INTO jobs (scan_sha256, scan_name, material, cutter, state, batch_id, origin, pieces)"
      " VALUES ($1, $2, 'calf', 'cutter-1', 'batched', $3, 'station-gone', 2)",
      sha256, scan, batch_id);
  if (!queued) {
    // station-gone marked it `sending` and vanished: its lease ran out a second ago.
    tx.exec_params(
        "INSERT INTO leases (kind, object_id, holder, epoch, expires_at)"
        " VALUES ('batch', $1, 'station-gone', 1, now() - interval '1 second')",
        batch_id);
  }
  tx.commit();
  return batch_id;
}

}  // namespace lastcut::daemon::testing
