// Mold DXFs and DXF-AAMA pattern sets for `lastcut nest`; see nest_inputs.hpp.
#include "daemon/cli/nest_inputs.hpp"

#include <algorithm>

#include "engine/core/dxf_reader.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/pattern/aama_dxf.hpp"

namespace lastcut::cli {
namespace {

// A mold DXF's label says which half it is ("medial"); the folder `lastcut flatten` wrote it to says
// whose last it is ("m-42-left"). The cutting room needs both on the piece.
Mold read_labelled_mold(const std::filesystem::path& file) {
  Mold mold = read_mold_dxf(file);
  const std::string folder = std::filesystem::absolute(file).parent_path().filename().string();
  if (!folder.empty() && mold.name.find(folder) == std::string::npos)
    mold.name = mold.name.empty() ? folder : folder + " " + mold.name;
  return mold;
}

bool draws_on_layer(const DxfEntities& entities, const std::string& layer) {
  auto on = [&](const auto& list) {
    return std::any_of(list.begin(), list.end(), [&](const auto& entity) { return entity.layer == layer; });
  };
  return on(entities.polylines) || on(entities.lines) || on(entities.texts) || on(entities.points) ||
         on(entities.arcs) || on(entities.others);
}

void read_input_file(const std::filesystem::path& file, NestInputs& into) {
  if (is_pattern_set(file)) {
    const std::vector<PatternPiece> pieces = read_aama_dxf(file);
    into.pattern_pieces.insert(into.pattern_pieces.end(), pieces.begin(), pieces.end());
  } else {
    into.molds.push_back(read_labelled_mold(file));
  }
}

}  // namespace

bool is_pattern_set(const std::filesystem::path& path) {
  DxfDrawing drawing;
  try {
    drawing = read_dxf_drawing(path);
  } catch (const EngineError&) {
    return false;  // not readable as a drawing: the mold reader says why, as it always did
  }
  if (!drawing.inserts.empty()) return true;
  return std::any_of(drawing.blocks.begin(), drawing.blocks.end(),
                     [](const DxfBlock& block) { return draws_on_layer(block.entities, "1"); });
}

NestInputs read_nest_inputs(const std::vector<std::string>& inputs) {
  NestInputs read;
  for (const std::string& input : inputs) {
    const std::filesystem::path path(input);
    if (!std::filesystem::is_directory(path)) {
      read_input_file(path, read);
      continue;
    }
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(path))
      if (entry.path().extension() == ".dxf") files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    if (files.empty()) throw EngineError("folder " + input + " holds no mold DXF files");
    for (const auto& file : files) read_input_file(file, read);
  }
  return read;
}

}  // namespace lastcut::cli
