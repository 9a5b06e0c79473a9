#pragma once
// ModbusClient: holding-register reads and writes over Modbus TCP or RTU through libmodbus,
// with every failure turned into one line that says what to check (exception codes by name).
#include <cstdint>
#include <string>
#include <vector>

typedef struct _modbus modbus_t;

namespace lastcut::drivers::modbus {

struct ModbusEndpoint {
  bool rtu = false;
  std::string host;        // TCP
  int port = 502;          // TCP
  std::string device;      // RTU: /dev/ttyUSB1 or a pty
  int baud = 19200;        // RTU
  char parity = 'N';       // RTU: 'N' | 'E' | 'O'
  int data_bits = 8, stop_bits = 1;
};

// "tcp://127.0.0.1:1502" or "rtu:/dev/ttyUSB1[,19200[,8N1]]".
bool parse_modbus_endpoint(const std::string& text, ModbusEndpoint& endpoint, std::string& error);

// "illegal data address (exception 2): the register map does not match the PLC", "timed out", ...
std::string explain_modbus_error(int error_number);

class ModbusClient {
 public:
  ModbusClient(ModbusEndpoint endpoint, int unit_id, double response_timeout_s);
  ~ModbusClient();
  ModbusClient(const ModbusClient&) = delete;
  ModbusClient& operator=(const ModbusClient&) = delete;

  bool connect(std::string& error);
  void close();
  // Reads `count` holding registers from `address` (function 3).
  bool read(int address, int count, std::vector<uint16_t>& values, std::string& error);
  // Writes holding registers (function 6 for one value, 16 for more).
  bool write(int address, const std::vector<uint16_t>& values, std::string& error);
  // True when the last failure was the link (timeout, reset, CRC), false for a Modbus exception.
  bool last_error_was_link() const { return last_error_was_link_; }
  std::string describe() const;

 private:
  bool fail(const char* what, int address, std::string& error);
  ModbusEndpoint endpoint_;
  int unit_id_;
  double response_timeout_s_;
  modbus_t* ctx_ = nullptr;
  bool last_error_was_link_ = false;
};

}  // namespace lastcut::drivers::modbus
