#include "daemon/config/style_forme.hpp"

#include <algorithm>

#include "engine/core/engine_error.hpp"
#include "engine/style/forme_layout.hpp"
#include "engine/style/forme_lift.hpp"

namespace lastcut::daemon {

Status lift_forme_style(StyleFolder& folder, const ScanResult& reference) {
  if (!folder.forme) return Status::success();
  LiftedForme lifted;
  try {
    lifted = lift_forme_drawing(*folder.forme, forme_layout(reference), reference.scan_to_canonical);
  } catch (const EngineError& error) {
    return Status::failure(error.what());
  }
  StyleDefinition& style = folder.style;
  for (const StylePiece& piece : style.pieces)
    if (std::none_of(lifted.pieces.begin(), lifted.pieces.end(), [&](const StylePiece& text) { return text.name == piece.name; }))
      return Status::failure("piece " + piece.name + " of style.toml has no text on layer PIECES of " + folder.forme->source +
                             ": write its name inside it");
  for (const StylePiece& text : lifted.pieces) {
    const auto configured = std::find_if(style.pieces.begin(), style.pieces.end(), [&](const StylePiece& piece) { return piece.name == text.name; });
    if (configured != style.pieces.end())
      configured->label_mm = text.label_mm;
    else
      style.pieces.push_back(text);
  }
  style.lines = std::move(lifted.lines);
  folder.forme.reset();
  return Status::success();
}

}  // namespace lastcut::daemon
