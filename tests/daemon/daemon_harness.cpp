#include "daemon_harness.hpp"

#include <fstream>
#include <sstream>
#include <thread>

namespace lastcut::daemon::testing {

std::filesystem::path binary(const std::string& name) {
  return std::filesystem::path(LASTCUT_BINARY_DIR) / "bin" / name;
}

bool wait_until(const std::function<bool()>& done, double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < deadline) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return done();
}

int run_command(const std::vector<std::string>& argv, const std::filesystem::path& log_file) {
  return lastcut::test::run_to_exit(argv, log_file, 300);
}

std::string read_text(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

void write_text(const std::filesystem::path& file, const std::string& text) {
  std::ofstream(file, std::ios::binary) << text;
}

int count_entries(const std::filesystem::path& folder) {
  int count = 0;
  std::error_code error;
  for (std::filesystem::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    if (it->path().filename().string()[0] != '.') ++count;
  }
  return count;
}

int count_occurrences(const std::string& haystack, const std::string& needle) {
  int count = 0;
  for (std::size_t at = haystack.find(needle); at != std::string::npos; at = haystack.find(needle, at + 1)) ++count;
  return count;
}

std::filesystem::path scratch_folder(const std::string& name) {
  const auto folder = std::filesystem::path(LASTCUT_BINARY_DIR) / "test-scratch" / "daemon" / name;
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  return folder;
}

void drop(const std::filesystem::path& file, const std::filesystem::path& watch_dir, const std::string& name) {
  const auto staging = watch_dir / ("." + name + ".part");
  std::filesystem::copy_file(file, staging, std::filesystem::copy_options::overwrite_existing);
  std::filesystem::rename(staging, watch_dir / name);
}

std::unique_ptr<Process> start_simulator(const std::string& protocol, const std::filesystem::path& link,
                                         const std::filesystem::path& record, const std::string& fault,
                                         const std::filesystem::path& log, std::string& error) {
  std::vector<std::string> argv = {binary("lastcut-sim").string(), protocol, "--link", link.string(),
                                   "--record", record.string(), "--time-scale", "0"};
  if (!fault.empty()) {
    argv.push_back("--fault");
    argv.push_back(fault);
  }
  auto process = std::make_unique<Process>(argv, log);
  if (!wait_until([&] { return read_text(log).find("ready:") != std::string::npos; }, 20)) {
    error = "simulator " + link.string() + " did not start: " + read_text(log);
    return nullptr;
  }
  return process;
}

std::string simulator_received(const std::string& protocol, const std::filesystem::path& record) {
  return read_text(record / (protocol == "grbl" ? "grbl-received.nc" : "hpgl-received.hpgl"));
}

}  // namespace lastcut::daemon::testing
