#pragma once
// The computing step of a hide (docs/hides.md): the pieces of the jobs waiting for a material,
// nested on the one hide that lies on a cutter's table, through the engine's batch entry
// (engine/nest/hide_batch.hpp: rotations, priorities, pairs, the independent checker), then the
// layout, SVG preview, cut file, hide report and offcut DXF written into the hide's batch folder.
// Engine errors come back as one-line reasons; nothing is thrown.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_parts.hpp"
#include "engine/core/status.hpp"

namespace lastcut::daemon {

inline constexpr const char* kHideReportFile = "hide-report.json";
inline constexpr const char* kOffcutFile = "offcut.dxf";

struct HideJobInput {
  std::string job_id;
  std::filesystem::path items_file;  // the job's items of this material (job_items_path)
  std::string order;              // pairs: the jobs of one order go on one hide (material pairs = same_hide)
  int priority = 0;               // higher first: the oldest waiting job gets the highest
  std::vector<int> copies;        // the current part's, when split over hides before (JobPart::copies)
  bool may_split = false;         // its ticket's split_over_hides: the hide may take some of its pieces
};

struct HideMade {
  std::vector<std::string> placed;               // jobs whose every piece is on the hide
  std::map<std::string, std::string> waiting;    // job id -> why it waits for the next hide
  std::map<std::string, std::string> rejected;   // job id -> why its pieces cannot be read
  // Jobs that may split whose pieces lie on the hide only in part (also in `placed`): job id -> the
  // copies of each item of its items file placed and left for the next hide (job_parts.hpp).
  std::map<std::string, PartSplit> split;
  std::string cut_file;                          // file name in batch_dir; empty when nothing was placed
  double utilisation = 0;                        // placed piece area / usable hide area, 0..1
  int piece_count = 0;
  int pieces_waiting = 0;                        // the pieces of the jobs in `waiting`
  nlohmann::json report;                         // what hide-report.json holds
};

// Nests the jobs' pieces on the hide file hide_dir/hide_file (with its sidecar beside it) and
// writes layout.json, preview.svg, the cut file, hide-report.json and offcut.dxf into hide_dir.
// Fails as a whole when the hide cannot be read, no machine profile is found or a file cannot be
// written.
Result<HideMade> build_hide(const std::vector<HideJobInput>& jobs, const std::filesystem::path& hide_dir,
                            const std::string& hide_file, const MaterialConfig& material, const CutterSection& cutter,
                            const std::filesystem::path& machines_dir, double nest_time_s);

}  // namespace lastcut::daemon
