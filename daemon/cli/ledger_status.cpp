// The ledger side of `lastcut status` and `lastcut requeue` (see ledger_status.hpp).
#include "daemon/cli/ledger_status.hpp"

#include <algorithm>
#include <cstdio>
#include <optional>

#include <nlohmann/json.hpp>

#include "daemon/config/config_loader.hpp"
#include "daemon/ledger/ledger_client.hpp"
#include "daemon/ledger/ledger_connection.hpp"

namespace lastcut::cli {
namespace {

std::optional<daemon::LedgerConfig> ledger_of(const std::string& config_file, const std::string& spool_dir,
                                              std::vector<std::string>* hide_materials = nullptr) {
  if (!spool_dir.empty()) return std::nullopt;
  const auto loaded = daemon::load_daemon_config(config_file);
  if (!loaded.config) return std::nullopt;  // the spool path reports the configuration's problem
  for (const auto& [name, material] : loaded.config->materials)
    if (hide_materials && material.kind == daemon::MaterialKind::Hide) hide_materials->push_back(name);
  return loaded.config->ledger;
}

nlohmann::json hide_json(const ledger::HideRow& hide) {
  return {{"name", hide.name},          {"state", hide.state},       {"material", hide.material},
          {"cutter", hide.cutter},      {"area_m2", hide.area_m2},   {"batch", hide.batch_id},
          {"pieces", hide.pieces},      {"utilisation", hide.utilisation}, {"reason", hide.reason},
          {"entered_by", hide.entered_by}};
}

void print_hide(const nlohmann::json& hide) {
  std::string detail;
  if (hide["batch"].get<long long>() != 0 && hide["state"] == "used") {
    char text[160];
    std::snprintf(text, sizeof(text), "batch %lld, %d pieces, %.1f %% of its usable area",
                  hide["batch"].get<long long>(), hide["pieces"].get<int>(), 100.0 * hide["utilisation"].get<double>());
    detail = text;
  } else {
    detail = hide["reason"].get<std::string>();
  }
  std::printf("  hide %-14s %-9s %-10s on %-12s %.2f m^2  %s\n", hide["name"].get<std::string>().c_str(),
              hide["state"].get<std::string>().c_str(), hide["material"].get<std::string>().c_str(),
              hide["cutter"].get<std::string>().c_str(), hide["area_m2"].get<double>(), detail.c_str());
}

nlohmann::json job_json(const ledger::JobRow& job) {
  return {{"id", job.job_id},         {"state", job.state},   {"scan", job.scan_name},   {"cutter", job.cutter},
          {"material", job.material}, {"origin", job.origin}, {"reason", job.reason},    {"holder", job.holder},
          {"batch", job.batch_id},    {"attempts", job.attempts}};
}

void print_job(const nlohmann::json& job) {
  const std::string holder = job["holder"];
  std::printf("  %-8lld %-9s %-12s %-24s %s%s\n", job["id"].get<long long>(), job["state"].get<std::string>().c_str(),
              job["cutter"].get<std::string>().c_str(), job["scan"].get<std::string>().c_str(),
              holder.empty() ? "" : ("on " + holder + " ").c_str(), job["reason"].get<std::string>().c_str());
}

}  // namespace

bool ledger_status(const std::string& config_file, const std::string& spool_dir, std::size_t recent_count, bool as_json,
                   int& exit_code) {
  std::vector<std::string> hide_materials;
  const auto config = ledger_of(config_file, spool_dir, &hide_materials);
  if (!config) return false;
  const auto fail = [&](const std::string& why) {
    std::fprintf(stderr, "lastcut status: %s\n", why.c_str());
    exit_code = 1;
    return true;
  };
  auto client = ledger::LedgerClient::connect(config->url, config->node);
  if (!client) return fail(client.error());
  auto overview = (*client)->overview();
  if (!overview) return fail(overview.error());
  auto held = (*client)->recent_jobs(1000, "held");
  if (!held) return fail(held.error());
  auto recent = (*client)->recent_jobs(static_cast<int>(recent_count));
  if (!recent) return fail(recent.error());
  auto hides = (*client)->recent_hides(static_cast<int>(recent_count));
  if (!hides) return fail(hides.error());

  nlohmann::json status{{"ledger", ledger::redact_url(config->url)}, {"node", config->node}};
  status["jobs"] = nlohmann::json::object();
  for (const auto& [state, count] : overview->jobs_per_state) status["jobs"][state] = count;
  status["nodes"] = nlohmann::json::array();
  for (const auto& node : overview->nodes) {
    status["nodes"].push_back({{"name", node.name}, {"roles", node.roles}, {"heartbeat_age_s", node.heartbeat_age_s}});
  }
  status["cutters"] = nlohmann::json::array();
  for (const auto& cutter : overview->cutters) {
    status["cutters"].push_back(
        {{"name", cutter.name}, {"station", cutter.station}, {"queued_batches", cutter.queued_batches}});
  }
  // Computed jobs of a hide material are waiting for a hide to be laid on a cutter's table.
  status["waiting_for_hide"] = nlohmann::json::object();
  for (const auto& [material, count] : overview->computed_per_material)
    if (std::find(hide_materials.begin(), hide_materials.end(), material) != hide_materials.end())
      status["waiting_for_hide"][material] = count;
  status["hides"] = nlohmann::json::array();
  for (const auto& hide : *hides) status["hides"].push_back(hide_json(hide));
  status["held"] = nlohmann::json::array();
  for (const auto& job : *held) status["held"].push_back(job_json(job));
  status["recent"] = nlohmann::json::array();
  for (const auto& job : *recent) status["recent"].push_back(job_json(job));
  exit_code = 0;
  if (as_json) {
    std::printf("%s\n", status.dump(2).c_str());
    return true;
  }
  std::string counts;
  for (const auto& [state, count] : overview->jobs_per_state) {
    counts += (counts.empty() ? "" : ", ") + std::to_string(count) + " " + state;
  }
  std::printf("ledger %s: %s\n", status["ledger"].get<std::string>().c_str(), counts.empty() ? "no jobs" : counts.c_str());
  for (const auto& node : overview->nodes) {
    std::printf("  node %-16s %-16s heartbeat %.0f s ago\n", node.name.c_str(), node.roles.c_str(), node.heartbeat_age_s);
  }
  for (const auto& cutter : overview->cutters) {
    std::printf("  cutter %-14s at %s, %lld batch(es) queued\n", cutter.name.c_str(), cutter.station.c_str(),
                cutter.queued_batches);
  }
  for (const auto& [material, count] : status["waiting_for_hide"].items()) {
    std::printf("%lld job(s) of %s waiting for a hide (drop a hide file, or lastcut hide load ID --cutter X)\n",
                count.get<long long>(), material.c_str());
  }
  if (!status["hides"].empty()) std::printf("hides:\n");
  for (const auto& hide : status["hides"]) print_hide(hide);
  if (!status["held"].empty()) std::printf("held (waiting for an operator: lastcut requeue ID):\n");
  for (const auto& job : status["held"]) print_job(job);
  if (!status["recent"].empty()) std::printf("recent:\n");
  for (const auto& job : status["recent"]) print_job(job);
  return true;
}

bool ledger_requeue(const std::string& config_file, const std::string& spool_dir, const std::string& job_id,
                    int& exit_code) {
  const auto config = ledger_of(config_file, spool_dir);
  if (!config) return false;
  const auto fail = [&](const std::string& why) {
    std::fprintf(stderr, "lastcut requeue: %s\n", why.c_str());
    exit_code = 1;
    return true;
  };
  long long id = 0;
  try {
    std::size_t used = 0;
    id = std::stoll(job_id, &used);
    if (used != job_id.size() || id <= 0) throw std::invalid_argument(job_id);
  } catch (const std::exception&) {
    exit_code = 2;
    std::fprintf(stderr, "lastcut requeue: \"%s\" is not a ledger job id (a whole number, see lastcut status)\n",
                 job_id.c_str());
    return true;
  }
  auto client = ledger::LedgerClient::connect(config->url, config->node);
  if (!client) return fail(client.error());
  if (Status requeued = (*client)->requeue_held(id); !requeued) return fail(requeued.error());
  std::printf("job %lld is back in the ledger's queue; a compute node takes it up\n", id);
  exit_code = 0;
  return true;
}

}  // namespace lastcut::cli
