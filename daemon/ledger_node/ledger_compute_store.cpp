#include "daemon/ledger_node/ledger_compute_store.hpp"

#include <algorithm>
#include <unordered_map>
#include <utility>

#include <spdlog/spdlog.h>

#include "daemon/ledger_node/ledger_batch_rule.hpp"
#include "daemon/ledger_node/ledger_node.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/station/hide_policy.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut::daemon {
namespace {

// A claim's scratch folder in the shared folder, removed when the claim ends, however it ends
// (publishing renames it away first). Move-only: only the last owner removes it.
class ScratchFolder {
 public:
  explicit ScratchFolder(std::filesystem::path path) : path_(std::move(path)) {}
  ScratchFolder(ScratchFolder&& other) noexcept : path_(std::exchange(other.path_, {})) {}
  ScratchFolder& operator=(ScratchFolder&&) = delete;
  ~ScratchFolder() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }

 private:
  std::filesystem::path path_;
};

// What every claim of this node holds while it computes.
struct ClaimContext {
  ledger::LedgerClient& client;  // the claiming worker's own connection
  ledger::LeaseKeeper& keeper;
  const SharedStore& shared;
  const LedgerConfig& ledger;
  const LedgerJournal& journal;
  LedgerJournal::Pause pause;
  ScratchFolder scratch;
};

// The one way a job claim of this node ends: the ledger's fenced change through the journal (it
// logs and tells the change once taken; finished work waits for a ledger that is away); the lease
// is renewed until then and no longer afterwards; a change the ledger refused drops the work
// (whoever holds the job now redoes it).
void end_job_claim(const LedgerJournal& journal, const LedgerJournal::Pause& pause, ledger::LeaseKeeper& keeper,
                   const ledger::JobClaim& claim, const std::string& label, const std::function<Status()>& save,
                   JobStage stage, const std::string& reason, const std::string& note = "") {
  const Status changed = journal.change_once_reachable(
      save_then(save, {{claim.job_id, claim.scan.scan_name, claim.scan.ticket, 0, stage, reason, note}}), pause,
      keeper.retry_s(), label);
  keeper.drop(claim.lease);
  if (!changed) spdlog::warn("{}: {}; the work is dropped", label, changed.error());
}

// A job claim given up before there is anything to tell the ledger: its lease runs out and the job
// is computed again (by this node or another).
void drop_job_claim(ledger::LeaseKeeper& keeper, const ledger::JobClaim& claim, const std::string& label,
                    const std::string& why) {
  keeper.drop(claim.lease);
  spdlog::warn("{}: {}; the work is dropped", label, why);
}

class LedgerMoldsClaim : public MoldsClaim {
 public:
  LedgerMoldsClaim(ClaimContext context, ledger::JobClaim claim, MoldsWork work)
      : context_(std::move(context)), claim_(std::move(claim)), work_(std::move(work)) {}

  const MoldsWork& work() const override { return work_; }

  void finish(const JobMolds& molds) override {
    ledger::LedgerClient& client = context_.client;
    const ledger::Lease& lease = claim_.lease;
    if (molds.verdict == JobMolds::Verdict::Failed) {
      return finish([&] { return client.mark_failed(lease, molds.reason); }, JobStage::Failed, molds.reason);
    }
    nlohmann::json report = molds.report;
    report.update({{"job", claim_.job_id}, {"scan", claim_.scan.scan_name}, {"sha256", claim_.scan.scan_sha256},
                   {"ticket", nlohmann::json::parse(claim_.scan.ticket)}, {"node", context_.ledger.node}});
    if (Status written = write_file_durably(work_.job_dir / kReportFile, report.dump(1)); !written) {
      return drop("molds made, report not written: " + written.error());
    }
    if (context_.keeper.lost(lease)) return drop("lease lost while computing: another node has the job now");
    if (Status published = context_.shared.publish(work_.job_dir, context_.shared.job_dir(claim_.job_folder));
        !published) {
      return drop("molds made but not published: " + published.error());
    }
    // The ledger computes a requeued job again in either case (LedgerClient::requeue_held).
    if (molds.verdict == JobMolds::Verdict::HeldForReview || molds.verdict == JobMolds::Verdict::HeldNotNestable) {
      return finish([&] { return client.mark_held(lease, molds.reason); }, JobStage::Held, molds.reason);
    }
    std::string ready = fmt::format("{} {} ready in {:.1f} s", molds.molds, molds.noun, molds.took_s);
    if (!molds.parts.empty()) ready += "; cut in parts: " + describe_parts(molds.parts);
    finish([&] { return client.mark_computed(lease, molds.pieces, molds.parts); }, JobStage::Computed, "", ready);
  }

