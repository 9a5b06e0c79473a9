// send_job / probe_cutter: opens the configured link and hands over to the protocol.
#include "drivers/cutter.hpp"

#include "drivers/grbl/grbl_job.hpp"
#include "drivers/hpgl/hpgl_job.hpp"
#include "drivers/modbus/modbus_job.hpp"
#include "drivers/transport/transport.hpp"

namespace lastcut::drivers {

std::string to_string(SendOutcome outcome) {
  switch (outcome) {
    case SendOutcome::Done: return "done";
    case SendOutcome::Interrupted: return "interrupted";
    case SendOutcome::Failed: break;
  }
  return "failed";
}

namespace {

std::string who(const CutterConfig& config) { return config.name.empty() ? "cutter" : "cutter '" + config.name + "'"; }

bool serial_settings(const CutterConfig& config, SerialSettings& settings, std::string& error) {
  settings.baud = config.baud;
  settings.data_bits = config.data_bits;
  settings.parity = config.parity;
  settings.stop_bits = config.stop_bits;
  if (!parse_flow_control(config.flow, settings.flow)) {
    error = "unknown flow control '" + config.flow + "' (none, xonxoff or rtscts)";
    return false;
  }
  return true;
}

}  // namespace

SendResult send_job(const CutterConfig& config, const std::string& program, const ProgressCallback& progress,
                    const std::atomic<bool>& cancel) {
  if (config.protocol == "modbus") {
    SendResult result = modbus::run_modbus_job(config, program, progress, cancel);
    if (result.outcome != SendOutcome::Done) result.reason = who(config) + ": " + result.reason;
    return result;
  }
  if (config.protocol != "grbl" && config.protocol != "hpgl") {
    return {SendOutcome::Failed, who(config) + ": unknown protocol '" + config.protocol + "' (grbl, hpgl or modbus)", {}};
  }
  SerialSettings settings;
  std::string error;
  if (!serial_settings(config, settings, error)) return {SendOutcome::Failed, who(config) + ": " + error, {}};
  OpenResult opened = open_transport(config.port, settings, config.timeout_s);
  if (!opened.transport) return {SendOutcome::Failed, who(config) + ": " + opened.error, {}};
  SendResult result = config.protocol == "grbl" ? grbl::run_grbl_job(*opened.transport, config, program, progress, cancel)
                                                : hpgl::run_hpgl_job(*opened.transport, config, program, progress, cancel);
  opened.transport->close();
  if (result.outcome != SendOutcome::Done) result.reason = who(config) + ": " + result.reason;
  return result;
}

ProbeResult probe_cutter(const CutterConfig& config) {
  if (config.protocol == "modbus") return modbus::probe_modbus(config);
  if (config.protocol != "grbl" && config.protocol != "hpgl") {
    return {false, "unknown", "unknown protocol '" + config.protocol + "'"};
  }
  SerialSettings settings;
  std::string error;
  if (!serial_settings(config, settings, error)) return {false, "unknown", error};
  OpenResult opened = open_transport(config.port, settings, config.timeout_s);
  if (!opened.transport) return {false, "unreachable", opened.error};
  return config.protocol == "grbl" ? grbl::probe_grbl(*opened.transport, config) : hpgl::probe_hpgl(*opened.transport, config);
}

}  // namespace lastcut::drivers
