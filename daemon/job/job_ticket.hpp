#pragma once
// JobTicket: the optional sidecar next to a scan (NAME.job.toml or NAME.job.json) saying what
// the workshop wants cut from it. Keys (all optional): order, customer, size, side
// (left | right | pair), quantity, material, cutter, allowance_mm, priority, split (auto | expert),
// reference_medial, reference_lateral, reference_patch (reference pattern files, DXF or SVG, relative
// to the sidecar's folder; see docs/compare.md), and the per-edge allowances lasting_mm, seam_mm,
// top_mm and balance notch spacings seam_notch_spacing_mm, feather_notch_spacing_mm
// (docs/mold-allowances.md), style (a style folder's name under [paths] styles: the job's pieces are
// that style's, docs/pieces.md), split_over_hides (true: the job's pieces may be cut over several hides,
// docs/hides.md). Unknown keys are errors.
#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "engine/core/status.hpp"

namespace lastcut::daemon {

struct JobTicket {
  std::string order;     // the workshop's order number, shown in every log line
  std::string customer;
  std::string size;      // e.g. "EU 42"
  std::string side;      // "" (from the scan), left, right or pair
  int quantity = 1;      // how many of each mold
  std::string material;  // "" means the configured default
  std::string cutter;    // "" means the configured default
  std::optional<double> allowance_mm;  // all edges; not together with the per-edge keys
  std::optional<double> lasting_mm, seam_mm, top_mm;                        // per edge, 0..50
  std::optional<double> seam_notch_spacing_mm, feather_notch_spacing_mm;    // 0 = off, or 5..500
  int priority = 0;      // higher is cut first within a batch
  std::string split;     // lengthwise cut: "" or auto (thesis 3.1 plane), expert (heel middle to second toe)
  std::string style;     // "": the last's two molds; else the pieces of this style (a folder name, no path)
  // On hides the pieces of a job (and of its order's pair) are cut together or wait for the next hide
  // together; true lets a hide take those of them that fit and the rest wait for the next hide.
  bool split_over_hides = false;
  // Reference pattern per mold name (medial, lateral, patch) as written in the sidecar; the claim
  // copies each into the job folder as reference_copy_name(mold, file).
  std::map<std::string, std::string> references;
};

// The name of a reference pattern's copy in the job folder: "reference-<mold><extension>".
std::string reference_copy_name(const std::string& mold, const std::string& reference_file);

// The sidecar's ticket, or one line saying why it is unusable.
Result<JobTicket> read_job_ticket(const std::filesystem::path& sidecar);
// Sidecar of a scan: NAME.job.toml or NAME.job.json beside NAME.stl; empty path when none exists.
std::filesystem::path find_sidecar(const std::filesystem::path& scan);
// True for names that are sidecars (*.job.toml, *.job.json).
bool is_sidecar_name(const std::string& file_name);

nlohmann::json ticket_to_json(const JobTicket& ticket);
JobTicket ticket_from_json(const nlohmann::json& json);

}  // namespace lastcut::daemon
