// `lastcut status` and `lastcut requeue ID`: the operator's view of the spool and the one
// decision the daemon never takes alone (cutting a held job again). Both read the spool folders
// directly, so they work while lastcutd runs (and when it does not).
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <string>
#include <vector>

#include <fstream>
#include <nlohmann/json.hpp>

#include "daemon/cli/commands.hpp"
#include "daemon/cli/ledger_status.hpp"
#include "daemon/config/config_loader.hpp"
#include "daemon/station/engine_steps.hpp"
#include "daemon/spool/spool.hpp"

namespace lastcut::cli {
namespace {

using daemon::JobFolder;

Result<std::string> spool_from(const std::string& config_file, const std::string& spool_dir) {
  if (!spool_dir.empty()) return spool_dir;
  const auto result = daemon::load_daemon_config(config_file);
  if (!result.config) return Status::failure(result.error);
  return result.config->paths.spool_dir.string();
}

nlohmann::json read_json(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return nullptr;
  auto json = nlohmann::json::parse(in, nullptr, false);
  return json.is_discarded() ? nlohmann::json(nullptr) : json;
}

nlohmann::json job_summary(const daemon::JobState& state, JobFolder folder) {
  return {{"id", state.id},         {"folder", daemon::folder_name(folder)}, {"stage", daemon::to_string(state.stage)},
          {"order", state.ticket.order}, {"scan", state.scan_name},         {"cutter", state.ticket.cutter},
          {"material", state.ticket.material}, {"reason", state.reason},  {"updated_at", state.updated_at}};
}

nlohmann::json collect_status(const daemon::Spool& spool, std::size_t recent_count) {
  nlohmann::json status;
  const nlohmann::json daemon_status = read_json(spool.root() / "status.json");
  status["daemon"] = daemon_status.is_null() ? nlohmann::json{{"running", false}} : daemon_status;
  if (!daemon_status.is_null()) status["daemon"]["running"] = true;
  nlohmann::json counts, work = nlohmann::json::array(), held = nlohmann::json::array();
  std::vector<std::pair<std::string, nlohmann::json>> finished;
  for (JobFolder folder : {JobFolder::Work, JobFolder::Done, JobFolder::Failed, JobFolder::Held}) {
    const auto ids = spool.list(folder);
    counts[daemon::folder_name(folder)] = ids.size();
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
  nlohmann::json batches = nlohmann::json::array();
  for (const std::string& id : spool.list_batches()) {
    auto batch = spool.read_batch(id);
    // A batch.json without a known stage is shown too: it is held until an operator looks.
    if (batch && (daemon::in_progress(batch->stage) || !batch->stage_problem.empty())) {
      batches.push_back({{"id", batch->id}, {"cutter", batch->cutter}, {"stage", daemon::to_string(batch->stage)},
                         {"jobs", batch->job_ids}, {"pieces", batch->piece_count}, {"reason", batch->reason}});
    }
  }
  status["counts"] = counts;
  status["work"] = work;
  status["held"] = held;
  status["active_batches"] = batches;
  status["recent"] = recent;
  return status;
}

void print_status(const nlohmann::json& status, const std::string& spool_dir) {
  const auto& daemon_status = status["daemon"];
  if (daemon_status.value("running", false)) {
    std::printf("lastcutd: running (pid %ld, status of %s)\n", daemon_status.value("pid", 0L),
                daemon_status.value("updated_at", "?").c_str());
  } else {
    std::printf("lastcutd: not running (no %s/status.json)\n", spool_dir.c_str());
  }
  const auto& counts = status["counts"];
  std::printf("spool %s: %d in work, %d done, %d failed, %d held\n", spool_dir.c_str(), counts.value("work", 0),
              counts.value("done", 0), counts.value("failed", 0), counts.value("held", 0));
  if (daemon_status.contains("cutters")) {
    for (const auto& [name, cutter] : daemon_status["cutters"].items()) {
      std::printf("  cutter %-12s %s, %d batch(es) queued\n", name.c_str(), cutter.value("condition", "?").c_str(),
                  cutter.value("queued_batches", 0));
    }
  }
  if (daemon_status.contains("waiting_for_hide")) {
    for (const auto& [material, count] : daemon_status["waiting_for_hide"].items())
      std::printf("  %d job(s) of %s waiting for a hide (drop one in the hides folder, or lastcut hide load)\n",
                  count.get<int>(), material.c_str());
  }
  auto row = [](const nlohmann::json& job) {
    const std::string order = job.value("order", "");
    std::printf("  %-20s %-8s %-9s %-10s %-24s %s\n", job.value("id", "").c_str(), job.value("folder", "").c_str(),
                job.value("stage", "").c_str(), order.empty() ? "-" : order.c_str(), job.value("scan", "").c_str(),
                job.value("reason", "").c_str());
  };
  if (!status["work"].empty()) std::printf("in work:\n");
  for (const auto& job : status["work"]) row(job);
  for (const auto& batch : status["active_batches"]) {
    const std::string reason = batch.value("reason", "");
    std::printf("  batch %s for %s: %s, %zu job(s), %d pieces%s\n", batch.value("id", "").c_str(),
                batch.value("cutter", "").c_str(), batch.value("stage", "").c_str(), batch["jobs"].size(),
                batch.value("pieces", 0), reason.empty() ? "" : (" - " + reason).c_str());
  }
  if (!status["held"].empty()) std::printf("held (waiting for an operator: lastcut requeue ID):\n");
  for (const auto& job : status["held"]) row(job);
  if (!status["recent"].empty()) std::printf("recent:\n");
  for (const auto& job : status["recent"]) row(job);
}

// Fails with the reason the job cannot be requeued.
Status requeue(const daemon::Spool& spool, const std::string& id, bool again) {
  const auto folder = spool.locate(id);
  if (!folder) return Status::failure("no job " + id + " in " + spool.root().string());
  if (*folder == JobFolder::Work) return Status::failure("job " + id + " is already in work");
  auto state = spool.read_state(*folder, id);
  if (!state) return Status::failure("job " + id + ": state.json is unreadable");
  if (*folder == JobFolder::Done && state->stage != daemon::JobStage::Skipped && !again) {
    return Status::failure("job " + id + " was already cut; add --again to cut it once more");
  }
  std::error_code error;
  const bool has_molds = std::filesystem::exists(spool.job_dir(*folder, id) / daemon::kItemsFile, error);
  const bool recompute = *folder == JobFolder::Failed || !has_molds;
  state->batch_id.clear();
  state->reason.clear();
  state->attempts = 0;
  state->advance(recompute ? daemon::JobStage::Claimed : daemon::JobStage::Computed,
                 "requeued by an operator from " + daemon::folder_name(*folder) + "/");
  return spool.move_job(*folder, JobFolder::Work, *state);
}

}  // namespace

void add_spool_commands(CLI::App& app, int& exit_code) {
  static std::string config_file = "/etc/lastcut/lastcut.toml";
  static std::string spool_dir;
  static bool as_json = false;
  static std::size_t recent_count = 10;
  auto* status = app.add_subcommand("status", "queue, cutters and recent jobs of the running daemon's spool");
  status->add_option("-c,--config", config_file, "lastcutd configuration (for the spool folder)");
  status->add_option("--spool", spool_dir, "spool folder (instead of reading the configuration)");
  status->add_option("--recent", recent_count, "how many recent jobs to list");
  status->add_flag("--json", as_json, "print JSON instead of text");
  status->callback([&exit_code] {
    if (ledger_status(config_file, spool_dir, recent_count, as_json, exit_code)) return;
    const Result<std::string> found = spool_from(config_file, spool_dir);
    if (!found) {
      std::fprintf(stderr, "lastcut status: %s\n", found.error().c_str());
      exit_code = 2;
      return;
    }
    const std::string& root = *found;
    const daemon::Spool spool(root);
    const nlohmann::json result = collect_status(spool, recent_count);
    if (as_json) std::printf("%s\n", result.dump(2).c_str());
    else print_status(result, root);
  });

  static std::string job_id;
  static bool again = false;
  auto* requeue_command = app.add_subcommand("requeue", "send a held (or failed) job through the pipeline again");
  requeue_command->add_option("id", job_id, "job id (see lastcut status)")->required();
  requeue_command->add_option("-c,--config", config_file, "lastcutd configuration (for the spool folder)");
  requeue_command->add_option("--spool", spool_dir, "spool folder (instead of reading the configuration)");
  requeue_command->add_flag("--again", again, "also requeue a job that was already cut (cut it once more)");
  requeue_command->callback([&exit_code] {
    if (ledger_requeue(config_file, spool_dir, job_id, exit_code)) return;
    const Result<std::string> found = spool_from(config_file, spool_dir);
    if (!found) {
      std::fprintf(stderr, "lastcut requeue: %s\n", found.error().c_str());
      exit_code = 2;
      return;
    }
    const std::string& root = *found;
    const daemon::Spool spool(root);
    if (Status requeued = requeue(spool, job_id, again); !requeued) {
      std::fprintf(stderr, "lastcut requeue: %s\n", requeued.error().c_str());
      exit_code = 1;
      return;
    }
    std::printf("job %s is back in work/; lastcutd takes it up within a second\n", job_id.c_str());
  });
}

}  // namespace lastcut::cli
