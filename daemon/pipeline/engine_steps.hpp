#pragma once
// The two computing steps of a job, bound to the engine: scan -> molds (engine/scan) and
// batch of molds -> layout -> cut file (engine/nest, engine/toolpath). Both write only into the
// folder they are given, under temporary names renamed at the end, so a crash mid-step leaves
// nothing half-written that a later reader could take for a result. Engine errors come back as
// one-line reasons; nothing is thrown.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "daemon/spool/job_ticket.hpp"

namespace lastcut::daemon {

// File names inside a job folder.
inline constexpr const char* kMoldsFolder = "molds";
inline constexpr const char* kPiecesFile = "pieces.json";  // mold outlines for nesting (own format)
inline constexpr const char* kReportFile = "report.json";
inline constexpr const char* kPreviewFile = "preview.svg";
inline constexpr const char* kLayoutFile = "layout.json";

struct MoldsOutcome {
  std::string error;          // one line in an operator's words; empty on success
  int piece_count = 0;        // molds made (before quantity)
  nlohmann::json measures;    // the engine's scan report (sizes, distortion, timings)
};

// Computes the molds of the scan into job_dir/molds/ and job_dir/pieces.json.
MoldsOutcome compute_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                           const JobTicket& ticket, double default_allowance_mm);

struct BatchJobInput {
  std::string job_id;
  std::filesystem::path job_dir;  // holds pieces.json
  JobTicket ticket;
  std::string scan_name;          // names the pieces of a job without an order number
};

struct BatchOutcome {
  std::string error;                           // the whole batch failed (e.g. no machine profile)
  std::map<std::string, std::string> rejected;  // job id -> why its molds could not be placed
  std::string cut_file;                        // file name in batch_dir
  double utilisation = 0;                      // 0..1
  int piece_count = 0;                         // pieces placed
  nlohmann::json measures;                     // nesting and toolpath figures
};

// Nests the pieces of `jobs` on `material`, writes layout.json, preview.svg and the cut file
// for `cutter` into batch_dir.
BatchOutcome build_batch(const std::vector<BatchJobInput>& jobs, const MaterialConfig& material,
                         const CutterSection& cutter, const std::filesystem::path& machines_dir,
                         double nest_time_s, const std::filesystem::path& batch_dir);

}  // namespace lastcut::daemon
