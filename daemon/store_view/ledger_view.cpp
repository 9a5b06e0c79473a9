// The ledger's StoreView (store_view.hpp): the shop's PostgreSQL ledger (docs/multi-station.md),
// read and written from any node, so status and requeue act on the whole shop.
#include <algorithm>
#include <cstdio>

#include "daemon/store_view/store_view.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::daemon {
namespace {

nlohmann::json hide_json(const ledger::HideRow& hide) {
  return {{"name", hide.name},          {"state", hide.state},       {"material", hide.material},
          {"cutter", hide.cutter},      {"area_m2", hide.area_m2},   {"batch", hide.batch_id},
          {"pieces", hide.pieces},      {"utilisation", hide.utilisation}, {"reason", hide.reason},
          {"entered_by", hide.entered_by}};
}

std::string hide_line(const ledger::HideRow& hide) {
  const std::string detail =
      hide.batch_id != 0 && hide.state == "used"
          ? format_line("batch %lld, %d pieces, %.1f %% of its usable area", hide.batch_id, hide.pieces, 100.0 * hide.utilisation)
          : hide.reason;
  return format_line("hide %-14s %-9s %-10s on %-12s %.2f m^2  %s", hide.name.c_str(), hide.state.c_str(),
                hide.material.c_str(), hide.cutter.c_str(), hide.area_m2, detail.c_str());
}

nlohmann::json job_json(const ledger::JobRow& job) {
  return {{"id", job.job_id},         {"state", job.state},   {"scan", job.scan_name},   {"cutter", job.cutter},
          {"material", job.material}, {"origin", job.origin}, {"reason", job.reason},    {"holder", job.holder},
          {"batch", job.batch_id},    {"attempts", job.attempts}, {"parts", parts_progress(job.parts, job.part, job.state == "done")}};
}

JobLine job_line(const ledger::JobRow& job) {
  return {std::to_string(job.job_id), job.state, job.holder.empty() ? "" : "on " + job.holder, "", job.scan_name,
          job.reason, parts_progress(job.parts, job.part, job.state == "done")};
}

class LedgerView : public StoreView {
 public:
  LedgerView(LedgerConfig ledger, std::vector<std::string> hide_materials)
      : ledger_(std::move(ledger)), hide_materials_(std::move(hide_materials)) {}

  Result<StoreOverview> overview(std::size_t recent_count) override {
    if (Status connected = connect(); !connected) return connected;
    auto overview_rows = client_->overview();
    if (!overview_rows) return overview_rows.status();
    auto held = client_->recent_jobs(1000, "held");
    if (!held) return held.status();
    auto recent = client_->recent_jobs(static_cast<int>(recent_count));
    if (!recent) return recent.status();
    auto hides = client_->recent_hides(static_cast<int>(recent_count));
    if (!hides) return hides.status();

    StoreOverview overview;
    nlohmann::json& status = overview.json;
    status = {{"ledger", ledger::redact_url(ledger_.url)}, {"node", ledger_.node}};
    status["jobs"] = nlohmann::json::object();
    std::string counts;
    for (const auto& [state, count] : overview_rows->jobs_per_state) {
      status["jobs"][state] = count;
      counts += (counts.empty() ? "" : ", ") + std::to_string(count) + " " + state;
    }
    overview.headline = "ledger " + status["ledger"].get<std::string>() + ": " + (counts.empty() ? "no jobs" : counts);
    status["nodes"] = nlohmann::json::array();
    for (const auto& node : overview_rows->nodes) {
      status["nodes"].push_back({{"name", node.name}, {"roles", node.roles}, {"heartbeat_age_s", node.heartbeat_age_s}});
      overview.station_lines.push_back(
          format_line("node %-16s %-16s heartbeat %.0f s ago", node.name.c_str(), node.roles.c_str(), node.heartbeat_age_s));
    }
    status["cutters"] = nlohmann::json::array();
    for (const auto& cutter : overview_rows->cutters) {
      status["cutters"].push_back(
          {{"name", cutter.name}, {"station", cutter.station}, {"queued_batches", cutter.queued_batches}});
      overview.cutter_lines.push_back(format_line("cutter %-14s at %s, %lld batch(es) queued", cutter.name.c_str(),
                                             cutter.station.c_str(), cutter.queued_batches));
    }
    // Computed jobs of a hide material are waiting for a hide to be laid on a cutter's table.
    status["waiting_for_hide"] = nlohmann::json::object();
    status["pieces_waiting_for_hide"] = nlohmann::json::object();
    for (const auto& waiting : overview_rows->computed_per_material) {
      if (std::find(hide_materials_.begin(), hide_materials_.end(), waiting.material) == hide_materials_.end()) continue;
      status["waiting_for_hide"][waiting.material] = waiting.jobs;
      status["pieces_waiting_for_hide"][waiting.material] = waiting.pieces;
      overview.waiting_for_hide[waiting.material] = waiting.jobs;
      overview.pieces_waiting_for_hide[waiting.material] = waiting.pieces;
    }
    status["queued_batches"] = nlohmann::json::array();
    for (const auto& batch : overview_rows->queued_batches) {
      status["queued_batches"].push_back(
          {{"id", batch.id}, {"cutter", batch.cutter}, {"jobs", batch.jobs}, {"pieces", batch.pieces}});
      overview.queued_batches.push_back({std::to_string(batch.id), batch.cutter, batch.jobs, batch.pieces});
    }
    status["hides"] = nlohmann::json::array();
    for (const auto& hide : *hides) {
      status["hides"].push_back(hide_json(hide));
      overview.batch_lines.push_back(hide_line(hide));
      overview.hides.push_back({hide.name, hide.batch_id != 0 ? std::to_string(hide.batch_id) : "", hide.cutter,
                                hide.material, hide.state, hide.pieces, hide.utilisation});
    }
    status["cut_last_24h"] = nlohmann::json::array();
    for (const auto& batch : overview_rows->cut_last_24h) {
      status["cut_last_24h"].push_back({{"id", batch.id}, {"cut_at", batch.cut_at_utc}, {"material", batch.material},
                                        {"jobs", batch.jobs}, {"pieces", batch.pieces}, {"utilisation", batch.utilisation}});
      overview.cut_last_24h.push_back({std::to_string(batch.id), batch.cut_at_utc, batch.material, batch.jobs,
                                       batch.pieces, batch.utilisation});
    }
    status["held"] = nlohmann::json::array();
    for (const auto& job : *held) {
      status["held"].push_back(job_json(job));
      overview.held.push_back(job_line(job));
    }
    status["recent"] = nlohmann::json::array();
    for (const auto& job : *recent) {
      status["recent"].push_back(job_json(job));
      overview.recent.push_back(job_line(job));
    }
    return overview;
  }

