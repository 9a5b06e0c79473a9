// The ledger client: connecting, node registration, and the job half of the queue (enqueue,
// claim, renew, computed/failed, the operator's requeue, the status listing).
#include <pqxx/pqxx>

#include "daemon/ledger/ledger_transaction.hpp"

namespace lastcut::ledger {

std::string to_string(LeaseKind kind) { return kind == LeaseKind::Job ? "job" : "batch"; }

std::string id_array(const std::vector<long long>& ids) {
  std::string out = "{";
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + std::to_string(ids[i]);
  return out + "}";
}

std::string text_array(const std::vector<std::string>& items) {
  std::string out = "{";
  for (std::size_t i = 0; i < items.size(); ++i) {
    out += i ? ",\"" : "\"";
    for (char c : items[i]) {
      if (c == '"' || c == '\\') out += '\\';  // array-literal quoting
      out += c;
    }
    out += '"';
  }
  return out + "}";
}

Status check_lease(pqxx::work& tx, const std::string& node, const Lease& lease) {
  const std::string what = to_string(lease.kind) + " " + std::to_string(lease.object_id);
  const pqxx::result row = tx.exec_params(
      "SELECT holder, epoch FROM leases WHERE kind = $1 AND object_id = $2 FOR UPDATE", to_string(lease.kind),
      lease.object_id);
  if (row.empty()) return Status::failure("lease lost: " + what + " was never claimed");
  const long long epoch = row[0][1].as<long long>();
  if (row[0][0].is_null()) {
    return Status::failure("lease lost: " + what + " went back to the queue after this node's lease expired");
  }
  const std::string holder = row[0][0].as<std::string>();
  if (holder != node || epoch != lease.epoch) {
    return Status::failure("lease lost: " + what + " is now held by " + holder + " (epoch " + std::to_string(epoch) +
                           ", this node's claim was epoch " + std::to_string(lease.epoch) + ")");
  }
  return Status::success();
}

long long take_lease(pqxx::work& tx, const std::string& node, LeaseKind kind, long long object_id, double lease_s) {
  return tx
      .exec_params1(
          "INSERT INTO leases (kind, object_id, holder, epoch, expires_at)"
          " VALUES ($1, $2, $3, 1, now() + make_interval(secs => $4))"
          " ON CONFLICT (kind, object_id) DO UPDATE"
          " SET holder = EXCLUDED.holder, epoch = leases.epoch + 1, expires_at = EXCLUDED.expires_at"
          " RETURNING epoch",
          to_string(kind), object_id, node, lease_s)[0]
      .as<long long>();
}

void release_lease(pqxx::work& tx, const Lease& lease) {
  tx.exec_params("UPDATE leases SET holder = NULL, expires_at = NULL WHERE kind = $1 AND object_id = $2",
                 to_string(lease.kind), lease.object_id);
}

void add_event(pqxx::work& tx, long long job_id, const std::string& node, const std::string& event,
               const std::string& detail) {
  tx.exec_params("INSERT INTO job_events (job_id, node, event, detail) VALUES ($1, $2, $3, $4)", job_id, node, event,
                 detail);
}

Result<std::unique_ptr<LedgerClient>> LedgerClient::connect(const std::string& url, const std::string& node) {
  std::unique_ptr<LedgerClient> client(new LedgerClient(url, node));
  if (Status opened = client->open(); !opened) return opened;
  return client;
}

LedgerClient::LedgerClient(std::string url, std::string node) : url_(std::move(url)), node_(std::move(node)) {}

LedgerClient::~LedgerClient() = default;

namespace {

// A database host that vanishes (a cut cable, not a refused port) must not hang a node for TCP's
// quarter of an hour: bounded connects, and keepalives plus a user timeout that end a call on a
// dead peer within about 10 s. Settings the URL gives itself are kept.
std::string with_time_limits(const std::string& url) {
  static const std::pair<const char*, const char*> kLimits[] = {
      {"connect_timeout", "5"}, {"keepalives", "1"},        {"keepalives_idle", "5"},
      {"keepalives_interval", "2"}, {"keepalives_count", "3"}, {"tcp_user_timeout", "10000"}};
  const bool uri = url.find("://") != std::string::npos;
  std::string out = url;
  for (const auto& [key, value] : kLimits) {
    if (url.find(std::string(key) + "=") != std::string::npos) continue;
    if (uri) out += (out.find('?') == std::string::npos ? "?" : "&") + std::string(key) + "=" + value;
    else out += " " + std::string(key) + "=" + value;
  }
  return out;
}

}  // namespace

Status LedgerClient::open() {
  if (connection_ && connection_->is_open()) return Status::success();
  connection_.reset();
  return guarded<bool>("connecting to " + redact_url(url_), [&]() -> Result<bool> {
           connection_ = std::make_unique<pqxx::connection>(with_time_limits(url_));
           return true;
         })
      .status();
}

Result<MigrationOutcome> LedgerClient::migrate() {
  if (Status opened = open(); !opened) return opened;
  return apply_migrations(*connection_);
}

Result<int> LedgerClient::schema_version() {
  if (Status opened = open(); !opened) return opened;
  return read_schema_version(*connection_);
}

Status LedgerClient::heartbeat() {
  return transact<bool>("recording this node's heartbeat", [&](pqxx::work& tx) -> Result<bool> {
           tx.exec_params("UPDATE nodes SET heartbeat_at = now() WHERE name = $1", node_);
           return true;
         })
      .status();
}

std::string job_folder_name(const std::string& scan_sha256, long long job_id, long long duplicate_of) {
  return duplicate_of == 0 ? scan_sha256 : scan_sha256 + "-" + std::to_string(job_id);
}

Result<Enqueued> LedgerClient::enqueue(const ScanEntry& scan, OnDuplicate on_duplicate) {
  return transact<Enqueued>("entering scan " + scan.scan_name, [&](pqxx::work& tx) -> Result<Enqueued> {
    // ON CONFLICT waits for a node inserting the same bytes at this moment, then finds its row.
    const pqxx::result inserted = tx.exec_params(
        "INSERT INTO jobs (scan_sha256, scan_name, ticket, material, cutter, state, origin)"
        " VALUES ($1, $2, $3, $4, $5, 'ready', $6)"
        " ON CONFLICT (scan_sha256) WHERE duplicate_of IS NULL DO NOTHING RETURNING id",
        scan.scan_sha256, scan.scan_name, scan.ticket, scan.material, scan.cutter, node_);
    Enqueued out;
    if (!inserted.empty()) {
      out.job_id = inserted[0][0].as<long long>();
      out.state = "ready";
      out.origin = node_;
      add_event(tx, out.job_id, node_, "entered", scan.scan_name);
      return out;
    }
    const pqxx::row first = tx.exec_params1(
        "SELECT id, state, origin FROM jobs WHERE scan_sha256 = $1 AND duplicate_of IS NULL", scan.scan_sha256);
    out.duplicate = true;
    out.duplicate_of = first[0].as<long long>();
    const std::string same = "same scan bytes as job " + std::to_string(out.duplicate_of);
    if (on_duplicate == OnDuplicate::Skip) {
      out.job_id = out.duplicate_of;
      out.state = first[1].as<std::string>();
      out.origin = first[2].as<std::string>();
      add_event(tx, out.job_id, node_, "duplicate", scan.scan_name + " dropped again");
      return out;
    }
    const bool hold = on_duplicate == OnDuplicate::Hold;
    out.state = hold ? "held" : "ready";
    out.reason = hold ? same + " (duplicate held by policy)" : "";
    out.origin = node_;
    out.job_id = tx.exec_params1(
                       "INSERT INTO jobs (scan_sha256, scan_name, ticket, material, cutter, state, origin, reason,"
                       " duplicate_of) VALUES ($1, $2, $3, $4, $5, $6, $7, nullif($8, ''), $9) RETURNING id",
                       scan.scan_sha256, scan.scan_name, scan.ticket, scan.material, scan.cutter, out.state, node_,
                       out.reason, out.duplicate_of)[0]
                     .as<long long>();
    add_event(tx, out.job_id, node_, "entered", scan.scan_name + ": " + same + (hold ? ", held" : ", processed again"));
    return out;
  });
}

Result<std::optional<JobClaim>> LedgerClient::claim_job(double lease_s) {
  using Claim = std::optional<JobClaim>;
  return transact<Claim>("claiming a job", [&](pqxx::work& tx) -> Result<Claim> {
    const pqxx::result found = tx.exec(
        "SELECT id, scan_sha256, scan_name, ticket, material, cutter, coalesce(duplicate_of, 0) FROM jobs"
        " WHERE state = 'ready' ORDER BY created_at, id LIMIT 1 FOR UPDATE SKIP LOCKED");
    if (found.empty()) return Claim();
    JobClaim claim;
    claim.job_id = found[0][0].as<long long>();
    claim.scan = {found[0][1].as<std::string>(), found[0][2].as<std::string>(), found[0][3].as<std::string>(),
                  found[0][4].as<std::string>(), found[0][5].as<std::string>()};
    claim.job_folder = job_folder_name(claim.scan.scan_sha256, claim.job_id, found[0][6].as<long long>());
    claim.attempts = tx.exec_params1(
                           "UPDATE jobs SET state = 'computing', attempts = attempts + 1, updated_at = now()"
                           " WHERE id = $1 RETURNING attempts",
                           claim.job_id)[0]
                         .as<int>();
    claim.lease = {LeaseKind::Job, claim.job_id, take_lease(tx, node_, LeaseKind::Job, claim.job_id, lease_s)};
    add_event(tx, claim.job_id, node_, "claimed", "attempt " + std::to_string(claim.attempts));
    return Claim(std::move(claim));
  });
}

Status LedgerClient::renew(const Lease& lease, double lease_s) {
  return transact<bool>("renewing a lease", [&](pqxx::work& tx) -> Result<bool> {
           if (Status held = check_lease(tx, node_, lease); !held) return held;
           // An expired lease is not brought back, even before a sweep has taken it: a node cut off
           // longer than its lease must take its claim as lost, as its peers already may (found
           // as a race in finished_work_outage_test: the renewal after the outage beat the sweep).
           const pqxx::result renewed = tx.exec_params(
               "UPDATE leases SET expires_at = now() + make_interval(secs => $3) "
               "WHERE kind = $1 AND object_id = $2 AND expires_at > now()",
               to_string(lease.kind), lease.object_id, lease_s);
           if (renewed.affected_rows() == 0) {
             return Status::failure("lease lost: " + to_string(lease.kind) + " " + std::to_string(lease.object_id) +
                                    " expired before this node could renew it");
           }
           return true;
         })
      .status();
}

Status LedgerClient::mark_computed(const Lease& lease, int pieces, const std::vector<daemon::JobPart>& parts) {
  return transact<bool>("marking job " + std::to_string(lease.object_id) + " computed",
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          // A job cut in part and computed again (a requeue) goes on where it was, as on a
                          // spool (JobState::take_parts): no piece already cut is cut again.
                          const pqxx::row row = tx.exec_params1(
                              "SELECT parts::text, part, material, cutter FROM jobs WHERE id = $1",
                              lease.object_id);
                          const daemon::ResumedParts resumed = daemon::resume_parts(
                              daemon::parts_from_json(nlohmann::json::parse(row[0].as<std::string>(), nullptr, false)),
                              row[1].as<int>(), parts, {row[2].as<std::string>(), row[3].as<std::string>(), pieces, {}});
                          tx.exec_params(
                              "UPDATE jobs SET state = 'computed', pieces = $2, parts = $3::jsonb, part = $4,"
                              " updated_at = now() WHERE id = $1",
                              lease.object_id, pieces, daemon::parts_to_json(resumed.parts).dump(), resumed.part);
                          tx.exec_params("UPDATE jobs SET material = parts -> part ->> 'material', cutter = parts -> part ->> 'cutter',"
                                         " pieces = (parts -> part ->> 'pieces')::integer"
                                         " WHERE id = $1 AND jsonb_array_length(parts) > 0",
                                         lease.object_id);
                          release_lease(tx, lease);
                          add_event(tx, lease.object_id, node_, "computed", daemon::describe_resumed(resumed));
                          return true;
                        })
      .status();
}

