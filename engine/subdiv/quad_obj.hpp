#pragma once
// Quad meshes as Wavefront OBJ: "v x y z" (mm) and "f a b c d" (1-based, "a/t/n" and negative
// indices accepted). Other records (vt, vn, g, o, s, usemtl, comments) are skipped.
#include <filesystem>

#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

// Throws EngineError with one line: unreadable file, a face that is not a quad, a bad number or
// index, no quads. Manifoldness is checked by build_quad_topology.
QuadMesh read_quad_obj(const std::filesystem::path& path);

// Positions with 6 decimals (1 nm), faces 1-based. Throws EngineError when the file cannot be written.
void write_quad_obj(const std::filesystem::path& path, const QuadMesh& mesh);

}  // namespace lastcut
