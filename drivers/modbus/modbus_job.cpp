// Modbus job: the host side of the register-map handshake (see modbus_job.hpp).
#include "drivers/modbus/modbus_job.hpp"

#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>

#include "drivers/modbus/modbus_client.hpp"
#include "drivers/seconds_text.hpp"

namespace lastcut::drivers::modbus {

namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

struct PlcState {
  int status = -1, error_code = 0, progress_permille = 0, block_ack = 0;
};

class ModbusJob {
 public:
  ModbusJob(const CutterConfig& config, const RegisterMap& map, ModbusClient& client, const ProgressCallback& progress,
            const std::atomic<bool>& cancel)
      : config_(config), map_(map), client_(client), progress_(progress), cancel_(cancel) {}

  SendResult run(const std::string& program);
  bool read_state(PlcState& state, std::string& error);
  std::string status_name(int status) const;

 private:
  SendResult finish(SendOutcome outcome, const std::string& reason) {
    log_.push_back(to_string(outcome) + ": " + reason);
    return {outcome, reason, log_};
  }
  // Polls until `done(state)`; reconnects on link errors until timeout_s passes without a reply.
  bool wait_for(const std::function<bool(const PlcState&)>& done, PlcState& state, std::string& error, bool& cancelled);
  void report(const std::string& device_state) {
    if (progress_) progress_({bytes_sent_, bytes_total_, blocks_acked_, blocks_total_, device_state});
  }

