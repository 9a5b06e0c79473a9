// The sidecar of a hide file (<stem>.toml): who the hide is and where it lies. See hide_file.hpp.
#include <set>

#include <toml++/toml.h>

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_file.hpp"

namespace lastcut {

void read_hide_sidecar(const std::filesystem::path& sidecar, HideFile& hide) {
  const std::string source = sidecar.string();
  toml::table table;
  try {
    table = toml::parse_file(source);
  } catch (const toml::parse_error& error) {
    throw EngineError(source + ": line " + std::to_string(error.source().begin.line) + ": " +
                      std::string(error.description()));
  }
  const std::set<std::string> known = {"id", "material", "cutter", "thickness_mm"};
  for (const auto& [key, node] : table) {
    if (!known.count(std::string(key.str())))
      throw EngineError(source + ": unknown key \"" + std::string(key.str()) +
                        "\" (known: id, material, cutter, thickness_mm)");
  }
  const auto text = [&](const char* key, std::string& into) {
    const toml::node* node = table.get(key);
    if (!node) return;
    const auto value = node->value<std::string>();
    if (!node->is_string() || !value || value->empty()) throw EngineError(source + ": " + key + " must be non-empty text");
    into = *value;
  };
  text("id", hide.hide_id);
  text("material", hide.material);
  text("cutter", hide.cutter);
  if (const toml::node* node = table.get("thickness_mm")) {
    const auto value = node->value<double>();
    if (!value || !(*value >= 0.2 && *value <= 20.0))
      throw EngineError(source + ": thickness_mm must be a number of mm within 0.2..20");
    hide.thickness_mm = *value;
  }
}

}  // namespace lastcut
