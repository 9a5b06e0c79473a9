#include "daemon/station/cutter_pauses.hpp"

#include <fstream>
#include <sstream>

#include <nlohmann/json.hpp>
#include <spdlog/spdlog.h>

#include "engine/core/durable_file.hpp"

namespace lastcut::daemon {

CutterPauses::CutterPauses(std::filesystem::path file) : file_(std::move(file)) {
  std::ifstream in(file_);
  if (!in) return;
  std::ostringstream text;
  text << in.rdbuf();
  try {
    const nlohmann::json saved = nlohmann::json::parse(text.str());  // named: items() refers into it
    for (const auto& [cutter, who] : saved.at("paused").items()) paused_[cutter] = who.get<std::string>();
  } catch (const std::exception& error) {
    paused_.clear();
    spdlog::error("{} unreadable, no cutter is paused: {}", file_.string(), error.what());
    return;
  }
  for (const auto& [cutter, who] : paused_)
    spdlog::warn("cutter {}: paused (by {}) before this start; it takes no batch until resumed", cutter, who);
}

std::optional<std::string> CutterPauses::paused_by(const std::string& cutter) const {
  std::lock_guard lock(mutex_);
  const auto found = paused_.find(cutter);
  if (found == paused_.end()) return std::nullopt;
  return found->second;
}

std::map<std::string, std::string> CutterPauses::paused() const {
  std::lock_guard lock(mutex_);
  return paused_;
}

Status CutterPauses::save(const std::map<std::string, std::string>& paused) const {
  return write_file_durably(file_, nlohmann::json{{"paused", paused}}.dump(2) + "\n");
}

Result<std::string> CutterPauses::pause(const std::string& cutter, const std::string& who) {
  std::lock_guard lock(mutex_);
  if (const auto found = paused_.find(cutter); found != paused_.end())
    return Status::failure("cutter " + cutter + " is already paused (by " + found->second + ")");
  auto next = paused_;
  next[cutter] = who;
  if (Status saved = save(next); !saved) return Status::failure("cutter " + cutter + " not paused: " + saved.error());
  paused_ = std::move(next);
  return "cutter " + cutter + " paused: it finishes the batch on its table, if any, and starts no other until resumed";
}

Result<std::string> CutterPauses::resume(const std::string& cutter, const std::string& who) {
  std::lock_guard lock(mutex_);
  const auto found = paused_.find(cutter);
  if (found == paused_.end()) return Status::failure("cutter " + cutter + " is not paused");
  auto next = paused_;
  next.erase(cutter);
  if (Status saved = save(next); !saved) return Status::failure("cutter " + cutter + " not resumed: " + saved.error());
  const std::string paused_by = found->second;
  paused_ = std::move(next);
  return "cutter " + cutter + " resumed (paused by " + paused_by + ", resumed by " + who + "): its batches are cut again";
}

}  // namespace lastcut::daemon