 private:
  void finish(const std::function<Status()>& save, JobStage stage, const std::string& reason,
              const std::string& note = "") {
    end_job_claim(context_.journal, context_.pause, context_.keeper, claim_, work_.label, save, stage, reason, note);
  }
  void drop(const std::string& why) { drop_job_claim(context_.keeper, claim_, work_.label, why); }

  ClaimContext context_;
  ledger::JobClaim claim_;
  MoldsWork work_;
};

class LedgerNestClaim : public NestClaim {
 public:
  LedgerNestClaim(ClaimContext context, ledger::BatchClaim claim, NestWork work)
      : context_(std::move(context)), claim_(std::move(claim)), work_(std::move(work)) {}

  const NestWork& work() const override { return work_; }

  void finish(const NestResult& result) override {
    const bool on_hide = claim_.hide_id != 0;
    ledger::NestedBatch nested;
    Status made = result.made;
    if (made) {
      for (const auto& [job_id, reason] : result.rejected) nested.rejected.emplace_back(std::stoll(job_id), reason);
      for (const auto& [job_id, reason] : result.waiting)
        nested.waiting.emplace_back(std::stoll(job_id), "waiting for a hide of " + claim_.material + ": " + reason);
      for (const auto& [job_id, parted] : result.split) nested.split.push_back(split_job(std::stoll(job_id), parted));
      nested.pieces = result.pieces;
      nested.utilisation = result.utilisation;
      if (on_hide && result.placed.empty()) nested.reason = "no waiting job fitted on hide " + claim_.hide_name;
      if (!result.cut_file.empty()) {
        const std::filesystem::path final_dir = context_.shared.batch_dir(claim_.batch_id);
        nested.cut_file = context_.shared.relative(final_dir / result.cut_file);
        made = context_.shared.publish(work_.batch_dir, final_dir);
      }
    }
    if (!made) {
      // Not the jobs' fault (no machine profile, the share full). As on a spool, a strip batch holds
      // its jobs with the reason (`lastcut requeue` hands them back once the cause is mended); the
      // jobs of a hide wait for the next hide.
      nested = {};
      nested.reason = (on_hide ? "hide " + claim_.hide_name + " could not be nested: "
                               : "batch " + std::to_string(claim_.batch_id) + " could not be made: ") +
                      made.error();
      for (long long id : claim_.job_ids) {
        if (on_hide) nested.waiting.emplace_back(id, "waiting for a hide of " + claim_.material + ": " + nested.reason);
        else nested.held.emplace_back(id, nested.reason);
      }
    }
    std::size_t kept = 0;
    LedgerJobChanges changes = job_outcome_changes(nested, kept);
    const Status marked = context_.journal.change_once_reachable(
        save_then([&] { return context_.client.mark_nested(claim_.lease, nested); }, std::move(changes)),
        context_.pause, context_.keeper.retry_s(), work_.label);
    context_.keeper.drop(claim_.lease);
    if (!marked) {
      // Its published folder, if any, is pointed to by no row: the orphan sweep removes it (orphan_sweep.hpp).
      spdlog::warn("{}: {}; the nesting is dropped", work_.label, marked.error());
      return;
    }
    if (nested.cut_file.empty()) {
      spdlog::warn("{}: {}; nothing is cut", work_.label, nested.reason.empty() ? "no job could be placed" : nested.reason);
    } else if (on_hide) {
      spdlog::info("{}: {} job(s), {} pieces, utilisation of its usable area {:.1f} %, {} job(s) wait; queued for {}",
                   work_.label, kept, nested.pieces, 100.0 * nested.utilisation, nested.waiting.size(), claim_.cutter);
    } else {
      spdlog::info("{}: {} job(s), {} pieces nested on {} (utilisation {:.1f} %) in {:.1f} s; queued for {}",
                   work_.label, kept, nested.pieces, claim_.material, 100.0 * nested.utilisation, result.took_s,
                   claim_.cutter);
    }
  }

 private:
  // A job the hide took in part: its parts from now on (the ledger row's, split) and the event's words.
  ledger::NestedBatch::Split split_job(long long job_id, const PartSplit& parted) const {
    const auto index = static_cast<std::size_t>(
        std::find(claim_.job_ids.begin(), claim_.job_ids.end(), job_id) - claim_.job_ids.begin());
    const int part = claim_.job_part.at(index);
    const JobPart whole{claim_.material, claim_.cutter, 0, {}};
    return {job_id, split_part(claim_.job_parts.at(index), part, whole, parted),
            describe_split(parted, claim_.material, claim_.hide_name)};
  }