  const CutterConfig& config_;
  const RegisterMap& map_;
  ModbusClient& client_;
  const ProgressCallback& progress_;
  const std::atomic<bool>& cancel_;
  std::vector<std::string> log_;
  size_t bytes_sent_ = 0, bytes_total_ = 0, blocks_acked_ = 0, blocks_total_ = 0;
};

std::string ModbusJob::status_name(int status) const {
  const StatusCodes& c = map_.status_codes;
  if (status == c.not_ready) return "not ready";
  if (status == c.ready) return "ready";
  if (status == c.receiving) return "receiving";
  if (status == c.loaded) return "loaded";
  if (status == c.running) return "running";
  if (status == c.done) return "done";
  if (status == c.error) return "error";
  return "unknown status " + std::to_string(status);
}

bool ModbusJob::read_state(PlcState& state, std::string& error) {
  const int first = std::min({map_.status, map_.error_code, map_.progress_permille, map_.block_ack});
  const int last = std::max({map_.status, map_.error_code, map_.progress_permille, map_.block_ack});
  std::vector<uint16_t> values;
  if (last - first < 16) {
    if (!client_.read(first, last - first + 1, values, error)) return false;
    state = {values[static_cast<size_t>(map_.status - first)], values[static_cast<size_t>(map_.error_code - first)],
             values[static_cast<size_t>(map_.progress_permille - first)], values[static_cast<size_t>(map_.block_ack - first)]};
    return true;
  }
  int* fields[] = {&state.status, &state.error_code, &state.progress_permille, &state.block_ack};
  const int addresses[] = {map_.status, map_.error_code, map_.progress_permille, map_.block_ack};
  for (int i = 0; i < 4; ++i) {
    if (!client_.read(addresses[i], 1, values, error)) return false;
    *fields[i] = values[0];
  }
  return true;
}

bool ModbusJob::wait_for(const std::function<bool(const PlcState&)>& done, PlcState& state, std::string& error, bool& cancelled) {
  double last_reply_s = now_s();
  cancelled = false;
  while (true) {
    if (cancel_.load()) {
      cancelled = true;
      return false;
    }
    std::string read_error;
    if (read_state(state, read_error)) {
      last_reply_s = now_s();
      if (state.status == map_.status_codes.error || done(state)) return true;
    } else if (!client_.last_error_was_link()) {
      error = read_error;
      return false;
    } else {
      if (now_s() - last_reply_s > config_.timeout_s) {
        error = "no reply from the PLC for " + seconds_text(config_.timeout_s) + " (" + read_error + ")";
        return false;
      }
      log_.push_back("link error, reconnecting: " + read_error);
      std::string ignored;
      client_.connect(ignored);
    }
    std::this_thread::sleep_for(std::chrono::duration<double>(map_.poll_s));
  }
}

SendResult ModbusJob::run(const std::string& program) {
  bytes_total_ = program.size();
  const size_t window_bytes = static_cast<size_t>(map_.window_words) * 2;
  blocks_total_ = (program.size() + window_bytes - 1) / window_bytes;
  std::string error;
  if (program.empty()) return finish(SendOutcome::Failed, "the program is empty");
  if (program.size() > 0xffffffffu) return finish(SendOutcome::Failed, "the program is larger than 4 GB");
  if (!client_.connect(error)) return finish(SendOutcome::Failed, error);
  PlcState state;
  if (!read_state(state, error)) return finish(SendOutcome::Failed, error);
  log_.push_back("PLC status " + status_name(state.status) + " on " + client_.describe());
  if (state.status == map_.status_codes.error) {
    return finish(SendOutcome::Failed, "PLC reports error code " + std::to_string(state.error_code) +
                                           ": clear it at the machine (lastcut never clears errors on its own)");
  }
  if (state.status != map_.status_codes.ready) return finish(SendOutcome::Failed, "cutter not ready (" + status_name(state.status) + ")");

  std::vector<uint16_t> identity(static_cast<size_t>(map_.job_id_words), 0);
  for (size_t i = 0; i < config_.job_id.size() && i / 2 < identity.size(); ++i) {
    identity[i / 2] |= static_cast<uint16_t>(static_cast<unsigned char>(config_.job_id[i]) << (i % 2 == 0 ? 8 : 0));
  }
  const auto length = static_cast<uint32_t>(program.size());
  bool cancelled = false;
  if (!client_.write(map_.job_id, identity, error) ||
      !client_.write(map_.program_bytes, {static_cast<uint16_t>(length >> 16), static_cast<uint16_t>(length & 0xffff)}, error) ||
      !client_.write(map_.command, {static_cast<uint16_t>(map_.command_codes.begin)}, error)) {
    return finish(SendOutcome::Failed, error);
  }
  if (!wait_for([&](const PlcState& s) { return s.status == map_.status_codes.receiving; }, state, error, cancelled)) {
    return finish(SendOutcome::Failed, cancelled ? "cancelled before the program was sent" : error);
  }
  if (state.status == map_.status_codes.error) {
    return finish(SendOutcome::Failed, "PLC refused the job: error code " + std::to_string(state.error_code));
  }

  // Transfer. Nothing runs before `start`, so any failure here leaves the machine uncut.
  for (size_t block = 1; block <= blocks_total_; ++block) {
    const size_t offset = (block - 1) * window_bytes;
    const size_t bytes = std::min(window_bytes, program.size() - offset);
    std::vector<uint16_t> words((bytes + 1) / 2, 0);
    for (size_t i = 0; i < bytes; ++i) {
      words[i / 2] |= static_cast<uint16_t>(static_cast<unsigned char>(program[offset + i]) << (i % 2 == 0 ? 8 : 0));
    }
    if (!client_.write(map_.window, words, error) ||
        !client_.write(map_.block_number, {static_cast<uint16_t>(block & 0xffff), static_cast<uint16_t>(bytes)}, error)) {
      return finish(SendOutcome::Failed, "block " + std::to_string(block) + ": " + error + "; nothing was started");
    }
    const auto expected = static_cast<int>(block & 0xffff);
    if (!wait_for([&](const PlcState& s) { return s.block_ack == expected; }, state, error, cancelled)) {
      if (!cancelled) {
        return finish(SendOutcome::Failed, "block " + std::to_string(block) + " not acknowledged: " + error + "; nothing was started");
      }
      std::string ignored;
      client_.write(map_.command, {static_cast<uint16_t>(map_.command_codes.abort)}, ignored);
      return finish(SendOutcome::Failed, "cancelled during transfer; nothing was started");
    }
    if (state.status == map_.status_codes.error) {
      return finish(SendOutcome::Failed, "PLC rejected block " + std::to_string(block) + ": error code " + std::to_string(state.error_code));
    }
    bytes_sent_ += bytes;
    blocks_acked_ = block;
    report("receiving block " + std::to_string(block) + "/" + std::to_string(blocks_total_));
  }
  if (!wait_for([&](const PlcState& s) { return s.status == map_.status_codes.loaded; }, state, error, cancelled) ||
      state.status == map_.status_codes.error) {
    return finish(SendOutcome::Failed, cancelled ? "cancelled before start" : "PLC did not confirm the program was loaded: " +
                                                       (error.empty() ? "error code " + std::to_string(state.error_code) : error));
  }
  if (!client_.write(map_.command, {static_cast<uint16_t>(map_.command_codes.start)}, error)) {
    // The start request may or may not have reached the PLC: treat the machine as possibly cutting.
    return finish(SendOutcome::Interrupted, "start command not confirmed: " + error + "; check the machine, nothing was resent");
  }
  log_.push_back("program loaded (" + std::to_string(program.size()) + " bytes), started");

  int last_permille = -1;
  const bool finished = wait_for(
      [&](const PlcState& s) {
        if (s.progress_permille != last_permille && s.status == map_.status_codes.running) {
          last_permille = s.progress_permille;
          report("running " + std::to_string(s.progress_permille / 10) + "%");
        }
        return s.status == map_.status_codes.done;
      },
      state, error, cancelled);
  if (cancelled) {
    std::string abort_error;
    const bool aborted = client_.write(map_.command, {static_cast<uint16_t>(map_.command_codes.abort)}, abort_error);
    return finish(SendOutcome::Interrupted, std::string("cancelled by the operator; ") +
                                                (aborted ? "abort sent to the PLC" : "abort NOT confirmed (" + abort_error + "): check the machine"));
  }
  if (!finished) return finish(SendOutcome::Interrupted, error + "; the machine may have cut part of the job, nothing was resent");
  if (state.status == map_.status_codes.error) {
    return finish(SendOutcome::Interrupted, "PLC reports error code " + std::to_string(state.error_code) + " while cutting (" +
                                                std::to_string(state.progress_permille / 10) + "% done); nothing was resent");
  }
  report("done");
  return finish(SendOutcome::Done, "PLC reports the job done");
}

}  // namespace

