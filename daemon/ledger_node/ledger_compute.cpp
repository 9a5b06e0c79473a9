// The compute role of a ledger node: claim a ready job, make its molds into the shared folder,
// mark it computed; when no job waits, nest a hide that lies on a cutter's table or a group of
// computed jobs (ledger_nesting.cpp). The same engine steps as the single-station pipeline (engine_steps.hpp).
// Every result is published before the ledger hears of it, and the ledger only takes it from the
// node that still holds the lease (fencing), so a lost claim costs work, never a wrong state.
#include <spdlog/spdlog.h>

#include "daemon/ledger_node/ledger_batch_rule.hpp"
#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/hide_policy.hpp"
#include "daemon/station/job_molds.hpp"
#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {
namespace {

// Removes a job's scratch folder when the computation ends, however it ends.
struct ScratchRemover {
  std::filesystem::path folder;
  ~ScratchRemover() {
    std::error_code ignored;
    std::filesystem::remove_all(folder, ignored);
  }
};

void copy_references(const std::filesystem::path& from, const std::filesystem::path& job_dir) {
  std::error_code error;
  if (!std::filesystem::is_directory(from, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(from, error)) {
    std::filesystem::copy_file(entry.path(), job_dir / entry.path().filename(), error);
  }
}

}  // namespace

void LedgerNode::compute_worker(int index) {
  const std::string worker = "compute-" + std::to_string(index);
  std::unique_ptr<ledger::LedgerClient> client;
  std::string trouble;
  while (!stopping_) {
    if (!connect_worker(client, trouble, worker)) continue;
    const auto job = client->claim_job(ledger().lease_s);
    if (job && job->has_value()) {
      note_trouble(trouble, "", worker);
      compute_job(*client, **job, worker);
      continue;
    }
    // A hide on a cutter's table comes before strip batches: the cutter and its operator wait for it.
    auto batch = job ? client->make_hide_batch(ledger_hide_rule(config()->batch.window_s), kHideMaxJobs, ledger().lease_s)
                     : Result<std::optional<ledger::BatchClaim>>(job.status());
    if (batch && !batch->has_value())
      batch = client->make_batch(ledger_batch_rule(config()->batch), ledger().lease_s, hide_materials());
    if (batch && batch->has_value()) {
      note_trouble(trouble, "", worker);
      nest_batch(*client, **batch, worker);
      continue;
    }
    note_trouble(trouble, batch ? "" : batch.error(), worker);
    pause(batch ? 0.25 : ledger().heartbeat_s);
  }
}

void LedgerNode::compute_job(ledger::LedgerClient& client, const ledger::JobClaim& claim, const std::string& worker) {
  const auto settings = config();  // one configuration for the whole step (SIGHUP may replace it)
  const std::string label = "job " + std::to_string(claim.job_id) + " (" + claim.scan.scan_name + ")";
  keeper_->keep(claim.lease);
  job_changed(claim.job_id, claim.scan.scan_name, claim.scan.ticket, 0, JobStage::Claimed, "",
              "computing molds on " + ledger().node + " (attempt " + std::to_string(claim.attempts) + ")");
  // The one way out: the ledger's fenced change, then what it says (job_changed).
  const auto finish = [&](const Status& marked, JobStage stage, const std::string& reason, const std::string& note = "") {
    keeper_->drop(claim.lease);
    if (!marked) spdlog::warn("{}: {}; the work is dropped", label, marked.error());
    else job_changed(claim.job_id, claim.scan.scan_name, claim.scan.ticket, 0, stage, reason, note);
  };
  const Result<JobTicket> ticket = ticket_from_ledger(claim.scan.ticket);
  if (!ticket) {
    return finish(client.mark_failed(claim.lease, ticket.error()), JobStage::Failed, ticket.error());
  }
  const std::filesystem::path final_dir = store_.job_dir(claim.job_folder);
  auto scratch = store_.scratch_for(final_dir, ledger().node);
  if (!scratch) return finish(Status::failure(scratch.error()), JobStage::Failed, "");
  const ScratchRemover remover{*scratch};  // whatever happens below; publishing renames it away first
  copy_references(store_.references(claim.scan.scan_sha256), *scratch);

  const JobMolds molds = make_job_molds(store_.scan(claim.scan.scan_sha256, claim.scan.scan_name), *scratch, *ticket,
                                        *settings, monitor_, worker, label, label);
  if (molds.verdict == JobMolds::Verdict::Failed) {
    return finish(client.mark_failed(claim.lease, molds.reason), JobStage::Failed, molds.reason);
  }
  nlohmann::json report = molds.report;
  report.update({{"job", claim.job_id}, {"scan", claim.scan.scan_name}, {"sha256", claim.scan.scan_sha256},
                 {"ticket", nlohmann::json::parse(claim.scan.ticket)}, {"node", ledger().node}});
  if (Status written = write_file_durably(*scratch / kReportFile, report.dump(1)); !written) {
    return finish(Status::failure("molds made, report not written: " + written.error()), JobStage::Failed, "");
  }
  if (keeper_->lost(claim.lease)) {
    return finish(Status::failure("lease lost while computing: another node has the job now"), JobStage::Claimed, "");
  }
  if (Status published = store_.publish(*scratch, final_dir); !published) {
    return finish(Status::failure("molds made but not published: " + published.error()), JobStage::Claimed, "");
  }
  if (molds.verdict == JobMolds::Verdict::HeldForReview) {
    return finish(client.mark_held(claim.lease, molds.reason), JobStage::Held, molds.reason);
  }
  finish(client.mark_computed(claim.lease, molds.pieces), JobStage::Computed, "",
         fmt::format("{} molds ready in {:.1f} s", molds.molds, molds.took_s));
}

}  // namespace lastcut::daemon
