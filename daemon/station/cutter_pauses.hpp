#pragma once
// CutterPauses: which of this station's cutters an operator paused from the page, and who. A paused
// cutter finishes the batch on its table and claims no new one until resumed; its batches wait in
// the store, nothing is lost (as a stopped CUPS printer keeps its queue). Kept in
// <spool>/paused-cutters.json, written durably, so that a restart (systemd's, after a crash) does
// not start a cutter someone stopped. Thread-safe: the page's threads set it, the cutter workers
// read it at every turn.
#include <filesystem>
#include <map>
#include <mutex>
#include <optional>
#include <string>

#include "engine/core/status.hpp"

namespace lastcut::daemon {

class CutterPauses {
 public:
  // Reads `file`; a missing file means no cutter is paused. A file that cannot be read or parsed
  // pauses nothing (who and which are unknown) and says so in the log.
  explicit CutterPauses(std::filesystem::path file);

  // Who paused `cutter` ("anna"), nullopt when it is not paused.
  std::optional<std::string> paused_by(const std::string& cutter) const;
  // cutter -> who paused it.
  std::map<std::string, std::string> paused() const;
  // The line to log and answer, or why not: already paused, not paused, or the file not written
  // (then nothing changed).
  Result<std::string> pause(const std::string& cutter, const std::string& who);
  Result<std::string> resume(const std::string& cutter, const std::string& who);

 private:
  Status save(const std::map<std::string, std::string>& paused) const;

  std::filesystem::path file_;
  mutable std::mutex mutex_;
  std::map<std::string, std::string> paused_;
};

}  // namespace lastcut::daemon
