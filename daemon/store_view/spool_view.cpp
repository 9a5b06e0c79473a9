// The spool's StoreView (store_view.hpp): the folders of one station read directly, and
// spool/status.json, which a running lastcutd rewrites every 2 s (its cutters, queues, pid).
#include <algorithm>
#include <chrono>
#include <ctime>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

#include "daemon/store_view/store_view.hpp"
#include "daemon/spool/batch_lock.hpp"
#include "daemon/spool/spool.hpp"
#include "daemon/spool_store/job_outcomes.hpp"
#include "daemon/station/engine_steps.hpp"

namespace lastcut::daemon {
namespace {

nlohmann::json job_summary(const JobState& state, JobFolder folder) {
  return {{"id", state.id},         {"folder", folder_name(folder)}, {"stage", to_string(state.stage)},
          {"order", state.ticket.order}, {"scan", state.scan_name},         {"cutter", state.ticket.cutter},
          {"material", state.ticket.material}, {"reason", state.reason},  {"updated_at", state.updated_at},
          {"parts", parts_progress(state.parts, state.part, state.stage == JobStage::Cut)}};
}

JobLine job_line(const nlohmann::json& job) {
  return {job.value("id", ""),    job.value("stage", ""), job.value("folder", ""),
          job.value("order", ""), job.value("scan", ""),  job.value("reason", ""), job.value("parts", "")};
}

// The time `hours` ago as utc_now_iso() writes times (ISO 8601 UTC): such texts sort as times do.
std::string utc_iso_hours_ago(int hours) {
  const std::time_t then = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now() - std::chrono::hours(hours));
  std::tm utc{};
  gmtime_r(&then, &utc);
  char text[40];
  std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%S.000Z", &utc);
  return text;
}

// The document `lastcut status --json` prints for a spool (docs/daemon.md).
nlohmann::json collect_status(const Spool& spool, std::size_t recent_count) {
  nlohmann::json status;
  const nlohmann::json daemon_status = read_json_or_null(spool.root() / "status.json");
  status["daemon"] = daemon_status.is_null() ? nlohmann::json{{"running", false}} : daemon_status;
  if (!daemon_status.is_null()) status["daemon"]["running"] = true;
  nlohmann::json counts, work = nlohmann::json::array(), held = nlohmann::json::array();
  std::vector<std::pair<std::string, nlohmann::json>> finished;
  for (JobFolder folder : {JobFolder::Work, JobFolder::Done, JobFolder::Failed, JobFolder::Held}) {
    const auto ids = spool.list(folder);
    counts[folder_name(folder)] = ids.size();
    // Only the newest finished jobs are read: status stays fast with months of history.
    const std::size_t first = folder == JobFolder::Work || folder == JobFolder::Held || ids.size() <= recent_count
                                  ? 0 : ids.size() - recent_count;
    for (std::size_t i = first; i < ids.size(); ++i) {
      auto state = spool.read_state(folder, ids[i]);
      if (!state) continue;
      const nlohmann::json summary = job_summary(*state, folder);
      if (folder == JobFolder::Work) work.push_back(summary);
      else if (folder == JobFolder::Held) held.push_back(summary);
      if (folder != JobFolder::Work) finished.emplace_back(state->updated_at, summary);
    }
  }
  std::sort(finished.begin(), finished.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  nlohmann::json recent = nlohmann::json::array();
  for (std::size_t i = 0; i < finished.size() && i < recent_count; ++i) recent.push_back(finished[i].second);
  nlohmann::json batches = nlohmann::json::array(), hides = nlohmann::json::array(), cut = nlohmann::json::array();
  const std::string day_ago = utc_iso_hours_ago(24);
  for (const std::string& id : spool.list_batches()) {
    auto batch = spool.read_batch(id);
    if (!batch) continue;
    // A batch.json without a known stage is shown too: it is held until an operator looks.
    if (in_progress(batch->stage) || !batch->stage_problem.empty()) {
      batches.push_back({{"id", batch->id}, {"cutter", batch->cutter}, {"stage", to_string(batch->stage)},
                         {"jobs", batch->job_ids}, {"pieces", batch->piece_count}, {"reason", batch->reason}});
    }
    if (!batch->hide_id.empty()) {
      hides.push_back({{"hide", batch->hide_id}, {"batch", batch->id}, {"cutter", batch->cutter},
                       {"material", batch->material}, {"stage", to_string(batch->stage)},
                       {"pieces", batch->piece_count}, {"utilisation", batch->utilisation},
                       {"created_at", batch->created_at}});
    }
    if (batch->stage == BatchStage::Cut && batch->updated_at >= day_ago) {
      cut.push_back({{"id", batch->id}, {"cut_at", batch->updated_at}, {"material", batch->material},
                     {"jobs", batch->job_ids.size()}, {"pieces", batch->piece_count}, {"utilisation", batch->utilisation}});
    }
  }
  std::sort(hides.begin(), hides.end(), [](const auto& a, const auto& b) { return a["created_at"] > b["created_at"]; });
  if (hides.size() > 20) hides.erase(hides.begin() + 20, hides.end());
  std::sort(cut.begin(), cut.end(), [](const auto& a, const auto& b) { return a["cut_at"] < b["cut_at"]; });
  status["counts"] = counts;
  status["work"] = work;
  status["held"] = held;
  status["active_batches"] = batches;
  status["hides"] = hides;
  status["cut_last_24h"] = cut;
  status["recent"] = recent;
  return status;
}

class SpoolView : public StoreView {
 public:
  explicit SpoolView(const std::string& root) : spool_(root) {}

  Result<StoreOverview> overview(std::size_t recent_count) override {
    StoreOverview overview;
    overview.json = collect_status(spool_, recent_count);
    const nlohmann::json& status = overview.json;
    const auto& counts = status["counts"];
    overview.headline = format_line("spool %s: %d in work, %d done, %d failed, %d held", spool_.root().c_str(),
                               counts.value("work", 0), counts.value("done", 0), counts.value("failed", 0),
                               counts.value("held", 0));
    const auto& daemon_status = status["daemon"];
    overview.station_lines.push_back(
        daemon_status.value("running", false)
            ? format_line("lastcutd: running (pid %ld, status of %s)", daemon_status.value("pid", 0L),
                     daemon_status.value("updated_at", "?").c_str())
            : format_line("lastcutd: not running (no %s/status.json)", spool_.root().c_str()));
    if (daemon_status.contains("cutters")) {
      for (const auto& [name, cutter] : daemon_status["cutters"].items()) {
        overview.cutter_lines.push_back(format_line("cutter %-12s %s, %d batch(es) queued", name.c_str(),
                                               cutter.value("condition", "?").c_str(), cutter.value("queued_batches", 0)));
      }
    }
    if (daemon_status.contains("waiting_for_hide")) {
      for (const auto& [material, count] : daemon_status["waiting_for_hide"].items())
        overview.waiting_for_hide[material] = count.get<long long>();
      const nlohmann::json pieces_waiting = daemon_status.value("pieces_waiting_for_hide", nlohmann::json::object());
      for (const auto& [material, count] : pieces_waiting.items())
        overview.pieces_waiting_for_hide[material] = count.get<long long>();
    }
    for (const auto& batch : status["active_batches"]) {
      if (batch.value("stage", "") == "queued")
        overview.queued_batches.push_back({batch.value("id", ""), batch.value("cutter", ""),
                                           static_cast<long long>(batch["jobs"].size()), batch.value("pieces", 0)});
      const std::string reason = batch.value("reason", "");
      overview.batch_lines.push_back(format_line("batch %s for %s: %s, %zu job(s), %d pieces%s", batch.value("id", "").c_str(),
                                            batch.value("cutter", "").c_str(), batch.value("stage", "").c_str(),
                                            batch["jobs"].size(), batch.value("pieces", 0),
                                            reason.empty() ? "" : (" - " + reason).c_str()));
    }
    for (const auto& hide : status["hides"]) {
      overview.hides.push_back({hide.value("hide", ""), hide.value("batch", ""), hide.value("cutter", ""),
                                hide.value("material", ""), hide.value("stage", ""), hide.value("pieces", 0),
                                hide.value("utilisation", 0.0)});
    }
    for (const auto& batch : status["cut_last_24h"]) {
      overview.cut_last_24h.push_back({batch.value("id", ""), batch.value("cut_at", ""), batch.value("material", ""),
                                       batch.value("jobs", 0LL), batch.value("pieces", 0), batch.value("utilisation", 0.0)});
    }
    for (const auto& job : status["work"]) overview.in_work.push_back(job_line(job));
    for (const auto& job : status["held"]) overview.held.push_back(job_line(job));
    for (const auto& job : status["recent"]) overview.recent.push_back(job_line(job));
    return overview;
  }

  std::string id_problem(const std::string& /*job_id: any folder name; requeue says when it is unknown*/) const override {
    return "";
  }

  Result<std::string> requeue(const std::string& id, bool again) override {
    const auto folder = spool_.locate(id);
    if (!folder) return Status::failure("no job " + id + " in " + spool_.root().string());
    if (*folder == JobFolder::Work) return Status::failure("job " + id + " is already in work");
    auto state = spool_.read_state(*folder, id);
    if (!state) return Status::failure("job " + id + ": state.json is unreadable");
    if (*folder == JobFolder::Done && state->stage != JobStage::Skipped && !again) {
      return Status::failure("job " + id + " was already cut; add --again to cut it once more");
    }
    if (*folder == JobFolder::Done && !state->parts.empty()) {  // cut once more: every part again
      const std::vector<JobPart> parts = state->parts;
      state->part = 0;
      state->take_parts(parts);
    }
    std::error_code error;
    const bool has_molds =
        std::filesystem::exists(job_items_path(spool_.job_dir(*folder, id), state->ticket.material), error);
    const bool recompute = *folder == JobFolder::Failed || !has_molds;
    state->batch_id.clear();
    state->reason.clear();
    state->attempts = 0;
    state->advance(recompute ? JobStage::Claimed : JobStage::Computed,
                   "requeued by an operator from " + folder_name(*folder) + "/");
    if (Status moved = spool_.move_job(*folder, JobFolder::Work, *state); !moved) return moved;
    return "job " + id + " is back in work/; lastcutd takes it up within a second";
  }

  Result<JobRecord> job_record(const std::string& job_id) override {
    const auto folder = spool_.locate(job_id);
    if (!folder) return Status::failure("no job " + job_id + " in " + spool_.root().string());
    const auto dir = spool_.job_dir(*folder, job_id);
    return JobRecord{dir, read_json_or_null(dir / "state.json")};
  }

  Result<std::string> cancel_batch(const std::string& batch_id, const std::string& who) override {
    if (!spool_.read_batch(batch_id)) return Status::failure("no batch " + batch_id + " in " + spool_.root().string());
    // Under the batch's lock, as the cutter worker's `sending`: one of the two wins (batch_lock.hpp).
    const auto lock = BatchLock::take(spool_.batch_dir(batch_id));
    if (!lock) return lock.status();
    auto batch = spool_.read_batch(batch_id);
    if (!batch) return Status::failure("batch.json of " + batch_id + " unreadable");
    if (batch->stage != BatchStage::Queued || !batch->stage_problem.empty()) {
      return Status::failure("batch " + batch_id + " is " + std::string(to_string(batch->stage)) +
                             ": only a batch waiting for its cutter can be cancelled");
    }
    const std::string reason = cancel_reason(batch_id, who);
    if (!set_batch_stage(spool_, *batch, BatchStage::Held, reason))
      return Status::failure("batch " + batch_id + " not cancelled: batch.json not written");
    hold_batch_jobs(spool_, *batch, reason);
    return cancelled_line(batch_id, static_cast<long long>(batch->job_ids.size()));
  }

 private:
  Spool spool_;
};

}  // namespace

nlohmann::json read_json_or_null(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  auto json = nlohmann::json::parse(in, nullptr, false);
  return json.is_discarded() ? nlohmann::json(nullptr) : json;
}

std::unique_ptr<StoreView> make_spool_view(const std::string& spool_dir) {
  return std::make_unique<SpoolView>(spool_dir);
}

}  // namespace lastcut::daemon
