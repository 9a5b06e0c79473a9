#include "daemon/spool_store/spool_compute_store.hpp"

#include <algorithm>

#include <spdlog/spdlog.h>

#include "daemon/spool_store/job_outcomes.hpp"

namespace lastcut::daemon {
namespace {

class SpoolMoldsClaim : public MoldsClaim {
 public:
  SpoolMoldsClaim(const Spool& spool, JobState state, MoldsWork work, std::function<void(const std::string&)> computed)
      : spool_(spool), state_(std::move(state)), work_(std::move(work)), computed_(std::move(computed)) {}

  const MoldsWork& work() const override { return work_; }

  void finish(const JobMolds& molds) override {
    if (molds.verdict == JobMolds::Verdict::Failed) {
      fail_job(spool_, state_, molds.reason);
      return;
    }
    state_.piece_count = molds.pieces;
    nlohmann::json report = molds.report;
    report.update({{"job", state_.id}, {"scan", state_.scan_name}, {"sha256", state_.sha256},
                   {"ticket", ticket_to_json(state_.ticket)}});
    if (Status reported = update_job_report(spool_, JobFolder::Work, state_.id, report); !reported) {
      fail_job(spool_, state_, "molds made but " + reported.error());
      return;
    }
    if (molds.verdict == JobMolds::Verdict::HeldNotNestable) {
      // Not Computed: the job has no items.json, so `lastcut requeue` computes it again under the
      // configuration of that moment (a raised limit, a new lastcut).
      hold_job(spool_, state_, molds.reason);
      return;
    }
    std::string ready = fmt::format("{} {} ready in {:.1f} s", molds.molds, molds.noun, molds.took_s);
    // Cut one material after another (daemon/job/job_parts.hpp): the current part's targets now.
    state_.take_parts(molds.parts);
    if (!molds.parts.empty()) ready += "; cut in parts: " + describe_parts(molds.parts);
    if (const std::string resumed = describe_resumed({state_.parts, state_.part}); !resumed.empty()) ready += "; " + resumed;
    if (!set_job_stage(spool_, state_, JobStage::Computed, ready,
                       "molds made, but the state is not written (computed again at the next start)")) {
      return;
    }
    if (molds.verdict == JobMolds::Verdict::HeldForReview) {
      // Computed first: `lastcut requeue` of the held job then nests it as it is (the operator's approval).
      hold_job(spool_, state_, molds.reason);
      return;
    }
    computed_(state_.id);
  }

 private:
  const Spool& spool_;
  JobState state_;
  MoldsWork work_;
  std::function<void(const std::string&)> computed_;
};

class SpoolNestClaim : public NestClaim {
 public:
  SpoolNestClaim(const Spool& spool, BatchState batch, std::map<std::string, JobState> states, NestWork work,
                 const SpoolComputeStore::Listeners& listeners)
      : spool_(spool), batch_(std::move(batch)), states_(std::move(states)), work_(std::move(work)),
        listeners_(listeners) {}

  const NestWork& work() const override { return work_; }

  void finish(const NestResult& result) override {
    const bool on_hide = !batch_.hide_file.empty();
    std::size_t back_to_wait = 0;
    for (auto& [id, state] : states_) {
      if (const auto rejected = result.rejected.find(id); result.made && rejected != result.rejected.end()) {
        fail_job(spool_, state, rejected->second);
      } else if (std::find(result.placed.begin(), result.placed.end(), id) != result.placed.end()) {
        if (const auto parted = result.split.find(id); parted != result.split.end()) split_job(state, parted->second);
        if (Status reported = update_job_report(spool_, JobFolder::Work, id,
                                                {{"timings_s", {{"nesting_and_cut_file", result.took_s}}}});
            !reported) {
          report_job_problem(spool_, JobFolder::Work, state, reported.error());
        }
      } else if (on_hide) {
        // Not placed on this hide (or the hide could not be nested): it waits for the next one.
        const auto waiting = result.waiting.find(id);
        const std::string why = !result.made                    ? "hide " + batch_.hide_id + " could not be nested: " +
                                                                    result.made.error()
                                : waiting != result.waiting.end() ? waiting->second
                                                                  : "no room left on hide " + batch_.hide_id;
        state.batch_id.clear();
        state.reason = "waiting for a hide of " + batch_.material + ": " + why;
        set_job_stage(spool_, state, JobStage::Computed, state.reason);
        listeners_.computed(id);
        ++back_to_wait;
      } else {
        // A strip batch that could not be made at all: not the job's fault; an operator requeues it.
        hold_job(spool_, state, "batch " + batch_.id + " could not be made: " +
                                    (result.made ? std::string("its cut file was not made") : result.made.error()));
      }
    }
    batch_.job_ids = result.placed;
    if (result.placed.empty()) {
      // Its jobs have left the batch already; if batch.json is not written, recovery abandons it.
      set_batch_stage(spool_, batch_, BatchStage::Empty,
                      !result.made       ? result.made.error()
                      : !on_hide         ? "no job left in the batch"
                      : states_.empty() ? "no piece of " + batch_.material + " was waiting for hide " + batch_.hide_id
                                         : "no waiting job fitted on hide " + batch_.hide_id);
      return;
    }
    batch_.cut_file = result.cut_file;
    batch_.utilisation = result.utilisation;
    batch_.piece_count = result.pieces;
    const std::string note =
        on_hide ? fmt::format("{} job(s), {} pieces, utilisation of its usable area {:.1f} %, {} job(s) wait; queued for {}",
                              result.placed.size(), batch_.piece_count, 100.0 * batch_.utilisation, back_to_wait,
                              batch_.cutter)
                : fmt::format("{} job(s), {} pieces nested on {} (utilisation {:.1f} %) in {:.1f} s; queued for {}",
                              result.placed.size(), batch_.piece_count, batch_.material, 100.0 * batch_.utilisation,
                              result.took_s, batch_.cutter);
    // Not written: still "nesting" on disk, the next start abandons it and nests its jobs again.
    if (!set_batch_stage(spool_, batch_, BatchStage::Queued, note, BatchLine::Logged, "nested, but not queued")) return;
    listeners_.queued(batch_);
  }

