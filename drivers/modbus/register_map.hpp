#pragma once
// RegisterMap: where a PLC-driven cutter keeps its handshake in Modbus holding registers.
// lastcut and the PLC program must agree on it; config/modbus-register-map.toml documents the
// default map and is what an integrator copies and edits. Addresses are 0-based PDU addresses
// (register 40001 in Modicon numbering is address 0).
#include <string>

namespace lastcut::drivers::modbus {

struct StatusCodes {
  int not_ready = 0, ready = 1, receiving = 2, loaded = 3, running = 4, done = 5, error = 6;
};
struct CommandCodes {
  int begin = 1, start = 2, abort = 3, clear_error = 4;
};

struct RegisterMap {
  // read by lastcut
  int status = 0;             // one of StatusCodes
  int error_code = 1;         // 0 = none; PLC-specific otherwise
  int progress_permille = 2;  // 0..1000 while running
  int block_ack = 3;          // number of the last block the PLC accepted
  // written by lastcut
  int command = 10;           // one of CommandCodes; the PLC clears it to 0 when taken
  int job_id = 11;            // job_id_words registers, two ASCII characters per register, high byte first
  int job_id_words = 8;
  int program_bytes = 19;     // two registers, high word first: total program length
  int block_number = 21;      // 1, 2, 3, ...: written together with block_length, AFTER the window
  int block_length = 22;      // bytes of the block in the window
  int window = 100;           // window_words registers of block data, two bytes per register, high byte first
  int window_words = 120;     // at most 123 (one Write Multiple Registers request)
  StatusCodes status_codes;
  CommandCodes command_codes;
  double poll_s = 0.1;        // period of status polls
  // The highest register address used, +1: the size a PLC (or the simulator) must provide.
  int register_count() const;
};

// Reads a map from TOML (see config/modbus-register-map.toml). Keys left out keep their defaults.
bool load_register_map(const std::string& path, RegisterMap& map, std::string& error);
// Checks the map for overlapping or out-of-range fields.
bool validate_register_map(const RegisterMap& map, std::string& error);

}  // namespace lastcut::drivers::modbus
