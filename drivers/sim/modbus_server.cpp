// Modbus TCP / RTU server loops for the simulated PLC (libmodbus does the framing).
#include "drivers/sim/modbus_server.hpp"

#include <chrono>
#include <modbus/modbus.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>
#include <vector>

#include "drivers/sim/sim_link.hpp"

namespace lastcut::drivers::sim {

namespace {

double steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

struct Served {
  drivers::modbus::RegisterMap map;
  modbus_mapping_t* mapping = nullptr;
  ~Served() {
    if (mapping) modbus_mapping_free(mapping);
  }
};

bool prepare(const ModbusSimOptions& options, Served& served, std::string& error) {
  if (!options.map_path.empty()) {
    if (!drivers::modbus::load_register_map(options.map_path, served.map, error)) return false;
  }
  served.mapping = modbus_mapping_new(0, 0, served.map.register_count(), 0);
  if (!served.mapping) {
    error = "cannot allocate registers";
    return false;
  }
  return true;
}

enum class LinkFault { None, Drop, Stall, Garbage };

LinkFault fault_now(const Faults& f, size_t blocks) {
  if (f.drop_at_line != 0 && blocks >= f.drop_at_line) return LinkFault::Drop;
  if (f.stall_at_line != 0 && blocks >= f.stall_at_line) return LinkFault::Stall;
  if (f.garbage_at_line != 0 && blocks >= f.garbage_at_line) return LinkFault::Garbage;
  return LinkFault::None;
}

// Answers one request waiting on `fd`. Returns false when the connection should be closed.
bool serve_one(modbus_t* ctx, int fd, Served& served, ModbusPlc& plc, const ModbusSimOptions& options) {
  uint8_t query[MODBUS_TCP_MAX_ADU_LENGTH];
  modbus_set_socket(ctx, fd);
  const int length = modbus_receive(ctx, query);
  if (length == 0) return true;   // a request for another unit id on the RTU line
  if (length < 0) return false;
  const LinkFault fault = fault_now(options.faults, plc.blocks_received());
  if (fault == LinkFault::Stall) return true;
  if (fault == LinkFault::Garbage) {
    static const uint8_t noise[] = {0xde, 0xad, 0xbe, 0xef, 0x00, 0x13};
    return ::write(fd, noise, sizeof noise) >= 0;
  }
  modbus_reply(ctx, query, length, served.mapping);
  plc.update(steady_now_s());
  return fault_now(options.faults, plc.blocks_received()) != LinkFault::Drop;
}

}  // namespace

int run_modbus_tcp(const ModbusSimOptions& options, int port, const std::atomic<bool>& stop, ModbusReadyCallback ready,
                   std::string& error) {
  Served served;
  if (!prepare(options, served, error)) return 1;
  ModbusPlc plc(served.map, options, served.mapping->tab_registers);
  const int listener = listen_loopback(port, error);
  if (listener < 0) return 1;
  modbus_t* ctx = modbus_new_tcp("127.0.0.1", port);
  ready("127.0.0.1:" + std::to_string(port) + " (Modbus TCP, unit " + std::to_string(options.unit_id) + ")");
  std::vector<int> clients;
  bool dropped = false;
  while (!stop.load()) {
    std::vector<pollfd> fds;
    if (!dropped) fds.push_back({listener, POLLIN, 0});
    for (int c : clients) fds.push_back({c, POLLIN, 0});
    const int ready_count = ::poll(fds.data(), fds.size(), 20);
    plc.update(steady_now_s());
    if (ready_count <= 0) continue;
    for (const auto& p : fds) {
      if (!(p.revents & (POLLIN | POLLHUP | POLLERR))) continue;
      if (p.fd == listener) {
        const int client = ::accept(listener, nullptr, nullptr);
        if (client >= 0) clients.push_back(client);
        continue;
      }
      if (!serve_one(ctx, p.fd, served, plc, options)) {
        ::close(p.fd);
        std::erase(clients, p.fd);
        if (fault_now(options.faults, plc.blocks_received()) == LinkFault::Drop && !dropped) {
          dropped = true;  // the PLC's network is gone: refuse reconnections too
          for (int c : clients) ::close(c);
          clients.clear();
        }
      }
    }
  }
  for (int c : clients) ::close(c);
  ::close(listener);
  modbus_free(ctx);
  if (!options.record_dir.empty()) plc.write_record(options.record_dir);
  return 0;
}

int run_modbus_rtu(const ModbusSimOptions& options, const std::string& link_path, int baud, const std::atomic<bool>& stop,
                   ModbusReadyCallback ready, std::string& error) {
  Served served;
  if (!prepare(options, served, error)) return 1;
  ModbusPlc plc(served.map, options, served.mapping->tab_registers);
  PtyLink pty;
  if (!open_pty_link(link_path, pty, error)) return 1;
  // The RTU context never opens a device: it serves the pty master handed to it.
  modbus_t* ctx = modbus_new_rtu(pty.slave_name.c_str(), baud, 'N', 8, 1);
  modbus_set_slave(ctx, options.unit_id);
  ready(link_path + " -> " + pty.slave_name + " (Modbus RTU " + std::to_string(baud) + " 8N1, unit " +
        std::to_string(options.unit_id) + ")");
  bool dropped = false;
  while (!stop.load()) {
    pollfd p{pty.master, POLLIN, 0};
    const int ready_count = dropped ? (::usleep(20000), 0) : ::poll(&p, 1, 20);
    plc.update(steady_now_s());
    if (ready_count <= 0 || !(p.revents & POLLIN)) continue;
    if (!serve_one(ctx, pty.master, served, plc, options)) {
      if (fault_now(options.faults, plc.blocks_received()) == LinkFault::Drop) {
        dropped = true;
        close_pty_link(pty);
      } else {
        modbus_flush(ctx);  // a broken frame: wait for the next one
      }
    }
  }
  modbus_free(ctx);
  close_pty_link(pty);
  if (!options.record_dir.empty()) plc.write_record(options.record_dir);
  return 0;
}

}  // namespace lastcut::drivers::sim
