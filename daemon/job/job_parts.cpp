// A job's parts, one per material; see job_parts.hpp.
#include "daemon/job/job_parts.hpp"

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
