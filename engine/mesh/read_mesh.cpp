#include "engine/mesh/read_mesh.hpp"

#include <OpenMesh/Core/IO/IOManager.hh>
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/mesh_file_checks.hpp"
#include "engine/mesh/mesh_orientation.hpp"
#include "engine/mesh/mesh_repair.hpp"
#include "engine/mesh/mesh_units.hpp"
#include "engine/mesh/soup_importer.hpp"

namespace lastcut {
namespace {

SoupImporter parse(const std::filesystem::path& path, const MeshFileFacts& facts) {
  SoupImporter soup;
  OpenMesh::IO::Options options;
  if (facts.format == MeshFileFormat::BinaryStl) options += OpenMesh::IO::Options::Binary;
  if (!OpenMesh::IO::IOManager().read(path.string(), soup, options))
    throw EngineError("unreadable " + facts.format_name + " file " + path.filename().string());
  return soup;
}

TriMesh to_trimesh(const SoupImporter& soup, const std::filesystem::path& path) {
  TriMesh mesh;
  mesh.V.resize(static_cast<Eigen::Index>(soup.points.size()), 3);
  for (size_t v = 0; v < soup.points.size(); ++v)
    for (int c = 0; c < 3; ++c) {
      const double value = soup.points[v][static_cast<size_t>(c)];
      if (!std::isfinite(value))
        throw EngineError("coordinates that are not numbers (NaN or infinite) at vertex " + std::to_string(v + 1) + " of " +
                          path.filename().string());
      mesh.V(static_cast<Eigen::Index>(v), c) = value;
    }
  mesh.F.resize(static_cast<Eigen::Index>(soup.triangles.size()), 3);
  for (size_t f = 0; f < soup.triangles.size(); ++f)
    for (int c = 0; c < 3; ++c) mesh.F(static_cast<Eigen::Index>(f), c) = soup.triangles[f][static_cast<size_t>(c)];
  return mesh;
}

}  // namespace

MeshIntake read_mesh(const std::filesystem::path& path, const MeshReadOptions& options) {
  SoupImporter soup;
  const MeshFileFacts facts = inspect_mesh_file(path, options.max_triangles, &soup);
  if (!facts.records_read) soup = parse(path, facts);
  if (soup.triangles.empty()) throw EngineError("no triangles in " + path.filename().string());
  if (static_cast<long long>(soup.triangles.size()) > options.max_triangles)
    throw EngineError("too many triangles in " + path.filename().string() + ": " + std::to_string(soup.triangles.size()) +
                      " (limit " + std::to_string(options.max_triangles) + ")");

  MeshIntake intake;
  IntakeReport& report = intake.report;
  report.format = facts.format_name;
  // OpenMesh's STL and OBJ parsers skip faces with a repeated corner without a word: count them
  // as degenerate faces, the file held them.
  const long long parser_dropped = std::max(0LL, facts.declared_faces - static_cast<long long>(soup.face_records));
  report.triangles_read = static_cast<int>(soup.triangles.size() + parser_dropped);
  if (soup.polygons_fanned > 0) report.notes.push_back(std::to_string(soup.polygons_fanned) + " polygons split into triangles");
  if (soup.faces_with_bad_indices > 0)
    report.notes.push_back(std::to_string(soup.faces_with_bad_indices) + " faces with invalid vertex numbers skipped");

  TriMesh& mesh = intake.mesh;
  mesh = to_trimesh(soup, path);
  const UnitChoice unit = choose_length_unit(bounding_box_size(mesh), options.unit);
  mesh.V *= unit.scale_to_mm;
  report.unit_note = unit.note;

  report.duplicate_vertices_merged = merge_duplicate_vertices(mesh);
  report.degenerate_faces_removed = static_cast<int>(parser_dropped) + remove_degenerate_faces(mesh);
  report.duplicate_faces_removed = remove_duplicate_faces(mesh);
  const Eigen::Index faces_before = mesh.F.rows();
  MeshTopology& topology = intake.topology;
  report.non_manifold_faces_removed = remove_non_manifold_faces(mesh, topology);
  // A few bad spots are repaired; a file that is mostly bad spots is not a scan of a solid.
  if (report.non_manifold_faces_removed > 0.2 * static_cast<double>(faces_before))
    throw EngineError("non-manifold mess in " + path.filename().string() + ": " +
                      std::to_string(report.non_manifold_faces_removed) + " of " + std::to_string(faces_before) +
                      " faces sit on edges or corners shared by too many faces");
  if (mesh.F.rows() == 0) throw EngineError("nothing usable left in " + path.filename().string() + " after repair");
  keep_largest_component(mesh, topology, options.min_component_fraction, report);
  report.faces_flipped = orient_outward(mesh, topology, report);
  report.boundary_loops = count_boundary_loops(topology);
  if (report.boundary_loops > 0) report.notes.push_back(std::to_string(report.boundary_loops) + " holes left open");
  return intake;
}

}  // namespace lastcut
