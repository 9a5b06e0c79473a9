// A job's parts, one per material; see job_parts.hpp.
#include "daemon/job/job_parts.hpp"

#include <algorithm>

namespace lastcut::daemon {
namespace {

std::string part_pieces(const JobPart& part) { return pieces_of(part.pieces, part.material); }

}  // namespace

nlohmann::json parts_to_json(const std::vector<JobPart>& parts) {
  nlohmann::json list = nlohmann::json::array();
  for (const JobPart& part : parts) {
    nlohmann::json entry{{"material", part.material}, {"cutter", part.cutter}, {"pieces", part.pieces}};
    if (!part.copies.empty()) entry["copies"] = part.copies;
    list.push_back(std::move(entry));
  }
  return list;
}

std::vector<JobPart> parts_from_json(const nlohmann::json& json) {
  std::vector<JobPart> parts;
  if (!json.is_array()) return parts;
  for (const nlohmann::json& entry : json) {
    if (!entry.is_object() || !entry.contains("material") || !entry.at("material").is_string()) continue;
    const auto cutter = entry.find("cutter");
    const auto pieces = entry.find("pieces");
    JobPart part{entry.at("material").get<std::string>(),
                 cutter != entry.end() && cutter->is_string() ? cutter->get<std::string>() : "",
                 pieces != entry.end() && pieces->is_number_integer() ? pieces->get<int>() : 0,
                 {}};
    if (const auto copies = entry.find("copies"); copies != entry.end() && copies->is_array()) {
      for (const nlohmann::json& count : *copies) part.copies.push_back(count.is_number_integer() ? count.get<int>() : 0);
    }
    parts.push_back(std::move(part));
  }
  return parts;
}

std::string pieces_of(int pieces, const std::string& material) {
  return std::to_string(pieces) + (pieces == 1 ? " piece of " : " pieces of ") + material;
}

int count_copies(const std::vector<int>& copies) {
  int total = 0;
  for (const int count : copies) total += count;
  return total;
}

std::vector<int> part_copies(const std::vector<JobPart>& parts, int current) {
  if (current < 0 || current >= static_cast<int>(parts.size())) return {};
  return parts[static_cast<std::size_t>(current)].copies;
}

std::string describe_split(const PartSplit& split, const std::string& material, const std::string& hide) {
  const int placed = count_copies(split.placed), rest = count_copies(split.rest);
  return std::to_string(placed) + " of " + std::to_string(placed + rest) + " pieces of " + material + " on hide " +
         hide + "; " + std::to_string(rest) + " wait for the next hide";
}

std::vector<JobPart> split_part(std::vector<JobPart> parts, int current, const JobPart& whole, const PartSplit& split) {
  if (parts.empty()) {
    parts.push_back(whole);
    current = 0;
  }
  JobPart& placed = parts.at(static_cast<std::size_t>(current));
  JobPart rest = placed;
  placed.copies = split.placed, placed.pieces = count_copies(split.placed);
  rest.copies = split.rest, rest.pieces = count_copies(split.rest);
  parts.insert(parts.begin() + current + 1, std::move(rest));
  return parts;
}

namespace {

bool same_target(const JobPart& a, const JobPart& b) { return a.material == b.material && a.cutter == b.cutter; }

// The stored parts of `target`'s material and cutter from index `from` on, as one part: their pieces
// and copies summed. Empty copies when they are one part not split. False when their copies do not add up.
bool merge_parts(const std::vector<JobPart>& stored, std::size_t from, const JobPart& target, JobPart& merged) {
  merged = JobPart{target.material, target.cutter, 0, {}};
  int merged_parts = 0;
  for (std::size_t i = from; i < stored.size(); ++i) {
    const JobPart& part = stored[i];
    if (!same_target(part, target)) continue;
    if (merged_parts++ == 0) {
      merged.copies = part.copies;
    } else {
      if (part.copies.size() != merged.copies.size() || part.copies.empty()) return false;
      for (std::size_t item = 0; item < part.copies.size(); ++item) merged.copies[item] += part.copies[item];
    }
    merged.pieces += part.pieces;
  }
  return true;
}

}  // namespace

ResumedParts resume_parts(const std::vector<JobPart>& stored, int stored_part, const std::vector<JobPart>& computed,
                          const JobPart& whole) {
  const ResumedParts from_start{computed, 0};
  if (stored.empty() || stored_part < 0 || stored_part >= static_cast<int>(stored.size())) return from_start;
  const std::vector<JobPart> wanted = computed.empty() ? std::vector<JobPart>{whole} : computed;
  const auto cut_end = static_cast<std::size_t>(stored_part);
  // Every stored part must be of a computed material, and each material's stored pieces must be its
  // computed pieces: then the stored parts are the computed ones split, and the cut ones can be trusted.
  for (const JobPart& part : stored) {
    if (std::none_of(wanted.begin(), wanted.end(), [&](const JobPart& target) { return same_target(part, target); })) {
      return from_start;
    }
  }
  ResumedParts resumed{{stored.begin(), stored.begin() + stored_part}, stored_part};
  for (const JobPart& target : wanted) {
    JobPart all, not_cut;
    if (!merge_parts(stored, 0, target, all) || all.pieces != target.pieces) return from_start;
    if (!merge_parts(stored, cut_end, target, not_cut)) return from_start;
    if (not_cut.pieces == 0) continue;                            // this material is cut
    resumed.parts.push_back(not_cut.pieces == target.pieces ? target : not_cut);  // none of it cut: as computed
  }
  if (computed.empty() && resumed.parts.size() == 1 && resumed.part == 0) return from_start;  // one material, nothing cut
  if (resumed.part >= static_cast<int>(resumed.parts.size())) return from_start;  // every part cut: cut again
  return resumed;
}

std::string describe_resumed(const ResumedParts& resumed) {
  if (resumed.part <= 0 || resumed.part >= static_cast<int>(resumed.parts.size())) return "";
  return "goes on with part " + std::to_string(resumed.part + 1) + " of " + std::to_string(resumed.parts.size()) + ": " +
         part_pieces(resumed.parts[static_cast<std::size_t>(resumed.part)]) + " (the parts before it are cut)";
}

std::string describe_parts(const std::vector<JobPart>& parts) {
  std::string text;
  for (const JobPart& part : parts) {
    if (!text.empty()) text += ", then ";
    text += part_pieces(part) + " on " + part.cutter;
  }
  return text;
}

std::string parts_progress(const std::vector<JobPart>& parts, int current, bool all_cut) {
  std::string text;
  for (int i = 0; i < static_cast<int>(parts.size()); ++i) {
    const char* where = all_cut || i < current ? "cut" : i == current ? "now" : "next";
    if (!text.empty()) text += "; ";
    text += part_pieces(parts[static_cast<std::size_t>(i)]) + " " + where;
  }
  return text;
}

}  // namespace lastcut::daemon
