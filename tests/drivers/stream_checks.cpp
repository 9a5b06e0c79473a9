#include "tests/drivers/stream_checks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <regex>

#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::testing {

SendResult SimulatedCutter::send(const std::string& program, const std::atomic<bool>* cancel) {
  static const std::atomic<bool> never{false};
  return send_job(config, program, nullptr, cancel ? *cancel : never);
}

std::pair<std::string, std::string> SimulatedCutter::record() {
  EXPECT_EQ(sim->stop(), 0) << "lastcut-sim must exit cleanly on SIGTERM";
  return {read_file(dir.path() / "rec" / received_file), read_file(dir.path() / "rec" / stats_file)};
}

std::string SimulatedCutter::deliver(const std::string& program) {
  const SendResult result = send(program);
  EXPECT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  auto [received, stats] = record();
  EXPECT_EQ(received, program);
  return stats;
}

int stat_value(const std::string& stats_json, const std::string& key) {
  std::smatch m;
  if (!std::regex_search(stats_json, m, std::regex("\"" + key + "\": ([0-9]+)"))) return -1;
  return std::stoi(m[1]);
}

void expect_delivered_over_loopback(const std::string& protocol, std::vector<std::string> sim_args, CutterConfig config,
                                    const std::string& program, const std::string& record_file) {
  TempDir dir;
  const int port = free_loopback_port();
  std::vector<std::string> args{protocol, "--port", std::to_string(port), "--record", dir / "rec"};
  args.insert(args.end(), sim_args.begin(), sim_args.end());
  SimProcess sim(args);
  ASSERT_TRUE(sim.ready()) << sim.ready_line();
  config.protocol = protocol;
  config.port = "tcp://127.0.0.1:" + std::to_string(port);
  const std::atomic<bool> never{false};
  const SendResult result = send_job(config, program, nullptr, never);
  EXPECT_EQ(result.outcome, SendOutcome::Done) << result.reason;
  EXPECT_EQ(sim.stop(), 0);
  EXPECT_EQ(read_file(dir.path() / "rec" / record_file), program);
}

TimedSend timed_send(const CutterConfig& config, const std::string& program) {
  const std::atomic<bool> never{false};
  const auto start = std::chrono::steady_clock::now();
  TimedSend timed{send_job(config, program, nullptr, never), 0.0};
  timed.elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return timed;
}

void expect_interrupted(const SendResult& result, std::initializer_list<const char*> phrases) {
  EXPECT_EQ(result.outcome, SendOutcome::Interrupted) << result.reason;
  for (const char* phrase : phrases) EXPECT_NE(result.reason.find(phrase), std::string::npos) << phrase << " not in: " << result.reason;
}

}  // namespace lastcut::drivers::testing
