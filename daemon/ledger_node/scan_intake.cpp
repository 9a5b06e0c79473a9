// Intake on a ledger node (main thread): a ready scan from the watch folder is copied into the
// shared folder under its hash and entered in the ledger; bytes already entered on any node are
// skipped, held or processed again by [jobs] duplicate_policy, as on one station. Entered scans move to <spool>/entered/, refused ones (bad sidecar, unknown material or
// cutter, a cut-off file) to <spool>/failed/ with NAME.reason; while the ledger cannot be reached a
// scan stays in the watch folder and is offered again.
// Hides take the same path from the hides folder (docs/hides.md): checked as on one station (an
// open or self-intersecting outline, a zone outside the hide, unknown units, an absurd size are
// refused with the one line), copied into hides/<sha256>/ with their sidecar, entered as lying on
// their cutter's table; entered hide files move to <spool>/hides/.
#include <spdlog/spdlog.h>

#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/station/ticket_targets.hpp"
#include "daemon/job/job_ticket.hpp"
#include "daemon/job/sha256.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {
namespace {

// Moves the scan (and its sidecar) into `folder` of the node's spool; false with the log line when it cannot.
bool move_into(const std::filesystem::path& folder, const ReadyScan& ready) {
  std::error_code error;
  std::filesystem::create_directories(folder, error);
  for (const std::filesystem::path& file : {ready.scan, ready.sidecar}) {
    if (file.empty()) continue;
    if (Status moved = move_durably(file, folder / file.filename()); !moved) {
      spdlog::error("watch folder: {} cannot be moved to {}: {}", file.filename().string(), folder.string(),
                    moved.error());
      return false;
    }
  }
  return true;
}

// The ledger or the share away: nothing was entered, the file waits where it was dropped.
ledger::OnDuplicate on_duplicate(const DaemonConfig& config) {
  switch (config.jobs.duplicate_policy) {
    case DuplicatePolicy::Hold: return ledger::OnDuplicate::Hold;
    case DuplicatePolicy::Process: return ledger::OnDuplicate::Process;
    case DuplicatePolicy::Skip: break;
  }
  return ledger::OnDuplicate::Skip;
}

bool not_the_files_fault(const Status& entered) {
  return entered.error().rfind("ledger unreachable", 0) == 0 || entered.error().rfind("shared folder unusable", 0) == 0;
}

}  // namespace

StationStore::Intake LedgerNode::take_scan(const ReadyScan& ready) { return take(ready, scans_); }

StationStore::Intake LedgerNode::take_hide(const ReadyScan& ready) { return take(ready, hides_); }

StationStore::Intake LedgerNode::take(const ReadyScan& ready, DropFolder& intake) {
  const Status entered = (this->*intake.enter)(ready);
  if (!entered && not_the_files_fault(entered)) {
    // Not the file's fault and nothing was entered: it waits where it was dropped.
    note_trouble(intake.trouble, entered.error(), intake.name + ": files wait in the " + intake.name);
    return Intake::Later;
  }
  note_trouble(intake.trouble, "", intake.name);
  if (!entered) refuse(ready, entered.error());
  return Intake::Taken;
}

