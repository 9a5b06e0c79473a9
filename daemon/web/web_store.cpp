// WebStore (web_store.hpp).
#include "daemon/web/web_store.hpp"

#include <algorithm>

#include "daemon/spool/spool.hpp"
#include "daemon/web/web_route.hpp"

namespace lastcut::daemon {
namespace {

constexpr std::size_t kRecentJobs = 50;
constexpr std::size_t kIncomingShown = 200;
constexpr auto kOverviewMaxAge = std::chrono::milliseconds(500);

nlohmann::json job_json(const JobLine& job, const char* list) {
  return {{"id", job.id},       {"state", job.state}, {"where", job.where}, {"order", job.order},
          {"scan", job.scan},   {"reason", job.reason}, {"list", list}, {"parts", job.parts}};
}

// Scans waiting in the watch folder, not yet taken by the station (names only).
nlohmann::json incoming_files(const std::filesystem::path& watch_dir) {
  std::vector<std::string> names;
  std::error_code error;
  for (std::filesystem::directory_iterator it(watch_dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.empty() || name[0] == '.' || !it->is_regular_file(error)) continue;
    names.push_back(name);
    if (names.size() >= kIncomingShown) break;
  }
  std::sort(names.begin(), names.end());
  return names;
}

// The files of a job folder the page may show: its own top-level files, its molds/ and a style job's pieces/.
nlohmann::json job_files(const std::filesystem::path& dir) {
  nlohmann::json files = nlohmann::json::array();
  std::error_code error;
  for (const char* sub : {"", "molds", "pieces"}) {
    std::vector<std::string> names;
    for (std::filesystem::directory_iterator it(dir / sub, error), end; !error && it != end; it.increment(error)) {
      const std::string name = it->path().filename().string();
      if (safe_name(name) && it->is_regular_file(error)) names.push_back(*sub ? std::string(sub) + "/" + name : name);
    }
    error.clear();
    std::sort(names.begin(), names.end());
    for (auto& name : names) files.push_back(name);
  }
  return files;
}

}  // namespace

WebStore::WebStore(std::shared_ptr<const DaemonConfig> config)
    : config_(std::move(config)), view_(open_store_view(*config_)) {}

Result<nlohmann::json> WebStore::overview() {
  std::lock_guard lock(mutex_);
  const auto now = std::chrono::steady_clock::now();
  if (cached_ && now - cached_at_ < kOverviewMaxAge) return *cached_;
  auto read = view_->overview(kRecentJobs);
  if (!read) return read.status();
  nlohmann::json queued = nlohmann::json::array();
  for (const QueuedBatch& batch : read->queued_batches)
    queued.push_back({{"id", batch.id}, {"cutter", batch.cutter}, {"jobs", batch.jobs}, {"pieces", batch.pieces}});
  // A nested hide's report (hide_step.cpp) says what is left of it: the offcut and its file.
  nlohmann::json hides = nlohmann::json::array();
  for (const HideLine& hide : read->hides) {
    nlohmann::json line = {{"hide", hide.hide},     {"batch", hide.batch_id}, {"cutter", hide.cutter},
                           {"material", hide.material}, {"state", hide.state}, {"pieces", hide.pieces},
                           {"utilisation", hide.utilisation}};
    if (!hide.batch_id.empty()) {
      if (const auto report = batch_file(hide.batch_id, "hide-report.json")) {
        const nlohmann::json figures = read_json_or_null(*report);
        if (figures.is_object()) {
          line["usable_area_m2"] = figures.value("usable_area_m2", 0.0);
          line["offcut_area_m2"] = figures.value("offcut_area_m2", 0.0);
          line["offcut_file"] = figures.value("offcut_file", "");
          if (figures.contains("pairs_mirrored_about_backbone")) line["pairs_mirrored"] = figures["pairs_mirrored_about_backbone"];
        }
      }
    }
    hides.push_back(line);
  }
  nlohmann::json cut = nlohmann::json::array();
  for (const CutBatch& batch : read->cut_last_24h) {
    cut.push_back({{"batch", batch.batch_id}, {"cut_at", batch.cut_at_utc}, {"material", batch.material},
                   {"jobs", batch.jobs}, {"pieces", batch.pieces}, {"utilisation", batch.utilisation}});
  }
  nlohmann::json jobs = nlohmann::json::array();
  for (const JobLine& job : read->in_work) jobs.push_back(job_json(job, "work"));
  for (const JobLine& job : read->held) jobs.push_back(job_json(job, "held"));
  for (const JobLine& job : read->recent) jobs.push_back(job_json(job, "recent"));
  nlohmann::json out = {{"mode", config_->ledger ? "ledger" : "spool"},
                        {"headline", read->headline},
                        {"stations", read->station_lines},
                        {"cutters", read->cutter_lines},
                        {"batches", read->batch_lines},
                        {"queued_batches", queued},
                        {"hides", hides},
                        {"cut_last_24h", cut},
                        {"waiting_for_hide", read->waiting_for_hide},
                        {"pieces_waiting_for_hide", read->pieces_waiting_for_hide},
                        {"incoming", incoming_files(config_->paths.watch_dir)},
                        {"jobs", jobs},
                        {"can_act", !config_->web || !config_->web->tokens.empty()}};
  cached_ = out;
  cached_at_ = now;
  return out;
}

Result<JobRecord> WebStore::record(const std::string& id) {
  std::lock_guard lock(mutex_);
  if (std::string problem = view_->id_problem(id); !problem.empty()) return Status::failure(problem);
  return view_->job_record(id);
}

Result<nlohmann::json> WebStore::job(const std::string& id) {
  const auto found = record(id);
  auto all = overview();
  if (!all) return all.status();
  nlohmann::json out = {{"id", id}};
  for (const auto& line : (*all)["jobs"])
    if (line["id"] == id) out["line"] = line;
  if (found) {
    out["state"] = found->state;
    out["report"] = read_json_or_null(found->folder / "report.json");
    out["files"] = job_files(found->folder);
  } else if (!out.contains("line")) {
    return found.status();
  }
  return out;
}

namespace {

// A symbolic link could lead anywhere; only a folder's own regular files are served.
Result<std::filesystem::path> regular_file_in(const std::filesystem::path& dir, const std::string& name,
                                              const std::string& owner) {
  std::error_code error;
  const std::filesystem::path file = dir / name;
  if (!std::filesystem::is_regular_file(std::filesystem::symlink_status(file, error)))
    return Status::failure(owner + " has no file " + name);
  return file;
}

}  // namespace

Result<std::filesystem::path> WebStore::job_file(const std::string& id, const std::string& name) {
  const auto found = record(id);
  if (!found) return found.status();
  return regular_file_in(found->folder, name, "job " + id);
}

Result<std::filesystem::path> WebStore::batch_file(const std::string& batch_id, const std::string& name) {
  const std::filesystem::path dir = config_->ledger ? config_->ledger->shared_dir / "batches" / batch_id
                                                    : Spool(config_->paths.spool_dir).batch_dir(batch_id);
  return regular_file_in(dir, name, "batch " + batch_id);
}

Result<std::string> WebStore::requeue(const std::string& id) {
  std::lock_guard lock(mutex_);
  if (std::string problem = view_->id_problem(id); !problem.empty()) return Status::failure(problem);
  cached_.reset();
  return view_->requeue(id, false);
}

Result<std::string> WebStore::cancel_batch(const std::string& batch_id, const std::string& who) {
  std::lock_guard lock(mutex_);
  cached_.reset();
  return view_->cancel_batch(batch_id, who);
}

}  // namespace lastcut::daemon