  std::string id_problem(const std::string& job_id) const override {
    try {
      std::size_t used = 0;
      const long long id = std::stoll(job_id, &used);
      if (used == job_id.size() && id > 0) return "";
    } catch (const std::exception&) {
    }
    return "\"" + job_id + "\" is not a ledger job id (a whole number, see lastcut status)";
  }

  Result<std::string> requeue(const std::string& job_id, bool again) override {
    if (again) return Status::failure("--again is for a spool; on the ledger a cut job is entered again as a new scan");
    if (Status connected = connect(); !connected) return connected;
    if (Status requeued = client_->requeue_held(std::stoll(job_id)); !requeued) return requeued;
    return "job " + job_id + " is back in the ledger's queue; a compute node takes it up";
  }

  Result<JobRecord> job_record(const std::string& job_id) override {
    if (std::string problem = id_problem(job_id); !problem.empty()) return Status::failure(problem);
    if (Status connected = connect(); !connected) return connected;
    const auto detail = client_->job_detail(std::stoll(job_id));
    if (!detail) return detail.status();
    nlohmann::json history = nlohmann::json::array();
    for (const auto& event : detail->history)
      history.push_back({{"at", event.at_utc}, {"stage", event.event}, {"note", event.detail + " (" + event.node + ")"}});
    return JobRecord{ledger_.shared_dir / "jobs" / detail->job_folder,
                     {{"stage", detail->state}, {"reason", detail->reason}, {"history", history}}};
  }

  Result<std::string> cancel_batch(const std::string& batch_id, const std::string& who) override {
    if (std::string problem = id_problem(batch_id); !problem.empty())
      return Status::failure("\"" + batch_id + "\" is not a ledger batch id (a whole number)");
    if (Status connected = connect(); !connected) return connected;
    const auto held = client_->cancel_queued_batch(std::stoll(batch_id), cancel_reason(batch_id, who));
    if (!held) return held.status();
    return cancelled_line(batch_id, *held);
  }

 private:
  Status connect() {
    if (client_) return Status::success();
    auto connected = ledger::LedgerClient::connect(ledger_.url, ledger_.node);
    if (!connected) return connected.status();
    client_ = std::move(*connected);
    return Status::success();
  }

  LedgerConfig ledger_;
  std::vector<std::string> hide_materials_;
  std::unique_ptr<ledger::LedgerClient> client_;
};

}  // namespace

std::unique_ptr<StoreView> make_ledger_view(const LedgerConfig& ledger, std::vector<std::string> hide_materials) {
  return std::make_unique<LedgerView>(ledger, std::move(hide_materials));
}

}  // namespace lastcut::daemon