Status LedgerNode::enter(const ReadyScan& ready) {
  if (!ready.incompleteness.empty()) return Status::failure(ready.incompleteness);
  const auto settings = config();
  JobTicket ticket;
  if (!ready.sidecar.empty()) {
    Result<JobTicket> read = read_job_ticket(ready.sidecar);
    if (!read) return read.status();
    ticket = *read;
  }
  if (const std::string unknown_target = settle_ticket_targets(ticket, *settings, ready.scan); !unknown_target.empty())
    return Status::failure(unknown_target);
  const auto hash = sha256_file_hex(ready.scan);
  if (!hash) return Status::failure("the scan cannot be read (it vanished or is not readable)");
  const std::string name = ready.scan.filename().string();

  // The bytes first, then the row: a job in the ledger always finds its scan in the shared folder.
  const std::filesystem::path shared_scan = store_.scan(*hash, name);
  std::error_code exists_error;
  if (!std::filesystem::exists(shared_scan, exists_error)) {
    if (Status copied = copy_file_durably(ready.scan, shared_scan); !copied)
      return Status::failure("shared folder unusable: " + copied.error());
  }
  for (const auto& [mold, file] : ticket.references) {
    const std::filesystem::path from = ready.sidecar.parent_path() / file;
    const std::filesystem::path to = store_.references(*hash) / reference_copy_name(mold, file);
    std::error_code error;
    if (!std::filesystem::is_regular_file(from, error))
      return Status::failure("reference pattern " + file + " for the " + mold + " mold is not in the watch folder");
    std::filesystem::create_directories(to.parent_path(), error);
    if (Status copied = copy_file_durably(from, to); !copied)
      return Status::failure("shared folder unusable: reference pattern " + file + " not copied: " + copied.error());
  }
  const std::string ticket_json = ticket_to_json(ticket).dump();
  ledger::Enqueued job;
  const Status entered = journal_->change([&]() -> Result<LedgerJobChanges> {
    auto enqueued = client_->enqueue({*hash, name, ticket_json, ticket.material, ticket.cutter}, on_duplicate(*settings));
    if (!enqueued) return enqueued.status();
    job = *enqueued;
    if (!job.duplicate) {
      ++entered_;
      return LedgerJobChanges{{job.job_id, name, ticket_json, 0, JobStage::Claimed, "",
                               "entered in the ledger (material " + ticket.material + ", cutter " + ticket.cutter + ")"}};
    }
    ++duplicates_;
    const std::string same = "same scan bytes as job " + std::to_string(job.duplicate_of);
    switch (settings->jobs.duplicate_policy) {
      case DuplicatePolicy::Skip:
        spdlog::info("{}: {} (entered by {}, now {}) - not entered again (duplicate, skipped)", name, same, job.origin,
                     job.state);
        return LedgerJobChanges{};
      case DuplicatePolicy::Hold:
        return LedgerJobChanges{{job.job_id, name, ticket_json, 0, JobStage::Held, job.reason, ""}};
      case DuplicatePolicy::Process:
        return LedgerJobChanges{{job.job_id, name, ticket_json, 0, JobStage::Claimed, "", same + " - processed again (policy)"}};
    }
    return LedgerJobChanges{};
  });
  if (!entered) return entered;
  if (!move_into(settings->paths.spool_dir / "entered", ready)) {
    // Entered: offering it again would only find the duplicate, so nothing is lost either way.
    spdlog::warn("watch folder: {} is in the ledger as job {} but stays in the watch folder", name, job.job_id);
  }
  return Status::success();
}

