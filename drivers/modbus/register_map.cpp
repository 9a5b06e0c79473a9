// Register map: defaults, TOML loading and validation.
#include "drivers/modbus/register_map.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <toml++/toml.h>
#include <utility>
#include <vector>

namespace lastcut::drivers::modbus {

int RegisterMap::register_count() const {
  return std::max({status, error_code, progress_permille, block_ack, command, job_id + job_id_words - 1,
                   program_bytes + 1, block_number, block_length, window + window_words - 1}) + 1;
}

bool validate_register_map(const RegisterMap& map, std::string& error) {
  if (map.window_words < 1 || map.window_words > 123) {
    error = "register map: window_words must be 1..123 (one Write Multiple Registers request)";
    return false;
  }
  if (map.job_id_words < 1 || map.job_id_words > 32) {
    error = "register map: job_id_words must be 1..32";
    return false;
  }
  if (map.block_length != map.block_number + 1) {
    error = "register map: block_length must directly follow block_number (they are written in one request)";
    return false;
  }
  std::vector<std::pair<int, int>> ranges{{map.status, 1}, {map.error_code, 1}, {map.progress_permille, 1},
                                          {map.block_ack, 1}, {map.command, 1}, {map.job_id, map.job_id_words},
                                          {map.program_bytes, 2}, {map.block_number, 2}, {map.window, map.window_words}};
  // Every range inside the 16-bit address space first: then the sums below cannot overflow.
  for (const auto& [first, count] : ranges) {
    if (first < 0 || first > 65536 - count) {
      error = "register map: address out of range 0..65535";
      return false;
    }
  }
  for (size_t i = 0; i < ranges.size(); ++i) {
    for (size_t j = i + 1; j < ranges.size(); ++j) {
      const bool overlap = ranges[i].first < ranges[j].first + ranges[j].second && ranges[j].first < ranges[i].first + ranges[i].second;
      if (overlap) {
        error = "register map: registers " + std::to_string(ranges[i].first) + " and " + std::to_string(ranges[j].first) + " overlap";
        return false;
      }
    }
  }
  if (!(map.poll_s > 0) || !std::isfinite(map.poll_s)) {  // NaN fails the first test
    error = "register map: poll_s must be a positive number";
    return false;
  }
  return true;
}

bool load_register_map(const std::string& path, RegisterMap& map, std::string& error) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    error = "register map " + path + ": " + std::string(e.description()) + " at line " +
            std::to_string(e.source().begin.line);
    return false;
  }
  // Addresses and codes are 16-bit register values: anything else is refused here, before a
  // larger number could be cut down to an int (4294967296 would have become register 0).
  std::string bad_key;
  auto get = [&](const char* table, const char* key, int& field) {
    const auto node = root[table][key];
    if (!node) return;
    // Only integer nodes: toml++ converts a float like 1e78 to int64_t with undefined behaviour.
    const std::optional<int64_t> v = node.is_integer() ? node.value<int64_t>() : std::nullopt;
    if (!v || *v < 0 || *v > 65535) {
      if (bad_key.empty()) bad_key = std::string(table) + "." + key;
      return;
    }
    field = static_cast<int>(*v);
  };
  get("registers", "status", map.status);
  get("registers", "error_code", map.error_code);
  get("registers", "progress_permille", map.progress_permille);
  get("registers", "block_ack", map.block_ack);
  get("registers", "command", map.command);
  get("registers", "job_id", map.job_id);
  get("registers", "job_id_words", map.job_id_words);
  get("registers", "program_bytes", map.program_bytes);
  get("registers", "block_number", map.block_number);
  get("registers", "block_length", map.block_length);
  get("registers", "window", map.window);
  get("registers", "window_words", map.window_words);
  get("status", "not_ready", map.status_codes.not_ready);
  get("status", "ready", map.status_codes.ready);
  get("status", "receiving", map.status_codes.receiving);
  get("status", "loaded", map.status_codes.loaded);
  get("status", "running", map.status_codes.running);
  get("status", "done", map.status_codes.done);
  get("status", "error", map.status_codes.error);
  get("command", "begin", map.command_codes.begin);
  get("command", "start", map.command_codes.start);
  get("command", "abort", map.command_codes.abort);
  get("command", "clear_error", map.command_codes.clear_error);
  if (auto v = root["timing"]["poll_s"].value<double>()) map.poll_s = *v;
  if (!bad_key.empty()) {
    error = "register map " + path + ": " + bad_key + " must be an integer 0..65535";
    return false;
  }
  return validate_register_map(map, error);
}

}  // namespace lastcut::drivers::modbus