bool register_map_for(const CutterConfig& config, RegisterMap& map, std::string& error) {
  map = RegisterMap{};
  if (config.modbus_map.empty()) return validate_register_map(map, error);
  return load_register_map(config.modbus_map, map, error);
}

SendResult run_modbus_job(const CutterConfig& config, const std::string& program, const ProgressCallback& progress,
                          const std::atomic<bool>& cancel) {
  RegisterMap map;
  ModbusEndpoint endpoint;
  std::string error;
  if (!register_map_for(config, map, error)) return {SendOutcome::Failed, error, {}};
  if (!parse_modbus_endpoint(config.modbus, endpoint, error)) return {SendOutcome::Failed, error, {}};
  ModbusClient client(endpoint, config.modbus_unit_id, std::min(1.0, config.timeout_s));
  ModbusJob job(config, map, client, progress, cancel);
  return job.run(program);
}

ProbeResult probe_modbus(const CutterConfig& config) {
  RegisterMap map;
  ModbusEndpoint endpoint;
  std::string error;
  if (!register_map_for(config, map, error)) return {false, "unknown", error};
  if (!parse_modbus_endpoint(config.modbus, endpoint, error)) return {false, "unknown", error};
  ModbusClient client(endpoint, config.modbus_unit_id, std::min(1.0, config.timeout_s));
  const ProgressCallback none;
  const std::atomic<bool> never{false};
  ModbusJob job(config, map, client, none, never);
  PlcState state;
  if (!job.read_state(state, error)) return {false, "unreachable", error};
  const std::string name = job.status_name(state.status);
  if (state.status == map.status_codes.ready) return {true, name, ""};
  if (state.status == map.status_codes.error) return {false, name, "PLC reports error code " + std::to_string(state.error_code)};
  return {false, name, "cutter not ready (" + name + ")"};
}

}  // namespace lastcut::drivers::modbus
