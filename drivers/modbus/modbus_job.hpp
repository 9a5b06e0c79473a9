#pragma once
// A cut job through a PLC's Modbus register map (handshake in config/modbus-register-map.toml):
// ready check, job identity, block transfer with block number / length / acknowledge, start,
// progress, completion and error codes. Before `start` nothing has been cut, so failures then
// are Failed (safe to retry); after it they are Interrupted and nothing is resent.
#include <atomic>
#include <string>

#include "drivers/cutter.hpp"
#include "drivers/modbus/register_map.hpp"

namespace lastcut::drivers::modbus {

// The map named by config.modbus_map, or the built-in default.
bool register_map_for(const CutterConfig& config, RegisterMap& map, std::string& error);

SendResult run_modbus_job(const CutterConfig& config, const std::string& program, const ProgressCallback& progress,
                          const std::atomic<bool>& cancel);

ProbeResult probe_modbus(const CutterConfig& config);

}  // namespace lastcut::drivers::modbus
