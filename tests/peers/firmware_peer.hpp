#pragma once
// The real grbl 1.1h firmware (tests/peers/run_grbl_firmware.sh) as a test peer on a pty, and the
// jobs the firmware tests send it.
#include <atomic>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/cutter.hpp"
#include "tests/drivers/sim_process.hpp"

namespace lastcut::drivers::testing {

// The firmware on a pty in a fresh folder (its EEPROM.DAT starts empty: grbl's defaults).
struct Firmware {
  TempDir dir;
  std::unique_ptr<SimProcess> process;
  CutterConfig config;

  Firmware() {
    process = std::make_unique<SimProcess>("bash", std::vector<std::string>{GRBL_FIRMWARE_RUNNER, GRBL_FIRMWARE_EXE,
                                                                            dir / "firmware"});
    config.name = "firmware";
    config.protocol = "grbl";
    config.port = dir / "firmware/tty";
    // The simulator is CPU-bound and slows down under load: generous silences, fast axes.
    config.timeout_s = 30;
    config.grbl_settings = {"$110=60000", "$111=60000", "$112=60000", "$120=500000", "$121=500000", "$122=500000"};
  }
  // Lines of the firmware's block log: one per block its planner committed.
  std::vector<std::string> blocks() const {
    std::ifstream in(dir / "firmware/blocks.txt");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
  }
  SendResult send(const std::string& program, const std::atomic<bool>* cancel = nullptr) {
    const std::atomic<bool> never{false};
    return send_job(config, program, nullptr, cancel ? *cancel : never);
  }
};

// N short straight moves, a zigzag (every one a real move, so every one is one planner block;
// short, so the CPU-bound simulator runs the job in seconds), then home.
inline std::string moves(int count) {
  std::ostringstream program;
  program << "G21\nG90\nG1 F60000\n";
  for (int i = 0; i < count; ++i) {
    program << "G1 X" << 10 + (i % 2) * 1.5 + (i % 7) * 0.1 << " Y" << 10 + i * 0.05 << "\n";
  }
  program << "G0 X0 Y0\nM2\n";
  return program.str();
}

// The last lines of what the device said and what we did, for a failure message.
inline std::string tail_of(const std::vector<std::string>& log) {
  std::string text;
  for (std::size_t i = log.size() > 25 ? log.size() - 25 : 0; i < log.size(); ++i) text += "\n  " + log[i];
  return text;
}

inline int motion_lines(const std::string& program) {
  std::istringstream in(program);
  int count = 0;
  for (std::string line; std::getline(in, line);) count += line.rfind("G1 X", 0) == 0 || line.rfind("G0 X", 0) == 0;
  return count;
}

}  // namespace lastcut::drivers::testing
