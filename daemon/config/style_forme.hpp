#pragma once
// The step a style drawn on its forme (style.toml `forme = "forme.dxf"`) takes once the reference last
// is segmented: the drawing read by read_style_folder is lifted onto the reference (forme_layout.hpp,
// forme_lift.hpp), giving the style its 3D lines and each piece its label, as a style drawn in 3D
// (lines.obj) has them from the start. Kept apart from read_style_folder, which only reads files.
#include "daemon/config/style_folder.hpp"
#include "engine/core/status.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::daemon {

// reference: scan_to_molds of the folder's reference last (its side named). A folder with no forme is
// left as it is. Otherwise folder.style.lines are the lifted lines, each [[piece]] gets the label of its
// text, a text without a [[piece]] becomes a piece with the defaults (upper leather, 1 per shoe), and the
// drawing is dropped (it has been used). Fails in one line on what the lift refuses and on a [[piece]]
// without a text.
Status lift_forme_style(StyleFolder& folder, const ScanResult& reference);

}  // namespace lastcut::daemon
