#pragma once
// What a mesh file is, checked before any parser sees it: OpenMesh's readers accept truncated
// and oversized files silently (a short binary STL is read as ASCII garbage, a cut ASCII STL
// gives the facets before the cut). Here: existence, emptiness, format by extension, binary STL
// size = 84 + 50 n, ASCII STL complete (every facet closed, endsolid present), PLY and ASCII OFF
// holding every vertex and face record their header declares (ply_records.hpp), and the triangle
// count against the cap from the header where the format declares it (STL, PLY, OFF) or a
// line count (OBJ). Each failure is one EngineError line naming the file.
//
// An ASCII OFF is read in the same pass: its check converts every record anyway, so the checked
// records are the mesh (`records`), with no second parse by OpenMesh. Vertex values are read as
// float, as OpenMesh's OFF reader reads them, so the mesh is the one OpenMesh would give.
#include <filesystem>
#include <string>

#include "engine/mesh/soup_importer.hpp"

namespace lastcut {

enum class MeshFileFormat { BinaryStl, AsciiStl, Obj, Ply, Off };

struct MeshFileFacts {
  MeshFileFormat format = MeshFileFormat::BinaryStl;
  std::string format_name;         // "binary STL", "ASCII STL", "OBJ", "PLY", "OFF"
  long long declared_faces = -1;   // from the header or a count of face records; -1 unknown
  long long declared_vertices = -1;
  bool records_read = false;       // the check filled `records` (ASCII OFF): no parser needed
};

// records: where a format whose check reads every record (ASCII OFF) puts the mesh; may be null.
MeshFileFacts inspect_mesh_file(const std::filesystem::path& path, int max_triangles,
                                SoupImporter* records = nullptr);

}  // namespace lastcut
