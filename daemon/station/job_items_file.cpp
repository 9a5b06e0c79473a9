// The end of every job step, the items' files of a job and of its parts; see engine_steps.hpp
// (save_job_items, save_job_items_by_material, job_items_path).
#include <map>

#include "daemon/station/engine_steps.hpp"
#include "daemon/station/job_piece_rules.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::daemon {
namespace {

constexpr const char* kPartItemsPrefix = "items-";

std::string part_items_name(const std::string& material) {
  std::string name = kPartItemsPrefix;
  for (const char c : material) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_';
    name += plain ? c : '_';
  }
  return name + ".json";
}

Status write_items(const std::filesystem::path& file, const std::vector<NestItem>& items) {
  return write_file_durably(file, items_to_json(items).dump() + "\n");
}

}  // namespace

Result<MoldsMade> save_job_items(const std::filesystem::path& job_dir, const std::vector<NestItem>& items, MoldsMade made,
                                 const std::string& made_what) {
  made.pieces_to_cut = pieces_to_cut(items);
  if (Status written = write_items(job_dir / kItemsFile, items); !written)
    return written.with_context(made_what + " made but not saved: ");
  return made;
}

Result<MoldsMade> save_job_items_by_material(const std::filesystem::path& job_dir, const std::vector<NestItem>& items,
                                             const std::vector<std::string>& item_materials, const JobTicket& ticket,
                                             const DaemonConfig& settings, MoldsMade made, const std::string& made_what) {
  std::vector<int> demands;
  for (const NestItem& item : items) demands.push_back(item.demand);
  made.parts = job_parts(item_materials, demands, ticket, settings);
  if (made.parts.empty()) return save_job_items(job_dir, items, made, made_what);
  std::map<std::string, std::vector<NestItem>> items_of;
  for (std::size_t i = 0; i < items.size(); ++i) items_of[item_materials.at(i)].push_back(items[i]);
  made.pieces_to_cut = pieces_to_cut(items);
  for (const JobPart& part : made.parts) {
    if (Status written = write_items(job_dir / part_items_name(part.material), items_of[part.material]); !written)
      return written.with_context(made_what + " of " + part.material + " made but not saved: ");
  }
  return made;
}

std::filesystem::path job_items_path(const std::filesystem::path& job_dir, const std::string& material) {
  std::error_code unreadable;  // as good as absent: the job's items.json is read, and its reader says why not
  const auto part = job_dir / part_items_name(material);
  return std::filesystem::exists(part, unreadable) ? part : job_dir / kItemsFile;
}

PartItems read_part_items(const std::filesystem::path& items_file, const std::vector<int>& copies,
                          const std::string& what) {
  std::vector<NestItem> file_items = items_from_json(read_json_file(items_file), what);
  PartItems part;
  part.file_items = static_cast<int>(file_items.size());
  if (!copies.empty() && copies.size() != file_items.size()) {
    throw EngineError(what + ": the part names " + std::to_string(copies.size()) + " pieces, the file holds " +
                      std::to_string(file_items.size()));
  }
  for (std::size_t i = 0; i < file_items.size(); ++i) {
    if (!copies.empty()) {
      if (copies[i] < 0 || copies[i] > file_items[i].demand)
        throw EngineError(what + ": the part cuts " + std::to_string(copies[i]) + " copies of a piece the file has " +
                          std::to_string(file_items[i].demand) + " of");
      if (copies[i] == 0) continue;
      file_items[i].demand = copies[i];
    }
    part.items.push_back(std::move(file_items[i]));
    part.file_index.push_back(static_cast<int>(i));
  }
  if (part.items.empty()) throw EngineError(what + ": the part has no pieces left to cut");
  return part;
}

void remove_job_items(const std::filesystem::path& job_dir) {
  std::error_code ignored;
  std::filesystem::remove(job_dir / kItemsFile, ignored);
  std::vector<std::filesystem::path> parts;
  for (std::filesystem::directory_iterator it(job_dir, ignored), end; !ignored && it != end; it.increment(ignored)) {
    const std::string name = it->path().filename().string();
    if (name.rfind(kPartItemsPrefix, 0) == 0 && it->path().extension() == ".json") parts.push_back(it->path());
  }
  for (const auto& part : parts) std::filesystem::remove(part, ignored);
}

}  // namespace lastcut::daemon
