// ModbusPlc: simulated PLC behind lastcut's register map (see modbus_plc.hpp).
#include "drivers/sim/modbus_plc.hpp"

#include <fstream>

namespace lastcut::drivers::sim {

namespace {
// Error codes this simulated PLC reports in the error_code register.
constexpr int kBlockOutOfSequence = 101;
constexpr int kBlockTooLong = 102;
constexpr int kProgramLengthMismatch = 103;
constexpr int kUnknownCommand = 104;
}  // namespace

ModbusPlc::ModbusPlc(const drivers::modbus::RegisterMap& map, const ModbusSimOptions& options, uint16_t* registers)
    : map_(map), options_(options), registers_(registers) {
  reg(map_.status) = static_cast<uint16_t>(map_.status_codes.ready);
}

void ModbusPlc::fail(int code) {
  reg(map_.status) = static_cast<uint16_t>(map_.status_codes.error);
  reg(map_.error_code) = static_cast<uint16_t>(code);
  running_ = false;
}

void ModbusPlc::update(double now_s) {
  const auto& codes = map_.status_codes;
  const int command = reg(map_.command);
  if (command != 0) {
    reg(map_.command) = 0;
    const auto& c = map_.command_codes;
    if (command == c.abort) {
      running_ = false;
      reg(map_.status) = static_cast<uint16_t>(codes.ready);
    } else if (command == c.clear_error) {
      reg(map_.error_code) = 0;
      reg(map_.status) = static_cast<uint16_t>(codes.ready);
    } else if (command == c.begin && reg(map_.status) == codes.ready) {
      program_.clear();
      job_id_.clear();
      for (int i = 0; i < map_.job_id_words * 2; ++i) {
        const char ch = static_cast<char>(i % 2 == 0 ? reg(map_.job_id + i / 2) >> 8 : reg(map_.job_id + i / 2) & 0xff);
        if (ch != 0) job_id_ += ch;
      }
      expected_bytes_ = (static_cast<uint32_t>(reg(map_.program_bytes)) << 16) | reg(map_.program_bytes + 1);
      last_block_number_ = 0;
      reg(map_.block_number) = 0;
      reg(map_.block_ack) = 0;
      reg(map_.progress_permille) = 0;
      reg(map_.status) = static_cast<uint16_t>(codes.receiving);
    } else if (command == c.start && reg(map_.status) == codes.loaded) {
      running_ = true;
      run_start_s_ = now_s;
      reg(map_.status) = static_cast<uint16_t>(codes.running);
    } else if (command != c.begin && command != c.start) {
      fail(kUnknownCommand);
    }
  }
  const uint16_t number = reg(map_.block_number);
  if (reg(map_.status) == codes.receiving && number != 0 && number != last_block_number_) {
    last_block_number_ = number;
    const int length = reg(map_.block_length);
    ++blocks_;
    if (options_.faults.error_at_line == blocks_) {
      fail(options_.faults.error_code);
    } else if (number != static_cast<uint16_t>(reg(map_.block_ack) + 1)) {
      fail(kBlockOutOfSequence);
    } else if (length <= 0 || length > map_.window_words * 2) {
      fail(kBlockTooLong);
    } else {
      for (int i = 0; i < length; ++i) {
        const uint16_t word = reg(map_.window + i / 2);
        program_ += static_cast<char>(i % 2 == 0 ? word >> 8 : word & 0xff);
      }
      reg(map_.block_ack) = number;
      if (program_.size() == expected_bytes_) reg(map_.status) = static_cast<uint16_t>(codes.loaded);
      if (program_.size() > expected_bytes_) fail(kProgramLengthMismatch);
    }
  }
  if (running_) {
    const double fraction = options_.cut_s <= 0 ? 1.0 : (now_s - run_start_s_) / options_.cut_s;
    if (options_.faults.alarm_at_line != 0 && fraction >= 0.5) {
      reg(map_.progress_permille) = 500;
      fail(options_.faults.alarm_code);
    } else if (fraction >= 1.0) {
      running_ = false;
      ++jobs_done_;
      reg(map_.progress_permille) = 1000;
      reg(map_.status) = static_cast<uint16_t>(codes.done);
      if (!options_.record_dir.empty()) write_record(options_.record_dir);
    } else {
      reg(map_.progress_permille) = static_cast<uint16_t>(fraction * 1000);
    }
  }
  // A finished job: ready again once lastcut has seen `done` (give it a few polls).
  if (reg(map_.status) == codes.done && !running_ && now_s - run_start_s_ > options_.cut_s + 2.0) {
    reg(map_.status) = static_cast<uint16_t>(codes.ready);
  }
}

void ModbusPlc::write_record(const std::filesystem::path& dir) const {
  std::ofstream(dir / "modbus-received.bin", std::ios::binary) << program_;
  std::ofstream(dir / "modbus-stats.json") << "{\"job_id\": \"" << job_id_ << "\", \"program_bytes\": " << program_.size()
                                           << ", \"blocks\": " << blocks_ << ", \"jobs_done\": " << jobs_done_
                                           << ", \"status\": " << registers_[map_.status]
                                           << ", \"error_code\": " << registers_[map_.error_code] << "}\n";
}

}  // namespace lastcut::drivers::sim
