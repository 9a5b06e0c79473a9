// `lastcut send FILE ...`: streams a cut file to a cutter through drivers/cutter.hpp and waits
// until the machine reports it finished. `lastcut ports`: serial ports with their USB identity.
// Exit codes of `send`: 0 done, 1 failed (nothing cut, safe to retry), 3 interrupted (the
// machine may have cut part of the job: check it; lastcut never resends on its own), 2 usage.
#include <atomic>
#include <csignal>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <unistd.h>

#include "daemon/cli/commands.hpp"
#include "drivers/cutter.hpp"
#include "drivers/transport/serial_ports.hpp"

namespace lastcut::cli {

namespace {

std::atomic<bool> g_cancel{false};

void on_interrupt(int) { g_cancel.store(true); }

struct SendOptions {
  std::string file, port, modbus, protocol, flow = "none", handshake, map, job_id, streaming = "counting", unlock = "never";
  int baud = 115200;
  double timeout_s = 10;
  std::vector<int> harmless;
  bool no_queries = false;
};

std::string bar(const drivers::SendProgress& p) {
  const double fraction = p.bytes_total == 0 ? 0.0 : static_cast<double>(p.bytes_sent) / static_cast<double>(p.bytes_total);
  const int width = 30;
  const int filled = static_cast<int>(fraction * width);
  std::string text = "[" + std::string(static_cast<size_t>(filled), '#') + std::string(static_cast<size_t>(width - filled), '.') + "] ";
  char numbers[96];
  std::snprintf(numbers, sizeof numbers, "%3.0f%% %zu/%zu bytes", fraction * 100, p.bytes_sent, p.bytes_total);
  text += numbers;
  if (p.lines_total > 0) text += " " + std::to_string(p.lines_acked) + "/" + std::to_string(p.lines_total) + " lines";
  if (!p.device_state.empty()) text += " " + p.device_state;
  return text;
}

int run_send(const SendOptions& options) {
  std::ifstream in(options.file, std::ios::binary);
  if (!in) {
    std::fprintf(stderr, "lastcut: error: cannot read %s\n", options.file.c_str());
    return 1;
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string program = buffer.str();

  drivers::CutterConfig config;
  config.name = options.modbus.empty() ? options.port : options.modbus;
  config.protocol = options.modbus.empty() ? options.protocol : "modbus";
  config.port = options.port;
  config.modbus = options.modbus;
  config.baud = options.baud;
  config.flow = options.flow;
  config.timeout_s = options.timeout_s;
  config.harmless_grbl_errors = options.harmless;
  config.grbl_streaming = options.streaming;
  config.grbl_unlock = options.unlock;
  config.hpgl_handshake = options.handshake;
  config.hpgl_status_queries = !options.no_queries;
  config.modbus_map = options.map;
  config.job_id = options.job_id.empty() ? options.file.substr(options.file.find_last_of('/') + 1).substr(0, 16) : options.job_id;

  const bool terminal = ::isatty(STDERR_FILENO) != 0;
  double last_plain_fraction = -1;
  auto progress = [&](const drivers::SendProgress& p) {
    if (terminal) {
      std::fprintf(stderr, "\r%s\033[K", bar(p).c_str());
      return;
    }
    // Plain lines for logs and pipes: one per 10 % and at the end.
    const double fraction = p.bytes_total == 0 ? 0 : static_cast<double>(p.bytes_sent) / static_cast<double>(p.bytes_total);
    if (fraction - last_plain_fraction >= 0.1 || (fraction >= 1.0 && last_plain_fraction < 1.0)) {
      std::fprintf(stderr, "progress: %s\n", bar(p).c_str());
      last_plain_fraction = fraction;
    }
  };
  std::signal(SIGINT, on_interrupt);
  std::signal(SIGTERM, on_interrupt);
  const drivers::SendResult result = drivers::send_job(config, program, progress, g_cancel);
  std::signal(SIGINT, SIG_DFL);
  std::signal(SIGTERM, SIG_DFL);
  if (terminal) std::fprintf(stderr, "\n");
  switch (result.outcome) {
    case drivers::SendOutcome::Done:
      std::printf("done: %s\n", result.reason.c_str());
      return 0;
    case drivers::SendOutcome::Failed:
      std::fprintf(stderr, "lastcut: failed (nothing was cut): %s\n", result.reason.c_str());
      break;
    case drivers::SendOutcome::Interrupted:
      std::fprintf(stderr, "lastcut: INTERRUPTED (the machine may have cut part of the job; check it, nothing is resent): %s\n",
                   result.reason.c_str());
      break;
  }
  for (const auto& line : result.device_log) std::fprintf(stderr, "  %s\n", line.c_str());
  return result.outcome == drivers::SendOutcome::Failed ? 1 : 3;
}

int run_ports() {
  const auto ports = drivers::list_serial_ports();
  if (ports.empty()) {
    std::printf("no serial ports found\n");
    return 0;
  }
  std::printf("%-16s %-28s %s\n", "DEVICE", "STABLE NAME", "DESCRIPTION");
  for (const auto& port : ports) {
    std::string description = port.description;
    if (port.usb && !port.usb_manufacturer.empty()) description += " (" + port.usb_manufacturer + ")";
    std::printf("%-16s %-28s %s\n", port.device.c_str(), port.usb ? port.stable_name().c_str() : "-", description.c_str());
    if (!port.by_id_path.empty()) std::printf("%-16s %s\n", "", port.by_id_path.c_str());
  }
  return 0;
}

}  // namespace

void add_send_command(CLI::App& app, int& exit_code) {
  auto options = std::make_shared<SendOptions>();
  auto* send = app.add_subcommand("send", "send a cut file to a cutter and wait until it has finished");
  send->add_option("file", options->file, "HPGL or G-code file (any file for Modbus cutters)")->required()->check(CLI::ExistingFile);
  auto* port = send->add_option("--port", options->port, "serial port, usb:VID:PID[:SERIAL], /dev/serial/by-id/..., tcp://HOST:PORT or a pty");
  auto* modbus = send->add_option("--modbus", options->modbus, "PLC-driven cutter: tcp://HOST:PORT or rtu:DEVICE[,BAUD[,8N1]]");
  port->excludes(modbus);
  send->add_option("--protocol", options->protocol, "grbl or hpgl (with --port)")->check(CLI::IsMember({"grbl", "hpgl"}));
  send->add_option("--baud", options->baud, "serial speed")->capture_default_str();
  send->add_option("--flow", options->flow, "flow control")->check(CLI::IsMember({"none", "xonxoff", "rtscts"}))->capture_default_str();
  send->add_option("--timeout", options->timeout_s, "seconds of silence before the job is declared lost")->capture_default_str();
  send->add_option("--harmless-errors", options->harmless, "grbl error:N codes that do not stop the job")->delimiter(',');
  send->add_option("--streaming", options->streaming, "grbl: counting or send-wait")->check(CLI::IsMember({"counting", "send-wait"}));
  send->add_option("--unlock", options->unlock, "grbl in alarm: never (refuse) or unlock ($X)")->check(CLI::IsMember({"never", "unlock"}));
  send->add_option("--handshake", options->handshake, "hpgl: escb for the ESC.B buffer handshake")->check(CLI::IsMember({"escb"}));
  send->add_flag("--no-status-queries", options->no_queries, "hpgl: the device never answers ESC.O/ESC.E/OA");
  send->add_option("--map", options->map, "Modbus register map TOML (default: built-in map)")->check(CLI::ExistingFile);
  send->add_option("--job-id", options->job_id, "job identity written to the PLC (default: file name)");
  send->callback([options, &exit_code] {
    if (options->port.empty() == options->modbus.empty()) {
      std::fprintf(stderr, "lastcut: error: give --port (with --protocol) or --modbus\n");
      exit_code = 2;
      return;
    }
    if (!options->port.empty() && options->protocol.empty()) {
      std::fprintf(stderr, "lastcut: error: --port needs --protocol grbl or hpgl\n");
      exit_code = 2;
      return;
    }
    exit_code = run_send(*options);
  });

  auto* ports = app.add_subcommand("ports", "list serial ports with their USB ids (for stable port names in the configuration)");
  ports->callback([&exit_code] { exit_code = run_ports(); });
}

}  // namespace lastcut::cli
