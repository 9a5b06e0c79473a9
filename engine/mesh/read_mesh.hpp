#pragma once
// Mesh intake: reads a scan (STL ASCII/binary, OBJ, PLY through OpenMesh's parsers; ASCII OFF in
// the pass that checks it, mesh_file_checks.hpp), finds
// its length unit, repairs what scans contain (duplicate vertices, degenerate and duplicate
// faces, flipped faces, non-manifold spots, loose scanner debris) and refuses, with one line an
// operator can act on, what cannot be a usable scan (empty, truncated, NaN, too large, several
// big pieces, unknown format). check_is_last then refuses meshes that are no shoe last at all.
//
//   lastcut::MeshIntake intake = lastcut::read_mesh("scan.stl");   // throws EngineError
//   lastcut::check_is_last(intake.mesh);                           // throws EngineError
#include <filesystem>
#include <string>
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"
#include "engine/mesh/write_mesh.hpp"

namespace lastcut {

enum class LengthUnit { Auto, Millimetre, Centimetre, Metre, Inch };

struct MeshReadOptions {
  LengthUnit unit = LengthUnit::Auto;     // Auto: metres when the box is under 2 units (see mesh_units.hpp)
  int max_triangles = 2'000'000;          // refuse larger files before loading them
  double min_component_fraction = 0.01;   // pieces under this fraction of the main area are scanner debris
};

struct IntakeReport {
  std::string format;                     // "binary STL", "ASCII STL", "OBJ", "PLY", "OFF"
  std::string unit_note;                  // e.g. "metres (box 0.27 x 0.10 x 0.14), scaled to mm"
  int triangles_read = 0;
  int duplicate_vertices_merged = 0;
  int degenerate_faces_removed = 0;
  int duplicate_faces_removed = 0;
  int faces_flipped = 0;
  int non_manifold_faces_removed = 0;
  int loose_components_removed = 0;
  int boundary_loops = 0;                 // holes left open (tolerated)
  std::vector<std::string> notes;         // anything else worth telling the operator
};

struct MeshIntake {
  TriMesh mesh;  // mm, one connected 2-manifold piece, outward-oriented
  MeshTopology topology;  // of mesh (the repair builds it; callers need not build it again)
  IntakeReport report;
};

// Throws EngineError: empty, truncated, NaN/inf, too many triangles, unknown format, unreadable,
// several disconnected pieces.
MeshIntake read_mesh(const std::filesystem::path& path, const MeshReadOptions& options = {});

// Throws EngineError("not a shoe last: ...") for a flat plate, an absurd size (< 100 mm or
// > 500 mm long) or too few triangles to describe a last.
void check_is_last(const TriMesh& mesh);

}  // namespace lastcut