 private:
  // The hide took some of the job's pieces (split_over_hides): they are its current part now, and the
  // rest its next part, which waits for another hide once this one is cut (complete_batch_jobs).
  void split_job(JobState& state, const PartSplit& parted) {
    const JobPart whole{state.ticket.material, state.ticket.cutter, state.piece_count, {}};
    state.parts = split_part(state.parts, state.part, whole, parted);
    state.take_current_part();
    const std::string note = describe_split(parted, batch_.material, batch_.hide_id);
    // Unwritten, the job's state says its whole part is on this hide: held, so that an operator sees it
    // before anything of it is taken for cut (its pieces on the hide are cut with the others).
    if (!set_job_stage(spool_, state, JobStage::Batched, note, "split over hides, but the state is not written"))
      hold_job(spool_, state, note + ", but its state could not be written: requeue it to cut every piece again");
  }

  const Spool& spool_;
  BatchState batch_;
  std::map<std::string, JobState> states_;
  NestWork work_;
  const SpoolComputeStore::Listeners& listeners_;
};

}  // namespace

SpoolComputeStore::SpoolComputeStore(const Spool& spool, std::function<std::shared_ptr<const DaemonConfig>()> settings,
                                     Listeners listeners)
    : spool_(spool), settings_(std::move(settings)), listeners_(std::move(listeners)) {}

void SpoolComputeStore::add_job(const std::string& job_id) {
  std::lock_guard lock(mutex_);
  entries_.push_back({false, job_id});
}

void SpoolComputeStore::add_batch(const std::string& batch_id) {
  std::lock_guard lock(mutex_);
  entries_.push_back({true, batch_id});
}

std::size_t SpoolComputeStore::waiting() const {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

void SpoolComputeStore::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
}

Result<std::optional<ComputeClaim>> SpoolComputeStore::claim(const std::string&) {
  while (true) {
    Entry entry;
    {
      std::lock_guard lock(mutex_);
      if (entries_.empty()) return std::optional<ComputeClaim>();
      entry = std::move(entries_.front());
      entries_.pop_front();
    }
    if (entry.is_batch) {
      if (auto nest = claim_batch(entry.id)) return std::optional<ComputeClaim>(std::move(nest));
    } else if (auto molds = claim_job(entry.id)) {
      return std::optional<ComputeClaim>(std::move(molds));
    }
  }
}

std::unique_ptr<MoldsClaim> SpoolComputeStore::claim_job(const std::string& job_id) {
  auto state = spool_.read_state(JobFolder::Work, job_id);
  if (!state || state->stage != JobStage::Claimed || !state->stage_problem.empty()) return nullptr;
  if (state->attempts >= settings_()->jobs.max_attempts) {
    fail_job(spool_, *state,
             "computing the molds stopped lastcutd " + std::to_string(state->attempts) +
                 " times (crash or hang); the scan is kept for a developer to look at");
    return nullptr;
  }
  // Counted before the work: if this scan crashes the daemon, the next start knows.
  ++state->attempts;
  // Without the count on disk a scan that crashes lastcutd would be computed forever.
  const std::string computing =
      "computing " + job_work_noun(state->scan_name, state->ticket) + ", attempt " + std::to_string(state->attempts);
  if (!set_job_stage(spool_, *state, JobStage::Claimed, computing, "not computed, its attempt cannot be counted")) {
    return nullptr;
  }
  const auto job_dir = spool_.job_dir(JobFolder::Work, job_id);
  MoldsWork work{job_dir / state->scan_name, job_dir, state->ticket, state->label()};
  return std::make_unique<SpoolMoldsClaim>(spool_, std::move(*state), std::move(work), listeners_.computed);
}

std::unique_ptr<NestClaim> SpoolComputeStore::claim_batch(const std::string& batch_id) {
  auto batch = spool_.read_batch(batch_id);
  if (!batch || batch->stage != BatchStage::Nesting || !batch->stage_problem.empty()) return nullptr;
  NestWork work;
  work.label = batch_label(*batch);
  work.material = batch->material;
  work.cutter = batch->cutter;
  work.batch_dir = spool_.batch_dir(batch_id);
  work.hide_file = batch->hide_file;
  work.hide_name = batch->hide_id;
  std::map<std::string, JobState> states;
  // batch.job_ids is oldest first; only jobs still in this batch (an operator may have moved one).
  for (const std::string& id : batch->job_ids) {
    auto state = spool_.read_state(JobFolder::Work, id);
    if (!state || state->batch_id != batch_id) continue;
    work.jobs.push_back({id, spool_.job_dir(JobFolder::Work, id), state->ticket, part_copies(state->parts, state->part)});
    states.emplace(id, std::move(*state));
  }
  return std::make_unique<SpoolNestClaim>(spool_, std::move(*batch), std::move(states), std::move(work), listeners_);
}

}  // namespace lastcut::daemon
