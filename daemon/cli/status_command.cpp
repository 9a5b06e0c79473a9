// `lastcut status`, `lastcut requeue ID` and `lastcut cancel BATCH`: the operator's view of the jobs,
// the one decision the daemon never takes alone (cutting a held job again), and taking back a batch
// before it is cut. Written once against StoreView
// (store_view.hpp): the configuration decides whether that is the station's spool or the shop's ledger.
#include <cstdio>
#include <cstdlib>
#include <string>

#include "daemon/cli/commands.hpp"
#include "daemon/store_view/store_view.hpp"

namespace lastcut::cli {

using daemon::JobLine;
using daemon::StoreOverview;
using daemon::open_store_view;

namespace {

void print_jobs(const char* heading, const std::vector<JobLine>& jobs) {
  if (!jobs.empty()) std::printf("%s\n", heading);
  for (const JobLine& job : jobs) {
    std::printf("  %-20s %-9s %-8s %-10s %-24s %s\n", job.id.c_str(), job.state.c_str(), job.where.c_str(),
                job.order.empty() ? "-" : job.order.c_str(), job.scan.c_str(), job.reason.c_str());
    if (!job.parts.empty()) std::printf("  %-20s parts: %s\n", "", job.parts.c_str());
  }
}

void print_overview(const StoreOverview& overview) {
  std::printf("%s\n", overview.headline.c_str());
  for (const std::string& line : overview.station_lines) std::printf("  %s\n", line.c_str());
  for (const std::string& line : overview.cutter_lines) std::printf("  %s\n", line.c_str());
  for (const auto& [material, count] : overview.waiting_for_hide) {
    const auto pieces = overview.pieces_waiting_for_hide.find(material);
    std::printf("  %lld job(s) of %s waiting for a hide, %lld pieces (drop a hide file in the hides folder, or lastcut hide load)\n",
                count, material.c_str(), pieces == overview.pieces_waiting_for_hide.end() ? 0LL : pieces->second);
  }
  for (const std::string& line : overview.batch_lines) std::printf("  %s\n", line.c_str());
  print_jobs("in work:", overview.in_work);
  print_jobs("held (waiting for an operator: lastcut requeue ID):", overview.held);
  print_jobs("recent:", overview.recent);
}

}  // namespace

void add_status_commands(CLI::App& app, int& exit_code) {
  static std::string config_file = "/etc/lastcut/lastcut.toml";
  static std::string spool_dir;
  static bool as_json = false;
  static std::size_t recent_count = 10;
  // One line on stderr and the exit status: 2 when the command cannot know where the jobs are, 1
  // when the store refused or could not be reached.
  const auto fail = [&exit_code](const char* command, const std::string& why, int code) {
    std::fprintf(stderr, "lastcut %s: %s\n", command, why.c_str());
    exit_code = code;
  };
  auto* status = app.add_subcommand("status", "queue, cutters and recent jobs of the spool or the shop's ledger");
  status->add_option("-c,--config", config_file, "lastcutd configuration (its spool folder or [ledger])");
  status->add_option("--spool", spool_dir, "spool folder (instead of reading the configuration)");
  status->add_option("--recent", recent_count, "how many recent jobs to list");
  status->add_flag("--json", as_json, "print the store's JSON document instead of text");
  status->callback([fail] {
    auto view = open_store_view(config_file, spool_dir);
    if (!view) return fail("status", view.error(), 2);
    const Result<StoreOverview> overview = (*view)->overview(recent_count);
    if (!overview) return fail("status", overview.error(), 1);
    if (as_json) std::printf("%s\n", overview->json.dump(2).c_str());
    else print_overview(*overview);
  });

  static std::string job_id;
  static bool again = false;
  auto* requeue = app.add_subcommand("requeue", "send a held (or failed) job through the pipeline again");
  requeue->add_option("id", job_id, "job id (see lastcut status)")->required();
  requeue->add_option("-c,--config", config_file, "lastcutd configuration (its spool folder or [ledger])");
  requeue->add_option("--spool", spool_dir, "spool folder (instead of reading the configuration)");
  requeue->add_flag("--again", again, "also requeue a job that was already cut (cut it once more; spool only)");
  requeue->callback([fail] {
    auto view = open_store_view(config_file, spool_dir);
    if (!view) return fail("requeue", view.error(), 2);
    if (const std::string problem = (*view)->id_problem(job_id); !problem.empty()) return fail("requeue", problem, 2);
    const Result<std::string> requeued = (*view)->requeue(job_id, again);
    if (!requeued) return fail("requeue", requeued.error(), 1);
    std::printf("%s\n", requeued->c_str());
  });

  static std::string batch_id;
  auto* cancel = app.add_subcommand(
      "cancel", "hold a nested batch that waits for its cutter, with its jobs (requeue them to nest them again)");
  cancel->add_option("batch", batch_id, "batch id (see lastcut status)")->required();
  cancel->add_option("-c,--config", config_file, "lastcutd configuration (its spool folder or [ledger])");
  cancel->add_option("--spool", spool_dir, "spool folder (instead of reading the configuration)");
  cancel->callback([fail] {
    auto view = open_store_view(config_file, spool_dir);
    if (!view) return fail("cancel", view.error(), 2);
    const char* user = std::getenv("USER");
    const std::string who = std::string(user != nullptr && *user != '\0' ? user : "an operator") + " (lastcut cancel)";
    const Result<std::string> cancelled = (*view)->cancel_batch(batch_id, who);
    if (!cancelled) return fail("cancel", cancelled.error(), 1);
    std::printf("%s\n", cancelled->c_str());
  });
}

}  // namespace lastcut::cli
