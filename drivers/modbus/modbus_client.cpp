// ModbusClient over libmodbus (TCP with host names via modbus_new_tcp_pi, RTU on a tty).
#include "drivers/modbus/modbus_client.hpp"

#include <cerrno>
#include <cstring>
#include <modbus/modbus.h>

#include "drivers/transport/tcp_transport.hpp"

namespace lastcut::drivers::modbus {

bool parse_modbus_endpoint(const std::string& text, ModbusEndpoint& endpoint, std::string& error) {
  if (text.rfind("tcp://", 0) == 0) {
    endpoint.rtu = false;
    if (!split_host_port(text.substr(6), endpoint.host, endpoint.port)) {
      error = "bad Modbus TCP address '" + text + "' (want tcp://HOST:PORT)";
      return false;
    }
    return true;
  }
  if (text.rfind("rtu:", 0) == 0) {
    endpoint.rtu = true;
    std::string rest = text.substr(4);
    std::vector<std::string> parts;
    size_t start = 0;
    while (true) {
      const size_t comma = rest.find(',', start);
      parts.push_back(rest.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
      if (comma == std::string::npos) break;
      start = comma + 1;
    }
    endpoint.device = parts[0];
    if (endpoint.device.empty() || parts.size() > 3) {
      error = "bad Modbus RTU address '" + text + "' (want rtu:/dev/ttyUSB1[,19200[,8N1]])";
      return false;
    }
    if (parts.size() >= 2) {
      if (parts[1].empty() || parts[1].find_first_not_of("0123456789") != std::string::npos) {
        error = "bad baud rate in '" + text + "'";
        return false;
      }
      endpoint.baud = std::stoi(parts[1]);
    }
    if (parts.size() == 3) {
      const std::string& f = parts[2];
      if (f.size() != 3 || (f[0] != '7' && f[0] != '8') || (f[1] != 'N' && f[1] != 'E' && f[1] != 'O') || (f[2] != '1' && f[2] != '2')) {
        error = "bad framing '" + f + "' in '" + text + "' (want 8N1, 8E1, ...)";
        return false;
      }
      endpoint.data_bits = f[0] - '0';
      endpoint.parity = f[1];
      endpoint.stop_bits = f[2] - '0';
    }
    return true;
  }
  error = "bad Modbus address '" + text + "' (want tcp://HOST:PORT or rtu:DEVICE[,BAUD[,8N1]])";
  return false;
}

std::string explain_modbus_error(int error_number) {
  switch (error_number) {
    case EMBXILFUN: return "illegal function (exception 1): the PLC does not support holding-register access";
    case EMBXILADD: return "illegal data address (exception 2): the register map does not match the PLC program";
    case EMBXILVAL: return "illegal data value (exception 3): the PLC rejected the value written";
    case EMBXSFAIL: return "server device failure (exception 4): the PLC reported an internal fault";
    case EMBXACK: return "acknowledge (exception 5): the PLC is still processing a long request";
    case EMBXSBUSY: return "server busy (exception 6): the PLC is busy, try again";
    case EMBXNACK: return "negative acknowledge (exception 7): the PLC cannot perform the request";
    case EMBXMEMPAR: return "memory parity error (exception 8) in the PLC";
    case EMBXGPATH: return "gateway path unavailable (exception 10): check the gateway's configuration";
    case EMBXGTAR: return "gateway target failed to respond (exception 11): the PLC behind the gateway is off or unreachable";
    case EMBBADCRC: return "bad CRC in the reply: noise on the line or wrong baud rate";
    case EMBBADDATA: return "malformed reply data";
    case EMBBADEXC: return "invalid exception code in the reply";
    case EMBMDATA: return "too many registers requested";
    case EMBBADSLAVE: return "reply from the wrong unit id: check the unit id or line sharing";
    case ETIMEDOUT: return "no reply (timed out): PLC off, wrong address, unit id or baud rate";
    default: return std::strerror(error_number);
  }
}

ModbusClient::ModbusClient(ModbusEndpoint endpoint, int unit_id, double response_timeout_s)
    : endpoint_(std::move(endpoint)), unit_id_(unit_id), response_timeout_s_(response_timeout_s) {}

ModbusClient::~ModbusClient() { close(); }

std::string ModbusClient::describe() const {
  if (endpoint_.rtu) {
    return "modbus rtu:" + endpoint_.device + "," + std::to_string(endpoint_.baud) + " unit " + std::to_string(unit_id_);
  }
  return "modbus tcp://" + endpoint_.host + ":" + std::to_string(endpoint_.port) + " unit " + std::to_string(unit_id_);
}

bool ModbusClient::connect(std::string& error) {
  close();
  ctx_ = endpoint_.rtu ? modbus_new_rtu(endpoint_.device.c_str(), endpoint_.baud, endpoint_.parity, endpoint_.data_bits, endpoint_.stop_bits)
                       : modbus_new_tcp_pi(endpoint_.host.c_str(), std::to_string(endpoint_.port).c_str());
  if (ctx_ == nullptr) {
    error = describe() + ": " + std::strerror(errno);
    return false;
  }
  modbus_set_slave(ctx_, unit_id_);
  const auto seconds = static_cast<uint32_t>(response_timeout_s_);
  modbus_set_response_timeout(ctx_, seconds, static_cast<uint32_t>((response_timeout_s_ - seconds) * 1e6));
  if (modbus_connect(ctx_) != 0) {
    error = "cannot connect to " + describe() + ": " + explain_modbus_error(errno);
    last_error_was_link_ = true;
    modbus_free(ctx_);
    ctx_ = nullptr;
    return false;
  }
  return true;
}

void ModbusClient::close() {
  if (ctx_ == nullptr) return;
  modbus_close(ctx_);
  modbus_free(ctx_);
  ctx_ = nullptr;
}

bool ModbusClient::fail(const char* what, int address, std::string& error) {
  const int number = errno;
  last_error_was_link_ = number < MODBUS_ENOBASE || number > EMBXGTAR;
  error = std::string(what) + " register " + std::to_string(address) + " on " + describe() + ": " + explain_modbus_error(number);
  if (last_error_was_link_) modbus_flush(ctx_);
  return false;
}

bool ModbusClient::read(int address, int count, std::vector<uint16_t>& values, std::string& error) {
  if (ctx_ == nullptr && !connect(error)) return false;
  values.assign(static_cast<size_t>(count), 0);
  if (modbus_read_registers(ctx_, address, count, values.data()) != count) return fail("reading", address, error);
  return true;
}

bool ModbusClient::write(int address, const std::vector<uint16_t>& values, std::string& error) {
  if (ctx_ == nullptr && !connect(error)) return false;
  const int count = static_cast<int>(values.size());
  const int written = count == 1 ? modbus_write_register(ctx_, address, values[0])
                                 : modbus_write_registers(ctx_, address, count, values.data());
  if (written != count) return fail("writing", address, error);
  return true;
}

}  // namespace lastcut::drivers::modbus