Status LedgerClient::mark_failed(const Lease& lease, const std::string& reason) {
  return end_job(lease, "failed", reason);
}

Status LedgerClient::mark_held(const Lease& lease, const std::string& reason) { return end_job(lease, "held", reason); }

Status LedgerClient::end_job(const Lease& lease, const std::string& state, const std::string& reason) {
  return transact<bool>("marking job " + std::to_string(lease.object_id) + " " + state,
                        [&](pqxx::work& tx) -> Result<bool> {
                          if (Status held = check_lease(tx, node_, lease); !held) return held;
                          tx.exec_params(
                              "UPDATE jobs SET state = $3, reason = $2, updated_at = now() WHERE id = $1",
                              lease.object_id, reason, state);
                          release_lease(tx, lease);
                          add_event(tx, lease.object_id, node_, state, reason);
                          return true;
                        })
      .status();
}

Status LedgerClient::requeue_held(long long job_id) {
  const std::string what = "job " + std::to_string(job_id);
  return transact<bool>("requeueing " + what, [&](pqxx::work& tx) -> Result<bool> {
           const pqxx::result row = tx.exec_params("SELECT state FROM jobs WHERE id = $1 FOR UPDATE", job_id);
           if (row.empty()) return Status::failure("no " + what + " in the ledger");
           const std::string state = row[0][0].as<std::string>();
           if (state != "held" && state != "failed") {
             return Status::failure(what + " is " + state + ", neither held nor failed: nothing to requeue");
           }
           // Computed again from its scan: the molds of an interrupted batch are not trusted blindly.
           tx.exec_params(
               "UPDATE jobs SET state = 'ready', batch_id = NULL, attempts = 0, reason = NULL, updated_at = now()"
               " WHERE id = $1",
               job_id);
           add_event(tx, job_id, node_, "requeued", "by the operator (was " + state + ")");
           return true;
         })
      .status();
}

