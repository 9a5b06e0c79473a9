// The end of every job step; see engine_steps.hpp, save_job_items.
#include "daemon/station/engine_steps.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/nest/nest_json.hpp"

namespace lastcut::daemon {

Result<MoldsMade> save_job_items(const std::filesystem::path& job_dir, const std::vector<NestItem>& items, MoldsMade made,
                                 const std::string& made_what) {
  made.pieces_to_cut = pieces_to_cut(items);
  if (Status written = write_file_durably(job_dir / kItemsFile, items_to_json(items).dump() + "\n"); !written)
    return written.with_context(made_what + " made but not saved: ");
  return made;
}

}  // namespace lastcut::daemon
