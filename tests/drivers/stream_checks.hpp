#pragma once
// What the grbl and HP-GL streaming tests check alike: the simulator's statistics, delivery over
// loopback TCP, how long a send took, and an interruption with its reason.
#include <initializer_list>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "drivers/cutter.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::testing {

// One simulated cutter on a pseudo-terminal in a fresh folder, and the driver settings for it.
// The simulator records into dir/rec: `received_file` (the bytes) and `stats_file` (JSON).
struct SimulatedCutter {
  TempDir dir;
  std::unique_ptr<SimProcess> sim;
  CutterConfig config;
  std::string received_file, stats_file;

  SendResult send(const std::string& program, const std::atomic<bool>* cancel = nullptr);
  // Stops the simulator (so it writes its record) and returns {received program, stats json}.
  std::pair<std::string, std::string> record();
  // Sends `program`, expects Done and `program` byte-exact at the cutter; returns the stats JSON.
  std::string deliver(const std::string& program);
};

// The integer `"key": N` in a simulator's stats JSON; -1 when absent.
int stat_value(const std::string& stats_json, const std::string& key);

// Starts `lastcut-sim <protocol> --port P <sim_args> --record DIR` on 127.0.0.1, sends `program`
// with `config` pointed at it, and expects Done and `program` byte-exact in DIR/record_file.
void expect_delivered_over_loopback(const std::string& protocol, std::vector<std::string> sim_args, CutterConfig config,
                                    const std::string& program, const std::string& record_file);

struct TimedSend {
  SendResult result;
  double elapsed_s = 0.0;
};
TimedSend timed_send(const CutterConfig& config, const std::string& program);

// Expects the outcome Interrupted and each of `phrases` in the reason.
void expect_interrupted(const SendResult& result, std::initializer_list<const char*> phrases);

}  // namespace lastcut::drivers::testing
