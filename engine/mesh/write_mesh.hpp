#pragma once
// Mesh writers: binary STL, Wavefront OBJ, binary little-endian PLY and OFF, chosen by extension.
// Coordinates are written as they are (mm). Throws EngineError when the file cannot be written
// or the extension is not one of .stl .obj .ply .off.
#include <filesystem>

#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// Binary STL: 80-byte header, uint32 count, then per triangle normal, 3 corners (float32) and a
// zero attribute word; the file is exactly 84 + 50 * #F bytes.
void write_stl_binary(const std::filesystem::path& path, const TriMesh& mesh);
// By extension (case-insensitive): .stl (binary), .obj, .ply (binary little endian), .off.
void write_mesh(const std::filesystem::path& path, const TriMesh& mesh);

}  // namespace lastcut
