// The sidecar reader: TOML and JSON sidecars are turned into the same JSON object and checked
// once, so both formats accept exactly the same keys.
#include "daemon/job/job_ticket.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <fstream>
#include <set>
#include <sstream>

#include <toml++/toml.h>

namespace lastcut::daemon {
namespace {

bool ends_with(const std::string& text, const std::string& suffix) {
  return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::optional<nlohmann::json> toml_to_json(const std::filesystem::path& file, std::string& error) {
  try {
    const toml::table table = toml::parse_file(file.string());
    std::ostringstream text;
    text << toml::json_formatter{table};
    return nlohmann::json::parse(text.str());
  } catch (const toml::parse_error& parse_error) {
    std::ostringstream out;
    out << "line " << parse_error.source().begin.line << ": " << parse_error.description();
    error = out.str();
  } catch (const nlohmann::json::exception& json_error) {
    error = json_error.what();
  }
  return std::nullopt;
}

// The per-edge allowances and balance notch spacings (docs/mold-allowances.md).
Status check_mold_keys(const nlohmann::json& json, JobTicket& ticket) {
  for (auto [key, target] : {std::pair{"lasting_mm", &ticket.lasting_mm}, std::pair{"seam_mm", &ticket.seam_mm},
                             std::pair{"top_mm", &ticket.top_mm}}) {
    if (!json.contains(key)) continue;
    const auto& node = json.at(key);
    if (!node.is_number() || !(node.get<double>() >= 0) || node.get<double>() > 50)
      return Status::failure(std::string(key) + " must be a number from 0 to 50");
    *target = node.get<double>();
  }
  if (ticket.allowance_mm && (ticket.lasting_mm || ticket.seam_mm || ticket.top_mm))
    return Status::failure("allowance_mm (all edges) and lasting_mm/seam_mm/top_mm cannot be given together");
  for (auto [key, target] : {std::pair{"seam_notch_spacing_mm", &ticket.seam_notch_spacing_mm},
                             std::pair{"feather_notch_spacing_mm", &ticket.feather_notch_spacing_mm}}) {
    if (!json.contains(key)) continue;
    const auto& node = json.at(key);
    if (!node.is_number() || !(node.get<double>() == 0 || (node.get<double>() >= 5 && node.get<double>() <= 500)))
      return Status::failure(std::string(key) + " must be 0 (off) or a number from 5 to 500");
    *target = node.get<double>();
  }
  return Status::success();
}

// A folder name under [paths] styles: nothing that could reach outside it.
bool is_style_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || name[0] == '.') return false;
  return std::all_of(name.begin(), name.end(), [](unsigned char c) { return std::isalnum(c) || c == '-' || c == '_' || c == '.'; });
}

Result<JobTicket> check_ticket(const nlohmann::json& json) {
  JobTicket ticket;
  if (!json.is_object()) return Status::failure("the sidecar must be a table of keys");
  const std::set<std::string> known{"order", "customer", "size", "side", "quantity", "material",
                                    "cutter", "allowance_mm", "priority", "split", "reference_medial",
                                    "reference_lateral", "reference_patch", "lasting_mm", "seam_mm", "top_mm",
                                    "seam_notch_spacing_mm", "feather_notch_spacing_mm", "style",
                                    "split_over_hides"};
  for (auto it = json.begin(); it != json.end(); ++it) {
    if (!known.count(it.key())) return Status::failure("unknown key \"" + it.key() + "\"");
  }
  auto text = [&](const char* key, std::string& value) -> std::string {
    if (!json.contains(key)) return {};
    const auto& node = json.at(key);
    if (node.is_string()) value = node.get<std::string>();
    else if (node.is_number_integer()) value = std::to_string(node.get<long long>());
    else return std::string(key) + " must be a text";
    return {};
  };
  for (auto [key, target] : {std::pair{"order", &ticket.order}, std::pair{"customer", &ticket.customer},
                             std::pair{"size", &ticket.size}, std::pair{"side", &ticket.side},
                             std::pair{"material", &ticket.material}, std::pair{"cutter", &ticket.cutter},
                             std::pair{"split", &ticket.split}, std::pair{"style", &ticket.style}}) {
    if (std::string error = text(key, *target); !error.empty()) return Status::failure(error);
  }
  if (!ticket.side.empty() && ticket.side != "left" && ticket.side != "right" && ticket.side != "pair") {
    return Status::failure("side \"" + ticket.side + "\" is not one of left, right, pair");
  }
  if (!ticket.split.empty() && ticket.split != "auto" && ticket.split != "expert") {
    return Status::failure("split \"" + ticket.split + "\" is not one of auto, expert");
  }
  if (!ticket.style.empty() && !is_style_name(ticket.style)) {
    return Status::failure("style \"" + ticket.style + "\" is not a style's folder name (letters, digits, '-', '_', '.'; no path)");
  }
  if (json.contains("quantity")) {
    const auto& node = json.at("quantity");
    if (!node.is_number_integer() || node.get<long long>() < 1 || node.get<long long>() > 100) {
      return Status::failure("quantity must be a whole number from 1 to 100");
    }
    ticket.quantity = node.get<int>();
  }
  if (json.contains("priority")) {
    const auto& node = json.at("priority");
    if (!node.is_number_integer()) return Status::failure("priority must be a whole number");
    ticket.priority = node.get<int>();
  }
  if (json.contains("split_over_hides")) {
    const auto& node = json.at("split_over_hides");
    if (!node.is_boolean()) return Status::failure("split_over_hides must be true or false");
    ticket.split_over_hides = node.get<bool>();
  }
  for (const char* mold : {"medial", "lateral", "patch"}) {
    const std::string key = std::string("reference_") + mold;
    if (!json.contains(key)) continue;
    const auto& node = json.at(key);
    if (!node.is_string() || node.get<std::string>().empty()) return Status::failure(key + " must be a file name");
    ticket.references[mold] = node.get<std::string>();
  }
  if (json.contains("allowance_mm")) {
    const auto& node = json.at("allowance_mm");
    if (!node.is_number() || node.get<double>() < 0 || node.get<double>() > 50) {
      return Status::failure("allowance_mm must be a number from 0 to 50");
    }
    ticket.allowance_mm = node.get<double>();
  }
  if (Status per_edge = check_mold_keys(json, ticket); !per_edge) return per_edge;
  return ticket;
}

template <typename Ticket>
auto mold_keys(Ticket& ticket) {
  return std::array{std::pair{"lasting_mm", &ticket.lasting_mm}, std::pair{"seam_mm", &ticket.seam_mm},
                    std::pair{"top_mm", &ticket.top_mm}, std::pair{"seam_notch_spacing_mm", &ticket.seam_notch_spacing_mm},
                    std::pair{"feather_notch_spacing_mm", &ticket.feather_notch_spacing_mm}};
}

}  // namespace

