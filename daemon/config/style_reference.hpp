#pragma once
// A style folder's reference last made ready for `lastcut pieces`, `lastcut style check` and the daemon's
// style jobs: through the
// scan-to-molds pipeline (a generated reference is made in a scratch folder of its own under the
// system's temp folder, since the style folder may be read-only: /etc/lastcut/styles), and the style's
// forme drawing, if it has one, lifted onto it (daemon/config/style_forme.hpp).
#include "daemon/config/style_folder.hpp"
#include "engine/scan/scan_to_molds.hpp"

namespace lastcut::daemon {

// Throws EngineError (one line) when the reference cannot be read or the drawing not lifted.
ScanResult prepare_style_reference(StyleFolder& folder);

}  // namespace lastcut::daemon
