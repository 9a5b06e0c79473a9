// Throughput of the grbl sender as a share of the serial wire's capacity: a 10,000-line G-code
// job streamed to the real `lastcut-sim grbl` over a pseudo-terminal whose wire the simulator
// models at 115200 baud (10 bits per byte), with zero motion time, so the only limits are the
// wire and the protocol. Character counting vs send-and-wait, measured in the same run.
// Usage: bench_drivers_grbl_throughput [LINES] [BAUD]
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "drivers/cutter.hpp"
#include "drivers/grbl/grbl_job.hpp"
#include "tests/support/child_process.hpp"

namespace {

std::string make_job(int lines) {
  std::string program = "G21\nG90\nG1 F3000\n";
  for (int i = 3; i < lines - 1; ++i) {
    program += "G1 X" + std::to_string(i % 397) + "." + std::to_string(i % 1000) + " Y" + std::to_string((i * 7) % 283) + "." +
               std::to_string((i * 13) % 100) + "\n";
  }
  program += "M2\n";
  return program;
}

// The simulator on a new pty link; its output goes to LINK.log.
std::unique_ptr<lastcut::test::ChildProcess> start_sim(const std::string& link, int baud, int rx_buffer) {
  auto sim = std::make_unique<lastcut::test::ChildProcess>(
      std::vector<std::string>{std::string(LASTCUT_BINARY_DIR) + "/bin/lastcut-sim", "grbl", "--link", link, "--baud",
                               std::to_string(baud), "--time-scale", "0", "--rx-buffer", std::to_string(rx_buffer)},
      link + ".log", /*end_with_parent=*/true);
  for (int i = 0; i < 500 && !std::filesystem::exists(link); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  return sim;
}

}  // namespace

int main(int argc, char** argv) {
  int lines = 10000;
  int baud = 115200;
  CLI::App app{"Throughput of the grbl sender as a share of the serial wire's capacity: a G-code job streamed to "
               "lastcut-sim grbl over a pseudo-terminal, character counting vs send-and-wait"};
  app.add_option("LINES", lines, "lines of G-code in the job")
      ->capture_default_str()
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  app.add_option("BAUD", baud, "serial wire speed the simulator models (baud, 10 bits per byte)")
      ->capture_default_str()
      ->check(CLI::Range(1, std::numeric_limits<int>::max()));
  CLI11_PARSE(app, argc, argv);
  const std::string program = make_job(lines);
  size_t wire_bytes = 0;
  for (const auto& line : lastcut::drivers::grbl::program_lines(program)) wire_bytes += line.size() + 1;
  const double wire_s = static_cast<double>(wire_bytes) * 10.0 / baud;
  const std::string dir = std::filesystem::temp_directory_path() / ("lastcut-bench-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);

  std::printf("grbl streaming: %d lines, %zu bytes, %d baud (wire time %.2f s), zero motion time\n", lines, wire_bytes, baud, wire_s);
  std::printf("%-22s %8s %10s %12s %10s\n", "mode", "rx bytes", "elapsed s", "% of wire", "lines/s");
  struct Mode { const char* name; const char* streaming; int rx; };
  const Mode modes[] = {{"character counting", "counting", 128}, {"send-and-wait", "send-wait", 128},
                        {"counting (grblHAL)", "counting", 1024}};
  bool all_done = true;
  double counting_percent = 0;
  for (const Mode& mode : modes) {
    const std::string link = dir + "/grbl-" + mode.streaming + std::to_string(mode.rx);
    const auto sim = start_sim(link, baud, mode.rx);
    lastcut::drivers::CutterConfig config;
    config.protocol = "grbl";
    config.port = link;
    config.baud = baud;
    config.grbl_streaming = mode.streaming;
    const std::atomic<bool> never{false};
    const auto start = std::chrono::steady_clock::now();
    const auto result = lastcut::drivers::send_job(config, program, nullptr, never);
    const double elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sim->stop();
    if (result.outcome != lastcut::drivers::SendOutcome::Done) {
      std::printf("%-22s FAILED: %s\n", mode.name, result.reason.c_str());
      all_done = false;
      continue;
    }
    const double percent = 100.0 * wire_s / elapsed_s;
    if (mode.rx == 128 && std::string(mode.streaming) == "counting") counting_percent = percent;
    std::printf("%-22s %8d %10.2f %11.1f%% %10.0f\n", mode.name, mode.rx, elapsed_s, percent, lines / elapsed_s);
  }
  std::filesystem::remove_all(dir);
  std::printf("elapsed includes connect ($I, status) and the final wait for two Idle status reports (0.2 s poll)\n");
  std::printf("target: character counting >= 90%% of wire speed: %s\n", counting_percent >= 90 ? "met" : "NOT met");
  return all_done ? 0 : 1;
}
