// A job's parts, one per material; see job_parts.hpp.
#include "daemon/job/job_parts.hpp"

namespace lastcut::daemon {
namespace {

// "4 pieces of lining": how a part is named in every line about it.
std::string part_pieces(const JobPart& part) { return std::to_string(part.pieces) + " pieces of " + part.material; }

}  // namespace

nlohmann::json parts_to_json(const std::vector<JobPart>& parts) {
  nlohmann::json list = nlohmann::json::array();
  for (const JobPart& part : parts)
    list.push_back({{"material", part.material}, {"cutter", part.cutter}, {"pieces", part.pieces}});
  return list;
}

std::vector<JobPart> parts_from_json(const nlohmann::json& json) {
  std::vector<JobPart> parts;
  if (!json.is_array()) return parts;
  for (const nlohmann::json& entry : json) {
    if (!entry.is_object() || !entry.contains("material") || !entry.at("material").is_string()) continue;
    const auto cutter = entry.find("cutter");
    const auto pieces = entry.find("pieces");
    parts.push_back({entry.at("material").get<std::string>(),
                     cutter != entry.end() && cutter->is_string() ? cutter->get<std::string>() : "",
                     pieces != entry.end() && pieces->is_number_integer() ? pieces->get<int>() : 0});
  }
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