bool is_sidecar_name(const std::string& file_name) {
  return ends_with(file_name, ".job.toml") || ends_with(file_name, ".job.json");
}

std::filesystem::path find_sidecar(const std::filesystem::path& scan) {
  for (const char* suffix : {".job.toml", ".job.json"}) {
    std::filesystem::path candidate = scan.parent_path() / (scan.stem().string() + suffix);
    std::error_code error;
    if (std::filesystem::is_regular_file(std::filesystem::symlink_status(candidate, error))) return candidate;
  }
  return {};
}

Result<JobTicket> read_job_ticket(const std::filesystem::path& sidecar) {
  std::optional<nlohmann::json> json;
  std::string error;
  if (ends_with(sidecar.filename().string(), ".toml")) {
    json = toml_to_json(sidecar, error);
  } else {
    std::ifstream in(sidecar);
    if (!in) {
      error = "cannot be read";
    } else {
      json = nlohmann::json::parse(in, nullptr, false);
      if (json->is_discarded()) {
        json.reset();
        error = "is not valid JSON";
      }
    }
  }
  const std::string context = "sidecar " + sidecar.filename().string() + ": ";
  if (!json) return Status::failure(context + error);
  Result<JobTicket> ticket = check_ticket(*json);
  if (!ticket) return ticket.status().with_context(context);
  return ticket;
}

nlohmann::json ticket_to_json(const JobTicket& ticket) {
  nlohmann::json json{{"order", ticket.order},       {"customer", ticket.customer}, {"size", ticket.size},
                      {"side", ticket.side},         {"quantity", ticket.quantity}, {"material", ticket.material},
                      {"cutter", ticket.cutter},     {"priority", ticket.priority}};
  if (ticket.allowance_mm) json["allowance_mm"] = *ticket.allowance_mm;
  if (!ticket.split.empty()) json["split"] = ticket.split;
  if (!ticket.style.empty()) json["style"] = ticket.style;
  if (ticket.split_over_hides) json["split_over_hides"] = true;
  for (const auto& [mold, file] : ticket.references) json["reference_" + mold] = file;
  for (auto [key, value] : mold_keys(ticket))
    if (*value) json[key] = **value;
  return json;
}

JobTicket ticket_from_json(const nlohmann::json& json) {
  JobTicket ticket;
  ticket.order = json.value("order", "");
  ticket.customer = json.value("customer", "");
  ticket.size = json.value("size", "");
  ticket.side = json.value("side", "");
  ticket.quantity = json.value("quantity", 1);
  ticket.material = json.value("material", "");
  ticket.cutter = json.value("cutter", "");
  ticket.priority = json.value("priority", 0);
  ticket.split = json.value("split", "");
  ticket.style = json.value("style", "");
  ticket.split_over_hides = json.value("split_over_hides", false);
  if (json.contains("allowance_mm")) ticket.allowance_mm = json.at("allowance_mm").get<double>();
  for (const char* mold : {"medial", "lateral", "patch"})
    if (json.contains(std::string("reference_") + mold))
      ticket.references[mold] = json.at(std::string("reference_") + mold).get<std::string>();
  for (auto [key, value] : mold_keys(ticket))
    if (json.contains(key)) *value = json.at(key).get<double>();
  return ticket;
}

std::string reference_copy_name(const std::string& mold, const std::string& reference_file) {
  return "reference-" + mold + std::filesystem::path(reference_file).extension().string();
}

}  // namespace lastcut::daemon
