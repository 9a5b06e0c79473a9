#pragma once
// The two computing steps of a job, each one call of the engine's own stage entries, the same ones
// the command line uses:
//   scan -> molds:         scan_to_molds + write_scan_outputs (engine/scan), then the molds as nest
//                          items in the engine's JSON (items_from_molds, items_to_json)
//   items -> layout:       nest() (engine/nest/nester.hpp: option checks, independent layout check)
//   layout -> cut file:    make_cut_file (engine/toolpath/cut_job.hpp); the batch and job ids go
//                          into the file as it is written, and the cutter gets exactly these bytes
// Both write only into the folder they are given, through durable writes, so a crash mid-step
// leaves nothing half-written that a later reader could take for a result. Engine errors come
// back as one-line reasons; nothing is thrown: an exception that is not an EngineError (a bug, or a
// library's exception the engine failed to translate) fails the job, batch or hide with
// unexpected_failure_reason instead of ending lastcutd and every job it has in hand.
#include <filesystem>
#include <exception>
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "daemon/config/daemon_config.hpp"
#include "daemon/job/job_parts.hpp"
#include "daemon/job/job_ticket.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/status.hpp"
#include "engine/mold/mold.hpp"
#include "engine/nest/nest_problem.hpp"

namespace lastcut::daemon {

// File names inside a job folder.
inline constexpr const char* kMoldsFolder = "molds";
inline constexpr const char* kPiecesFolder = "pieces";  // a style job's pieces (engine/style/piece_outputs.hpp)
inline constexpr const char* kItemsFile = "items.json";  // the job's pieces as nest items (engine/nest/nest_json.hpp)
inline constexpr const char* kReportFile = "report.json";
inline constexpr const char* kPreviewFile = "preview.svg";
inline constexpr const char* kLayoutFile = "layout.json";

inline std::string unexpected_failure_reason(const std::exception& error) {
  return std::string("internal error, please report it with the input (kept): ") + error.what();
}

struct MoldsMade {
  int piece_count = 0;        // molds or pieces made (before quantity)
  int pieces_to_cut = 0;      // the items' demands together: what batching and status count
  std::string noun = "molds";  // what was made, for the log: "molds" or "pieces"
  nlohmann::json measures;    // the engine's report, as written to molds/report.json or pieces/pieces.json
  // "" when the job may be nested; else the one-line reason it is held (no items.json): a half beyond
  // the quality gate, or a style that cannot be applied to this last
  std::string hold_reason;
  // A job whose pieces are of several materials: its parts in cutting order (daemon/job/job_parts.hpp),
  // each part's items in job_items_path(job_dir, material); empty for a job of one material.
  std::vector<JobPart> parts;
};

// Computes the molds of the scan into job_dir/molds/ and its nest items into job_dir/items.json:
// `quantity` copies of each half, labelled for the cutting room, with a mirrored twin per half
// when the ticket asks for a pair. The ticket's side left|right names a symmetric last's halves.
// Scan holes up to max_hole_across_mm are closed. A failure is one line in an operator's words.
// Molds beyond the quality gate's limits are written to molds/ (report and stretch pictures) but
// get no items.json, so they can never be nested; quality_hold says why.
Result<MoldsMade> compute_molds(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                                const JobTicket& ticket, const MoldOptions& mold_options, double max_hole_across_mm,
                                const MoldQualityLimits& quality);

// A job whose sidecar names a style (style = "NAME", a folder in paths.styles_dir): the style's pieces
// on the scanned last (engine/style) into job_dir/pieces/ (write_piece_outputs) and as nest items into
// job_dir/items.json (items_from_style: the ticket's quantity of shoes, the other foot mirrored when the
// ticket asks for a pair, the style's leather rules or the material's, labels with order, size, piece
// and foot); pieces of several configured materials go to one items file per part
// (save_job_items_by_material). A style that cannot be read or applied to this last is a hold (hold_reason), not a
// failure: the scan is good, and a requeue after the style is mended makes the pieces. A bad scan
// fails as in compute_molds.
Result<MoldsMade> compute_style_pieces(const std::filesystem::path& scan, const std::filesystem::path& job_dir,
                                       const JobTicket& ticket, const DaemonConfig& settings);

// A job that is a DXF-AAMA pattern set (a .dxf in the watch folder, engine/pattern): its pieces as
// nest items into job_dir/items.json (items_from_pattern: each piece's quantity x the ticket's, the
// other foot mirrored when the ticket asks for a pair, the material's leather rules). A file the
// reader refuses fails the job with the reader's line. A piece whose Category names a configured
// material is cut from it: pieces of several materials make a job of parts (save_job_items_by_material).
Result<MoldsMade> compute_pattern_items(const std::filesystem::path& pattern, const std::filesystem::path& job_dir,
                                        const JobTicket& ticket, const DaemonConfig& settings);

// True for a job whose input is a pattern set rather than a scan (.dxf).
bool is_pattern_set(const std::filesystem::path& input);

// The pieces a job's items ask for: every item's demand (quantity, and the other foot of a pair).
inline int pieces_to_cut(const std::vector<NestItem>& items) {
  int pieces = 0;
  for (const NestItem& item : items) pieces += item.demand;
  return pieces;
}

// The end of every job step: the items saved durably as job_dir/items.json (the only file that makes a
// job nestable) and counted into made.pieces_to_cut. `made_what` ("molds", "pieces") names them in the failure.
Result<MoldsMade> save_job_items(const std::filesystem::path& job_dir, const std::vector<NestItem>& items, MoldsMade made,
                                 const std::string& made_what);

// The same for the items of a style or pattern set job, whose pieces may be of several materials
// (item_materials[i]: the material item i is cut from, piece_material): one material, job_dir/items.json
// as save_job_items; several, one file per material (job_items_path) and made.parts (job_parts).
Result<MoldsMade> save_job_items_by_material(const std::filesystem::path& job_dir, const std::vector<NestItem>& items,
                                             const std::vector<std::string>& item_materials, const JobTicket& ticket,
                                             const DaemonConfig& settings, MoldsMade made, const std::string& made_what);

// Where a job's items for `material` are: items-<material>.json for a part of a job of several
// materials (the name's characters other than letters, digits, '-' and '_' as '_'), else items.json.
std::filesystem::path job_items_path(const std::filesystem::path& job_dir, const std::string& material);

// The items of a job's current part: the items file's, each with the part's copies when the part
// was split over hides (JobPart::copies; an item of 0 copies is left out). file_index[k] is items[k]'s
// place in the file, file_items the file's count. Throws EngineError when the file cannot be read or
// the copies do not match it.
struct PartItems {
  std::vector<NestItem> items;
  std::vector<int> file_index;
  int file_items = 0;
};
PartItems read_part_items(const std::filesystem::path& items_file, const std::vector<int>& copies,
                          const std::string& what);

// A job step into job_dir run so that nothing escapes it: an EngineError is its one line, running out
// of memory says `too_large`, anything else is unexpected_failure_reason. A stale items.json (from a
// computation before a requeue; a part's items-<material>.json too) goes first: only this computation's
// items may be nested.
// Removes items.json and every part's items file from job_dir (absent is the usual case; a file that
// cannot go fails the step's own write).
void remove_job_items(const std::filesystem::path& job_dir);

template <typename Step>
Result<MoldsMade> guarded_job_step(const std::filesystem::path& job_dir, Step&& step, const std::string& too_large) {
  try {
    remove_job_items(job_dir);
    return step();
  } catch (const EngineError& error) {
    return Status::failure(error.what());
  } catch (const std::bad_alloc&) {
    return Status::failure(too_large);
  } catch (const std::exception& error) {
    return Status::failure(unexpected_failure_reason(error));
  }
}

struct ReferenceCheck {
  nlohmann::json comparisons = nlohmann::json::object();  // mold name -> compare JSON (engine/compare/compare_report.hpp)
  std::string hold_reason;  // "" when every corner is within tolerance (or no reference is named)
};

// Compares each mold in job_dir/molds/ with the reference pattern the ticket names for it (the
// claim's copy in job_dir, reference_copy_name) and writes molds/compare-<mold>.json and .svg.
// The hold reason names the worst corner beyond corner_tolerance_mm. An unreadable pattern or a
// pattern for a mold the scan did not give is a failure of one line.
Result<ReferenceCheck> check_against_references(const std::filesystem::path& job_dir, const JobTicket& ticket,
                                                double corner_tolerance_mm);

struct BatchJobInput {
  std::string job_id;
  std::filesystem::path items_file;  // the job's items of this material (job_items_path)
  std::vector<int> copies;           // the current part's, when split over hides (JobPart::copies)
};

struct BatchMade {
  std::map<std::string, std::string> rejected;  // job id -> why its molds could not be placed
  std::string cut_file;                        // file name in batch_dir; empty when every job was rejected
  double utilisation = 0;                      // 0..1
  int piece_count = 0;                         // pieces placed
  nlohmann::json measures;                     // nesting and toolpath figures
};

// Nests the pieces of `jobs` on `material`, writes layout.json, preview.svg and the cut file
// for `cutter` into batch_dir. Fails as a whole only when no cut file can be made for any job
// (no machine profile, a file not written); a job whose pieces cannot be placed is rejected alone.
Result<BatchMade> build_batch(const std::vector<BatchJobInput>& jobs, const MaterialConfig& material,
                              const CutterSection& cutter, const std::filesystem::path& machines_dir,
                              double nest_time_s, const std::filesystem::path& batch_dir);

}  // namespace lastcut::daemon
