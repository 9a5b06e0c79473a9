#include "daemon_rig.hpp"

#include <csignal>
#include <cstdint>
#include <fstream>
#include <sstream>

#include <gtest/gtest.h>

namespace lastcut::daemon::testing {

DaemonRig::DaemonRig(const std::string& name, RigOptions options)
    : root_(scratch_folder(name)), options_(std::move(options)) {
  std::filesystem::create_directories(watch());
  std::string toml = "[paths]\nwatch = \"incoming\"\nspool = \"spool\"\nmachines = \"" +
                     (std::filesystem::path(LASTCUT_SOURCE_DIR) / "config/machines").string() + "\"\n" + options_.extra_paths +
                     "[watch]\nmode = \"inotify\"\nrescan_interval_s = 5\nstable_checks = 2\n"
                     "stable_interval_s = 0.1\nincomplete_grace_s = 0.5\n"
                     "[jobs]\nduplicate_policy = \"" + options_.duplicate_policy + "\"\n"
                     "default_material = \"calf\"\ndefault_cutter = \"" + options_.cutters.front() + "\"\n"
                     "stop_grace_s = 20\n"
                     "[batch]\nwindow_s = " + std::to_string(options_.batch_window_s) +
                     "\nmax_pieces = " + std::to_string(options_.batch_max_pieces) + "\nnest_time_s = 0.3\n"
                     "[materials.calf]\nwidth_mm = 800\nlength_mm = 1200\nspacing_mm = 3\n";
  for (const std::string& cutter : options_.cutters) {
    // Both simulators record the exact bytes they were sent, so a cut file can be found in them.
    if (is_grbl(cutter)) {
      toml += "[cutters." + cutter + "]\nprotocol = \"grbl\"\nport = \"" + port_of(cutter) + "\"\n"
              "timeout_s = 5\nmachine = \"grbl-drag-knife\"\nretry_interval_s = 0.5\n";
    } else {
      toml += "[cutters." + cutter + "]\nprotocol = \"hpgl\"\nport = \"" + cutter + ".tty\"\nflow = \"xonxoff\"\n"
              "timeout_s = 5\nmachine = \"hpgl-pen-plotter\"\nretry_interval_s = 0.5\n";
    }
  }
  toml += options_.extra_config;
  write_text(config_file(), toml);
}

DaemonRig::~DaemonRig() {
  if (daemon_ && daemon_->running()) stop_daemon(30);
  stop_cutters();
}

void DaemonRig::start_cutters() {
  for (const std::string& cutter : options_.cutters) {
    if (is_firmware(cutter)) {
      const auto log = root_ / ("firmware-" + cutter + ".log");
      cutters_[cutter] = std::make_unique<Process>(
          std::vector<std::string>{"/bin/bash", (std::filesystem::path(LASTCUT_SOURCE_DIR) / "tests/peers/run_grbl_firmware.sh").string(),
                                   options_.grbl_firmware, (root_ / ("firmware-" + cutter)).string()},
          log);
      ASSERT_TRUE(wait_until([&] { return read_text(log).find("ready:") != std::string::npos; }, 20))
          << "the grbl firmware for " << cutter << " did not start: " << read_text(log);
      continue;
    }
    const auto fault = options_.sim_faults.find(cutter);
    std::string error;
    cutters_[cutter] = start_simulator(is_grbl(cutter) ? "grbl" : "hpgl", root_ / (cutter + ".tty"),
                                       root_ / ("record-" + cutter),
                                       fault != options_.sim_faults.end() ? fault->second : "",
                                       root_ / ("sim-" + cutter + ".log"), error);
    ASSERT_TRUE(cutters_[cutter]) << error;
  }
}

void DaemonRig::stop_cutters() {
  for (auto& [name, process] : cutters_) {
    if (process && process->running()) {
      process->signal(SIGTERM);
      process->wait(10);
    }
  }
}

void DaemonRig::start_daemon() {
  daemon_ = std::make_unique<Process>(
      std::vector<std::string>{binary("lastcutd").string(), "--config", config_file().string()}, daemon_log());
  ASSERT_TRUE(wait_until([&] { return read_text(daemon_log()).find("lastcutd ready") != std::string::npos; }, 20))
      << read_text(daemon_log());
}

int DaemonRig::stop_daemon(double timeout_s) {
  daemon_->signal(SIGTERM);
  return daemon_->wait(timeout_s);
}

void DaemonRig::kill_daemon() {
  daemon_->signal(SIGKILL);
  daemon_->wait(10);
}

std::string DaemonRig::received(const std::string& cutter) const {
  return simulator_received(is_grbl(cutter) ? "grbl" : "hpgl", root_ / ("record-" + cutter));
}

std::vector<std::string> DaemonRig::firmware_blocks(const std::string& cutter) const {
  std::vector<std::string> lines;
  std::istringstream log(read_text(root_ / ("firmware-" + cutter) / "blocks.txt"));
  for (std::string line; std::getline(log, line);) lines.push_back(line);
  return lines;
}

std::map<std::string, nlohmann::json> DaemonRig::jobs(const std::string& folder) const {
  std::map<std::string, nlohmann::json> result;
  std::error_code error;
  for (std::filesystem::directory_iterator it(spool() / folder, error), end; !error && it != end; it.increment(error)) {
    if (it->path().filename().string()[0] == '.') continue;
    // A folder being claimed has no state.json for a moment (readers skip it, like the daemon).
    auto state = nlohmann::json::parse(read_text(it->path() / "state.json"), nullptr, false);
    if (!state.is_discarded()) result[it->path().filename().string()] = state;
  }
  return result;
}

DaemonRig::FoundJob DaemonRig::find_job(const std::string& input) const {
  for (const char* folder : {"done", "failed", "held", "work"})
    for (const auto& [id, state] : jobs(folder))
      if (state.value("scan", "") == input) return {id, folder, state};
  return {};
}

bool DaemonRig::settled(int expected) const {
  return count_entries(watch()) == 0 && count_entries(spool() / "work") == 0 &&
         count_entries(spool() / "done") + count_entries(spool() / "failed") + count_entries(spool() / "held") ==
             expected;
}

std::filesystem::path small_last(int eu_size, const std::string& side, int seed) {
  const auto folder = std::filesystem::path(LASTCUT_BINARY_DIR) / "test-scratch" / "daemon-lasts";
  std::filesystem::create_directories(folder);
  const auto file = folder / ("last-" + std::to_string(eu_size) + side + std::to_string(seed) + ".stl");
  if (!std::filesystem::exists(file)) {
    const auto partial = folder / (".partial-" + file.filename().string());
    const int status = run_command({binary("lastcut").string(), "generate", "-o", partial.string(), "--size",
                                    std::to_string(eu_size), "--side", side, "--triangles", "3000", "--seed",
                                    std::to_string(seed)},
                                   folder / "generate.log");
    EXPECT_EQ(status, 0) << read_text(folder / "generate.log");
    std::filesystem::rename(partial, file);
  }
  return file;
}

void write_variant(const std::filesystem::path& stl, const std::filesystem::path& out, const std::string& tag) {
  std::string bytes = read_text(stl);
  std::string header = "lastcut test variant " + tag;
  header.resize(80, ' ');
  const bool binary_stl = bytes.size() >= 84 &&
                          bytes.size() == 84 + 50 * static_cast<std::size_t>(
                                                    static_cast<unsigned char>(bytes[80]) |
                                                    (static_cast<unsigned char>(bytes[81]) << 8) |
                                                    (static_cast<unsigned char>(bytes[82]) << 16) |
                                                    (static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[83])) << 24));
  if (binary_stl) bytes.replace(0, 80, header);
  else bytes += "\n";  // ASCII: a trailing newline changes the hash, not the geometry
  write_text(out, bytes);
}

}  // namespace lastcut::daemon::testing
