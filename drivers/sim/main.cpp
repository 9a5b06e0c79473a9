// lastcut-sim: simulated cutters for dry runs, tests and benchmarks.
//   lastcut-sim grbl --link /tmp/grbl [--baud 115200] [--time-scale 0] [--record DIR] [--fault error-at-line=3:22]
//   lastcut-sim hpgl --link /tmp/plotter [--handshake xonxoff|escb] [--buffer 1024] [--record DIR] [--svg cut.svg]
//   lastcut-sim modbus-tcp --port 1502 [--record DIR]      lastcut-sim modbus-rtu --link /tmp/plc [--baud 19200]
// Prints one "ready: ..." line on stdout when the link exists; exits 0 on SIGTERM or SIGINT.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <filesystem>

#include <CLI/CLI.hpp>

#include "drivers/sim/byte_link_loop.hpp"
#include "drivers/sim/grbl_machine.hpp"
#include "drivers/sim/hpgl_cutter.hpp"
#include "drivers/sim/modbus_server.hpp"

namespace {

std::atomic<bool> g_stop{false};

void on_signal(int) { g_stop.store(true); }

void print_ready(const std::string& where) {
  std::printf("ready: %s\n", where.c_str());
  std::fflush(stdout);
}

struct CommonOptions {
  std::string link;
  int port = 0;
  int baud = 0;
  std::string record;
  std::vector<std::string> faults;
};

void add_common(CLI::App* command, CommonOptions& options, int default_baud) {
  options.baud = default_baud;
  command->add_option("--link", options.link, "create a pseudo-terminal and a symlink at this path");
  command->add_option("--port", options.port, "listen on 127.0.0.1:PORT instead")->check(CLI::Range(1, 65535));
  command->add_option("--baud", options.baud,
                      "wire rate modelled on the link (10 bits per byte); 0 = unlimited; default: on a pty, the rate the "
                      "client sets (as a real device must match its sender); over TCP unlimited");
  command->add_option("--record", options.record, "folder where what was received is recorded");
  command->add_option("--fault", options.faults,
                      "inject a fault: drop-at-line=N, stall-at-line=N, freeze-at-line=N, garbage-at-line=N, error-at-line=N[:CODE], "
                      "alarm-at-line=N[:CODE]");
}

int check_common(const CommonOptions& options, lastcut::drivers::sim::Faults& faults) {
  if (options.link.empty() == (options.port == 0)) {
    std::fprintf(stderr, "lastcut-sim: error: give exactly one of --link PATH or --port N\n");
    return 2;
  }
  for (const auto& text : options.faults) {
    std::string error;
    if (!lastcut::drivers::sim::parse_fault(text, faults, error)) {
      std::fprintf(stderr, "lastcut-sim: error: %s\n", error.c_str());
      return 2;
    }
  }
  if (!options.record.empty()) {
    std::error_code ec;
    std::filesystem::create_directories(options.record, ec);
    if (ec) {
      std::fprintf(stderr, "lastcut-sim: error: cannot create %s: %s\n", options.record.c_str(), ec.message().c_str());
      return 2;
    }
  }
  return 0;
}

int run_bytes(lastcut::drivers::sim::ByteDevice& device, const CommonOptions& options,
              const lastcut::drivers::sim::Faults& faults) {
  const int baud = options.baud >= 0 ? options.baud : options.link.empty() ? 0 : -1;
  lastcut::drivers::sim::ByteLinkOptions link{options.link, options.port, baud, options.record, faults};
  std::string error;
  const int code = lastcut::drivers::sim::run_byte_device(device, link, g_stop, print_ready, error);
  if (code != 0) std::fprintf(stderr, "lastcut-sim: error: %s\n", error.c_str());
  return code;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace lastcut::drivers::sim;
  CLI::App app{"lastcut-sim: simulated grbl, HPGL and Modbus cutters (pty or 127.0.0.1)"};
  app.require_subcommand(1);

  CommonOptions grbl_common;
  GrblMachineOptions grbl_options;
  auto* grbl = app.add_subcommand("grbl", "grbl 1.1 controller");
  add_common(grbl, grbl_common, -1);
  grbl->add_option("--rx-buffer", grbl_options.rx_buffer_bytes, "serial receive buffer, bytes")->check(CLI::Range(16, 65536));
  grbl->add_option("--time-scale", grbl_options.time_scale, "motion time factor (0 = instant, 1 = real time)");

  CommonOptions hpgl_common;
  HpglCutterOptions hpgl_options;
  std::string svg_path;
  auto* hpgl = app.add_subcommand("hpgl", "HPGL cutter/plotter");
  add_common(hpgl, hpgl_common, -1);
  hpgl->add_option("--handshake", hpgl_options.handshake, "xonxoff | escb | none")->check(CLI::IsMember({"xonxoff", "escb", "none"}));
  hpgl->add_option("--buffer", hpgl_options.buffer_bytes, "input buffer, bytes")->check(CLI::Range(64, 65536));
  hpgl->add_option("--speed", hpgl_options.speed_mm_per_s, "cutting speed, mm/s");
  hpgl->add_option("--time-scale", hpgl_options.time_scale, "motion time factor (0 = instant)");

  CommonOptions modbus_common;
  ModbusSimOptions modbus_options;
  auto* modbus_tcp = app.add_subcommand("modbus-tcp", "PLC-driven cutter, Modbus TCP on 127.0.0.1");
  auto* modbus_rtu = app.add_subcommand("modbus-rtu", "PLC-driven cutter, Modbus RTU on a pty");
  for (auto* command : {modbus_tcp, modbus_rtu}) {
    add_common(command, modbus_common, 19200);
    command->add_option("--map", modbus_options.map_path, "register map TOML (default: built-in map)");
    command->add_option("--unit", modbus_options.unit_id, "unit (slave) id")->check(CLI::Range(1, 247));
    command->add_option("--cut-s", modbus_options.cut_s, "simulated cutting time of a job, seconds");
  }

  CLI11_PARSE(app, argc, argv);
  std::signal(SIGTERM, on_signal);
  std::signal(SIGINT, on_signal);
  std::signal(SIGPIPE, SIG_IGN);

  Faults faults;
  if (grbl->parsed()) {
    if (int rc = check_common(grbl_common, faults); rc != 0) return rc;
    grbl_options.faults = faults;
    GrblMachine machine(grbl_options);
    machine.power_on(0);
    return run_bytes(machine, grbl_common, faults);
  }
  if (hpgl->parsed()) {
    if (int rc = check_common(hpgl_common, faults); rc != 0) return rc;
    hpgl_options.faults = faults;
    HpglCutter cutter(hpgl_options);
    return run_bytes(cutter, hpgl_common, faults);
  }
  const bool rtu = modbus_rtu->parsed();
  if (rtu ? modbus_common.link.empty() : modbus_common.port == 0) {
    std::fprintf(stderr, "lastcut-sim: error: %s\n", rtu ? "modbus-rtu needs --link PATH" : "modbus-tcp needs --port N");
    return 2;
  }
  if (int rc = check_common(modbus_common, faults); rc != 0) return rc;
  modbus_options.faults = faults;
  modbus_options.record_dir = modbus_common.record;
  std::string error;
  const int code = rtu ? run_modbus_rtu(modbus_options, modbus_common.link, modbus_common.baud, g_stop, print_ready, error)
                       : run_modbus_tcp(modbus_options, modbus_common.port, g_stop, print_ready, error);
  if (code != 0) std::fprintf(stderr, "lastcut-sim: error: %s\n", error.c_str());
  return code;
}