  // How the nesting ended for each claimed job, in claim order; `kept`: the jobs batched.
  LedgerJobChanges job_outcome_changes(const ledger::NestedBatch& nested, std::size_t& kept) const {
    struct Outcome {
      JobStage stage;
      const std::string* reason;
    };
    std::unordered_map<long long, Outcome> outcome_of;
    for (const auto& [job_id, reason] : nested.rejected) outcome_of.try_emplace(job_id, Outcome{JobStage::Failed, &reason});
    for (const auto& [job_id, reason] : nested.waiting) outcome_of.try_emplace(job_id, Outcome{JobStage::Computed, &reason});
    for (const auto& [job_id, reason] : nested.held) outcome_of.try_emplace(job_id, Outcome{JobStage::Held, &reason});
    LedgerJobChanges changes;
    for (std::size_t i = 0; i < claim_.job_ids.size(); ++i) {
      const long long job_id = claim_.job_ids[i];
      const auto found = outcome_of.find(job_id);
      if (found == outcome_of.end()) {
        if (nested.cut_file.empty()) continue;  // nothing is cut: the reason is logged for the batch
        ++kept;
        std::string note;  // a job the hide took in part says so
        for (const ledger::NestedBatch::Split& split : nested.split)
          if (split.job_id == job_id) note = split.note;
        changes.push_back({job_id, claim_.job_names[i], claim_.job_tickets[i], claim_.batch_id, JobStage::Batched, "", note});
        continue;
      }
      const auto& [stage, reason] = found->second;
      // A waiting or held job has left the batch; a failed one names it.
      changes.push_back({job_id, claim_.job_names[i], claim_.job_tickets[i],
                         stage == JobStage::Failed ? claim_.batch_id : 0, stage, *reason, ""});
    }
    return changes;
  }

  ClaimContext context_;
  ledger::BatchClaim claim_;
  NestWork work_;
};

std::vector<std::string> hide_materials(const DaemonConfig& settings) {
  std::vector<std::string> names;
  for (const auto& [name, material] : settings.materials)
    if (material.kind == MaterialKind::Hide) names.push_back(name);
  return names;
}

// Reference patterns the intake copied beside the scan travel into the job's folder.
void copy_references(const std::filesystem::path& from, const std::filesystem::path& job_dir) {
  std::error_code error;
  if (!std::filesystem::is_directory(from, error)) return;
  for (const auto& entry : std::filesystem::directory_iterator(from, error)) {
    std::filesystem::copy_file(entry.path(), job_dir / entry.path().filename(), error);
  }
}

}  // namespace

LedgerComputeStore::LedgerComputeStore(const LedgerConfig& ledger, const SharedStore& shared,
                                       ledger::LeaseKeeper& keeper,
                                       std::function<std::shared_ptr<const DaemonConfig>()> settings,
                                       const LedgerJournal& journal, LedgerJournal::Pause pause)
    : ledger_(ledger), shared_(shared), keeper_(keeper), settings_(std::move(settings)), journal_(journal),
      pause_(std::move(pause)) {}

Result<std::optional<ComputeClaim>> LedgerComputeStore::claim(const std::string& worker) {
  ledger::LedgerClient* client = nullptr;
  {
    std::lock_guard lock(clients_mutex_);
    client = clients_[worker].get();
  }
  if (!client) {
    auto connected = ledger::LedgerClient::connect(ledger_.url, ledger_.node);
    if (!connected) return connected.status();
    std::lock_guard lock(clients_mutex_);
    clients_[worker] = std::move(*connected);
    client = clients_[worker].get();
  }
  while (true) {
    const auto settings = settings_();
    std::optional<ledger::JobClaim> job;
    const Status asked = journal_.change([&]() -> Result<LedgerJobChanges> {
      auto claimed = client->claim_job(ledger_.lease_s);
      if (!claimed) return claimed.status();
      job = std::move(*claimed);
      if (!job) return LedgerJobChanges{};
      const Result<JobTicket> ticket = ticket_from_ledger(job->scan.ticket);
      const std::string noun = job_work_noun(job->scan.scan_name, ticket ? *ticket : JobTicket{});
      return LedgerJobChanges{{job->job_id, job->scan.scan_name, job->scan.ticket, 0, JobStage::Claimed, "",
                               "computing " + noun + " on " + ledger_.node + " (attempt " + std::to_string(job->attempts) + ")"}};
    });
    if (!asked) return asked;
    if (job) {
      if (auto opened = open_job(*client, std::move(*job))) return std::optional<ComputeClaim>(std::move(opened));
      continue;  // ended at once (an unreadable ticket, no scratch folder): the next one
    }
    // A hide on a cutter's table comes before strip batches: the cutter and its operator wait for it.
    auto batch = client->make_hide_batch(ledger_hide_rule(settings->batch.window_s), kHideMaxJobs, ledger_.lease_s);
    if (batch && !batch->has_value())
      batch = client->make_batch(ledger_batch_rule(settings->batch), ledger_.lease_s, hide_materials(*settings));
    if (!batch) return batch.status();
    if (!batch->has_value()) return std::optional<ComputeClaim>();
    if (auto opened = open_batch(*client, std::move(**batch))) return std::optional<ComputeClaim>(std::move(opened));
  }
}

