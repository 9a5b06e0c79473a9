#pragma once
// The label of one mold piece in a batch: what the pen writes on the leather (after the cutting
// order number), what the layout and the preview show. A nested batch mixes the pieces of several
// customers; the cutter operator sorts them by this text, so it names the order, the size, the foot
// and the half: "#4711 EU44 L med", "#mueller-anna R lat". The leading '#' marks it as ready to draw
// (engine/toolpath/piece_label.hpp writes such labels verbatim). Short, because a pen draws it.
#include <string>

namespace lastcut::daemon {

struct PieceLabelParts {
  std::string order;      // the sidecar's order number; "" when none
  std::string scan_name;  // file name of the scan ("mueller-anna.stl"): its stem names a job without an order
  std::string size;       // the sidecar's size ("EU 44"), "" when none
  std::string foot;       // "left", "right", or "" when unknown
  std::string part;       // the mold's name: "medial", "lateral" (others are kept as they are)
};

// At most kMaxReferenceChars of the order/stem are kept; spaces become '-'.
inline constexpr std::size_t kMaxReferenceChars = 12;
std::string piece_label_text(const PieceLabelParts& parts);

// The other foot ("left" <-> "right"; "" stays ""), for the mirrored piece of a pair.
std::string opposite_foot(const std::string& foot);

}  // namespace lastcut::daemon
