#pragma once
// ModbusPlc: the PLC side of lastcut's Modbus register map (config/modbus-register-map.toml),
// as a state machine over a holding-register array: takes commands, checks and acknowledges
// program blocks, "cuts" for a simulated time while updating progress, reports done or error.
// Faults (per block number): error-at-line=N[:CODE] rejects block N, alarm-at-line=N[:CODE]
// raises an error while cutting, drop/stall/garbage are applied by the server loop.
#include <cstdint>
#include <filesystem>
#include <string>

#include "drivers/modbus/register_map.hpp"
#include "drivers/sim/byte_device.hpp"

namespace lastcut::drivers::sim {

struct ModbusSimOptions {
  std::string map_path;           // empty: the built-in default map
  int unit_id = 1;
  double cut_s = 0.5;             // simulated cutting time of one job
  std::string record_dir;
  Faults faults;
};

class ModbusPlc {
 public:
  ModbusPlc(const drivers::modbus::RegisterMap& map, const ModbusSimOptions& options, uint16_t* registers);
  // Call after every request the server answered, and periodically: reacts to what was written.
  void update(double now_s);
  size_t blocks_received() const { return blocks_; }
  void write_record(const std::filesystem::path& dir) const;

 private:
  void fail(int code);
  uint16_t& reg(int address) { return registers_[address]; }
  const drivers::modbus::RegisterMap& map_;
  const ModbusSimOptions& options_;
  uint16_t* registers_;
  std::string program_;
  std::string job_id_;
  uint32_t expected_bytes_ = 0;
  size_t blocks_ = 0, jobs_done_ = 0;
  uint16_t last_block_number_ = 0;
  double run_start_s_ = 0;
  bool running_ = false;
};

}  // namespace lastcut::drivers::sim