Result<std::vector<JobRow>> LedgerClient::recent_jobs(int limit, const std::string& state) {
  using Rows = std::vector<JobRow>;
  return transact<Rows>("listing jobs", [&](pqxx::work& tx) -> Result<Rows> {
    const pqxx::result found = tx.exec_params(
        "SELECT j.id, j.scan_name, j.state, j.cutter, j.material, j.origin, coalesce(j.reason, ''),"
        " coalesce(l.holder, ''), coalesce(j.batch_id, 0), j.attempts, j.parts::text, j.part"
        " FROM jobs j LEFT JOIN leases l ON l.kind = 'job' AND l.object_id = j.id"
        " WHERE $2 = '' OR j.state = $2 ORDER BY j.id DESC LIMIT $1",
        limit, state);
    Rows rows;
    for (const pqxx::row& r : found) {
      rows.push_back({r[0].as<long long>(), r[1].as<std::string>(), r[2].as<std::string>(), r[3].as<std::string>(),
                      r[4].as<std::string>(), r[5].as<std::string>(), r[6].as<std::string>(), r[7].as<std::string>(),
                      r[8].as<long long>(), r[9].as<int>(),
                      daemon::parts_from_json(nlohmann::json::parse(r[10].as<std::string>(), nullptr, false)),
                      r[11].as<int>()});
    }
    return rows;
  });
}

Result<JobDetail> LedgerClient::job_detail(long long job_id) {
  return transact<JobDetail>("reading job " + std::to_string(job_id), [&](pqxx::work& tx) -> Result<JobDetail> {
    const pqxx::result row = tx.exec_params(
        "SELECT state, coalesce(reason, ''), scan_sha256, coalesce(duplicate_of, 0) FROM jobs WHERE id = $1", job_id);
    if (row.empty()) return Status::failure("no job " + std::to_string(job_id) + " in the ledger");
    JobDetail out;
    out.state = row[0][0].as<std::string>();
    out.reason = row[0][1].as<std::string>();
    out.job_folder = job_folder_name(row[0][2].as<std::string>(), job_id, row[0][3].as<long long>());
    for (const pqxx::row& r : tx.exec_params(
             "SELECT to_char(at AT TIME ZONE 'UTC', 'YYYY-MM-DD\"T\"HH24:MI:SS.MS\"Z\"'), node, event, detail"
             " FROM job_events WHERE job_id = $1 ORDER BY id",
             job_id)) {
      out.history.push_back({r[0].as<std::string>(), r[1].as<std::string>(), r[2].as<std::string>(), r[3].as<std::string>()});
    }
    return out;
  });
}

}  // namespace lastcut::ledger