Status LedgerNode::enter_hide(const ReadyScan& ready) {
  if (!ready.incompleteness.empty()) return Status::failure(ready.incompleteness);
  const std::string name = ready.scan.filename().string();
  HideFile hide;
  try {
    hide = read_hide_file(ready.scan);
  } catch (const EngineError& failure) {
    return Status::failure(failure.what());
  } catch (const std::exception& failure) {  // a reader bug, not a refusal: the hide fails, the node runs on
    return Status::failure(name + ": unreadable hide file (" + failure.what() + ")");
  }
  std::string material, cutter;
  if (const std::string unknown = settle_hide_targets(hide.hide_id, hide.material, hide.cutter,
                                                      hide_sidecar_path(ready.scan).string(), *config(), material, cutter);
      !unknown.empty())
    return Status::failure(unknown);
  const auto hash = sha256_file_hex(ready.scan);
  if (!hash) return Status::failure("the hide file cannot be read (it vanished or is not readable)");

  // The files first, then the row: a hide in the ledger always finds its file in the shared folder.
  const std::filesystem::path shared = store_.hide_dir(*hash);
  std::error_code exists_error;
  if (std::filesystem::exists(shared, exists_error)) {
    // The same bytes entered before under another name (stock hides cut to one outline): this
    // hide's own file and sidecar join them, each written whole before the row names it.
    for (const std::filesystem::path& file : {ready.scan, ready.sidecar}) {
      if (file.empty() || std::filesystem::exists(shared / file.filename(), exists_error)) continue;
      if (Status copied = copy_file_durably(file, shared / file.filename()); !copied) {
        return Status::failure("shared folder unusable: " + copied.error());
      }
    }
  } else {
    auto scratch = store_.scratch_for(shared, ledger().node);
    Status copied = scratch.status();
    for (const std::filesystem::path& file : {ready.scan, ready.sidecar}) {
      if (copied && !file.empty()) copied = copy_file_durably(file, *scratch / file.filename());
    }
    if (copied) copied = store_.publish(*scratch, shared);
    if (!copied) {
      std::error_code ignored;
      if (scratch) std::filesystem::remove_all(*scratch, ignored);
      return Status::failure("shared folder unusable: " + copied.error());
    }
  }
  const Result<long long> entered =
      client_->enter_hide({hide.hide_id, material, cutter, store_.relative(shared / name), hide.area_m2});
  if (!entered) return entered.status();
  if (!move_into(config()->paths.spool_dir / "hides", ready)) {
    spdlog::warn("hides folder: {} is in the ledger as hide {} but stays in the hides folder", name, hide.hide_id);
  }
  spdlog::info("hide {} ({}, {:.2f} m^2) lies on cutter {}: entered in the ledger; the computed jobs of {} are "
               "nested on it",
               hide.hide_id, name, hide.area_m2, cutter, material);
  return Status::success();
}

void LedgerNode::refuse(const ReadyScan& ready, const std::string& reason) {
  ++refused_;
  const std::string name = ready.scan.filename().string();
  spdlog::error("{}: refused, not entered in the ledger: {}", name, reason);
  const std::filesystem::path failed = config()->paths.spool_dir / "failed";
  if (!move_into(failed, ready)) return;
  if (Status written = write_file_durably(failed / (name + ".reason"), reason + "\n"); !written)
    spdlog::error("{}: the reason cannot be written next to it in {}: {}", name, failed.string(), written.error());
}

void LedgerNode::sweep() {
  ledger::SweepOutcome swept;
  const Status done = journal_->change([&]() -> Result<LedgerJobChanges> {
    auto outcome = client_->sweep_expired(config()->jobs.max_attempts, ledger().heartbeat_s);
    if (!outcome) return outcome.status();
    swept = std::move(*outcome);
    return held_job_changes(swept.jobs_held);
  });
  if (!done) {
    note_trouble(sweep_trouble_, done.error(), "leases of vanished nodes");
    return;
  }
  note_trouble(sweep_trouble_, "", "leases of vanished nodes");
  const auto list = [](const std::vector<long long>& ids) {
    std::string out;
    for (long long id : ids) out += (out.empty() ? "" : ", ") + std::to_string(id);
    return out;
  };
  if (!swept.jobs_requeued.empty()) spdlog::warn("jobs {}: their node's lease ran out, computed again", list(swept.jobs_requeued));
  if (!swept.jobs_failed.empty()) spdlog::error("jobs {}: interrupted too often, failed", list(swept.jobs_failed));
  if (!swept.batches_dissolved.empty())
    spdlog::warn("batches {}: their node's lease ran out while nesting, jobs regrouped", list(swept.batches_dissolved));
  if (!swept.batches_requeued.empty())
    spdlog::warn("batches {}: claimed by a station that vanished before sending, queued again",
                 list(swept.batches_requeued));
  if (!swept.batches_held.empty())
    spdlog::error("batches {}: their station vanished while sending: held for an operator, never re-sent",
                  list(swept.batches_held));
}

}  // namespace lastcut::daemon
