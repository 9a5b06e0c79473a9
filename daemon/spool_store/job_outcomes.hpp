#pragma once
// A spool job's changes of stage, all through set_job_stage(), a batch's through set_batch_stage(),
// and the ends of a job's road: failed/ (bad input), held/ (an operator must decide), done/ (cut
// or skipped).
// report.json in the job folder collects the measures, timings, batch and cutter answer, and
// every failure met on the way ("problems"), so no error is only in the log.
#include <string>

#include <nlohmann/json.hpp>

#include "daemon/spool/spool.hpp"

namespace lastcut::daemon {

// The one place a spool job's stage changes (as cupsdSetJobState in the CUPS scheduler): `stage`
// and `note` go into its state.json durably (the status observers hear of it through
// Spool::on_job_written); an end stage also moves the job folder out of work/ (failed, held: their
// folders; cut, skipped: done/) and makes `note` the job's reason; and the change is one log line,
// "<job>: <note>" (for an end " - moved to <folder>/"), an error when failed, a warning when held.
// False when it could not be written or moved: the job stays in work/, and the problem is logged
// and noted in its report as "<if_not_written>: <error>".
bool set_job_stage(const Spool& spool, JobState& state, JobStage stage, const std::string& note,
                   const std::string& if_not_written = "state not written");
// Who says a batch's change in the log.
enum class BatchLine {
  Logged,    // set_batch_stage: "<batch>: <note>"
  ByCaller,  // the caller, in its own words: the station's cutter worker (the same line on both
             // stores), or a refused hide file with the folder it went to
};
// "batch BID", or for a hide batch "hide ID (batch BID)" (the hide file's name before it was read).
std::string batch_label(const BatchState& batch);
// The one place a spool batch's stage changes: `stage` goes into batch.json durably (for an end -
// held, abandoned, empty - with `note` as its reason). Its jobs still in work/ follow for the steps
// that keep them there, each through set_job_stage: nesting makes them part of the batch (batched),
// queued and sending set that stage on jobs not in it yet, with `note`; the ends of the jobs (cut,
// held) are written by complete_batch_jobs / hold_batch_jobs with their move out of work/. Then the
// one log line (BatchLine): info, a warning for held, abandoned and empty. False when batch.json
// could not be written: logged and noted in its jobs' reports as "<if_not_written>: <error>" (by
// default "<stage> (<note>), but batch.json not written").
bool set_batch_stage(const Spool& spool, BatchState& batch, BatchStage stage, const std::string& note,
                     BatchLine line = BatchLine::Logged, const std::string& if_not_written = "");
// work/ID -> failed/ID; the original scan stays there with the reason.
void fail_job(const Spool& spool, JobState state, const std::string& reason);
// work/ID -> held/ID with the reason and what the operator can do.
void hold_job(const Spool& spool, JobState state, const std::string& reason);
// Merges `fields` into the job's report.json (created when missing), durably.
Status update_job_report(const Spool& spool, JobFolder folder, const std::string& job_id, const nlohmann::json& fields);
// A failure that leaves the job where it is: logged as an error with the job's label and
// appended to its report.json under "problems".
void report_job_problem(const Spool& spool, JobFolder folder, const JobState& state, const std::string& problem);
// The same for a batch: one log line, and the problem in the report of each of its jobs in work/.
void report_batch_problem(const Spool& spool, const BatchState& batch, const std::string& problem);
// The batch was cut: its layout, preview and cut file are copied into each job's folder, the
// report completed, and every job still in work/ moves to done/, except a job of several materials
// whose next part waits (daemon/job/job_parts.hpp): it becomes computed again with that part's
// material and cutter. Returns those jobs' ids, for the batcher.
std::vector<std::string> complete_batch_jobs(const Spool& spool, const BatchState& batch);
// The batch may have been partly cut: every job of it still in work/ moves to held/.
void hold_batch_jobs(const Spool& spool, const BatchState& batch, const std::string& reason);

}  // namespace lastcut::daemon