std::unique_ptr<MoldsClaim> LedgerComputeStore::open_job(ledger::LedgerClient& client, ledger::JobClaim claim) {
  const std::string label = "job " + std::to_string(claim.job_id) + " (" + claim.scan.scan_name + ")";
  keeper_.keep(claim.lease);
  const Result<JobTicket> ticket = ticket_from_ledger(claim.scan.ticket);
  if (!ticket) {
    end_job_claim(journal_, pause_, keeper_, claim, label, [&] { return client.mark_failed(claim.lease, ticket.error()); },
                  JobStage::Failed, ticket.error());
    return nullptr;
  }
  auto scratch = shared_.scratch_for(shared_.job_dir(claim.job_folder), ledger_.node);
  if (!scratch) {
    drop_job_claim(keeper_, claim, label, scratch.error());
    return nullptr;
  }
  copy_references(shared_.references(claim.scan.scan_sha256), *scratch);
  MoldsWork work{shared_.scan(claim.scan.scan_sha256, claim.scan.scan_name), *scratch, *ticket, label};
  return std::make_unique<LedgerMoldsClaim>(ClaimContext{client, keeper_, shared_, ledger_, journal_, pause_, ScratchFolder(*scratch)},
                                            std::move(claim), std::move(work));
}

std::unique_ptr<NestClaim> LedgerComputeStore::open_batch(ledger::LedgerClient& client, ledger::BatchClaim claim) {
  const bool on_hide = claim.hide_id != 0;
  keeper_.keep(claim.lease);
  NestWork work;
  work.label = on_hide ? "hide " + claim.hide_name + " (batch " + std::to_string(claim.batch_id) + ")"
                       : "batch " + std::to_string(claim.batch_id);
  work.material = claim.material;
  work.cutter = claim.cutter;
  work.hide_name = claim.hide_name;
  for (std::size_t i = 0; i < claim.job_ids.size(); ++i) {
    const Result<JobTicket> ticket = ticket_from_ledger(claim.job_tickets[i]);
    // job_ids ascend with entry into the ledger: oldest first.
    work.jobs.push_back({std::to_string(claim.job_ids[i]), shared_.job_dir(claim.job_folders[i]),
                         ticket ? *ticket : JobTicket{}, part_copies(claim.job_parts[i], claim.job_part[i])});
  }
  auto scratch = shared_.scratch_for(shared_.batch_dir(claim.batch_id), ledger_.node);
  Status opened = scratch.status();
  if (opened && on_hide) {
    // build_hide reads the hide file and its sidecar from the batch folder, where they stay with the layout.
    const std::filesystem::path hide_file = shared_.absolute(claim.hide_file);
    work.hide_file = hide_file.filename().string();
    for (const std::filesystem::path& file : {hide_file, hide_sidecar_path(hide_file)}) {
      std::error_code error;
      if (!opened || !std::filesystem::exists(file, error)) continue;  // a hide needs no sidecar
      if (Status copied = copy_file_durably(file, *scratch / file.filename()); !copied)
        opened = Status::failure("the hide file cannot be read from the shared folder: " + copied.error());
    }
  }
  if (scratch) work.batch_dir = *scratch;
  auto nest = std::make_unique<LedgerNestClaim>(
      ClaimContext{client, keeper_, shared_, ledger_, journal_, pause_,
                   ScratchFolder(scratch ? *scratch : std::filesystem::path())},
      std::move(claim), std::move(work));
  if (opened) return nest;
  NestResult failed;
  failed.made = opened;
  nest->finish(failed);  // its jobs fail (strip) or wait (hide) with the reason
  return nullptr;
}

}  // namespace lastcut::daemon
