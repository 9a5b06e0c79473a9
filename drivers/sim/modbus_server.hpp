#pragma once
// Serving ModbusPlc over Modbus TCP (127.0.0.1) or RTU (on a pty with a symlink), with libmodbus.
// Link faults counted in program blocks: drop-at-line=N closes the connection when block N
// arrives, stall-at-line=N stops answering, garbage-at-line=N answers with noise.
#include <atomic>
#include <string>

#include "drivers/sim/modbus_plc.hpp"

namespace lastcut::drivers::sim {

using ModbusReadyCallback = void (*)(const std::string& where);

int run_modbus_tcp(const ModbusSimOptions& options, int port, const std::atomic<bool>& stop, ModbusReadyCallback ready,
                   std::string& error);
int run_modbus_rtu(const ModbusSimOptions& options, const std::string& link_path, int baud, const std::atomic<bool>& stop,
                   ModbusReadyCallback ready, std::string& error);

}  // namespace lastcut::drivers::sim
