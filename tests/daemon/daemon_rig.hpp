#pragma once
// DaemonRig: a whole installation in a scratch folder for end-to-end tests: simulated HPGL
// plotters or grbl tables (lastcut-sim) on pseudo-terminals, a generated configuration, lastcutd itself, and
// small generated lasts (lastcut generate) to drop into the watch folder.
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon_harness.hpp"

namespace lastcut::daemon::testing {

struct RigOptions {
  std::vector<std::string> cutters = {"cutter-1"};
  std::map<std::string, std::string> sim_faults;  // cutter -> --fault argument
  std::set<std::string> grbl_cutters;             // these are grbl tables (G-code); the others HPGL plotters
  std::string duplicate_policy = "skip";
  double batch_window_s = 0;
  int batch_max_pieces = 0;                       // [batch] max_pieces (0: no limit)
  std::string extra_config;                       // appended to the generated TOML
  std::string extra_paths;                        // appended to its [paths] table (e.g. hides = "hides")
  // When set (the built grbl_sim.exe), the grbl cutters are the real grbl 1.1h firmware behind a
  // pty (tests/peers/run_grbl_firmware.sh) instead of lastcut-sim; they keep a block log, no record.
  std::string grbl_firmware;
};

class DaemonRig {
 public:
  DaemonRig(const std::string& name, RigOptions options);
  ~DaemonRig();

  const std::filesystem::path& root() const { return root_; }
  std::filesystem::path watch() const { return root_ / "incoming"; }
  std::filesystem::path spool() const { return root_ / "spool"; }
  std::filesystem::path config_file() const { return root_ / "lastcut.toml"; }
  std::filesystem::path daemon_log() const { return root_ / "lastcutd.log"; }

  void start_cutters();
  void stop_cutters();  // SIGTERM: the simulators write their final records
  void start_daemon();
  // SIGTERM and wait; returns the exit status.
  int stop_daemon(double timeout_s = 60);
  void kill_daemon();  // SIGKILL
  Process* daemon() { return daemon_.get(); }

  // What cutter `name` received (the simulator's record), after stop_cutters().
  std::string received(const std::string& cutter) const;
  // The firmware's block log of a grbl cutter run as the real firmware: one line per planner block.
  std::vector<std::string> firmware_blocks(const std::string& cutter) const;
  bool is_firmware(const std::string& cutter) const { return is_grbl(cutter) && !options_.grbl_firmware.empty(); }
  // The cutter's port, relative to the configuration's folder.
  std::string port_of(const std::string& cutter) const {
    return is_firmware(cutter) ? "firmware-" + cutter + "/tty" : cutter + ".tty";
  }
  bool is_grbl(const std::string& cutter) const { return options_.grbl_cutters.count(cutter) > 0; }
  // The cut file a job of `cutter` keeps in its spool folder: cut.nc (grbl) or cut.plt (HPGL).
  std::string cut_file_name(const std::string& cutter) const { return is_grbl(cutter) ? "cut.nc" : "cut.plt"; }
  // Jobs per spool folder: id -> state.json.
  std::map<std::string, nlohmann::json> jobs(const std::string& folder) const;
  // The job whose input (scan or pattern set) had this name, in any spool folder; an empty id when none.
  struct FoundJob {
    std::string id, folder;  // folder: done, failed, held or work
    nlohmann::json state;
  };
  FoundJob find_job(const std::string& input) const;
  // True when the watch folder and work/ are empty and `expected` jobs have finished.
  bool settled(int expected) const;

 private:
  std::filesystem::path root_;
  RigOptions options_;
  std::map<std::string, std::unique_ptr<Process>> cutters_;
  std::unique_ptr<Process> daemon_;
};

// A small generated last (about 3000 triangles), made once per build tree and reused.
std::filesystem::path small_last(int eu_size, const std::string& side, int seed);
// A copy of a binary STL with different bytes (its 80-byte header changed): a new scan for the
// hash, the same geometry.
void write_variant(const std::filesystem::path& stl, const std::filesystem::path& out, const std::string& tag);

}  // namespace lastcut::daemon::testing
