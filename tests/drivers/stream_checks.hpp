#pragma once
// What the grbl and HP-GL streaming tests check alike: the simulator's statistics, delivery over
// loopback TCP, how long a send took, and an interruption with its reason.
#include <initializer_list>
#include <string>
#include <vector>

#include "drivers/cutter.hpp"

namespace lastcut::drivers::testing {

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
