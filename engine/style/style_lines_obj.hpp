#pragma once
// Style lines as Wavefront OBJ polylines, the way a pattern maker exports lines drawn on a 3D last
// from CAD (Rhino, Blender, MeshLab write them): `v x y z` vertices (mm) and `l i j k ...` lines of
// 1-based vertex indices (negative: counted back from the last vertex, as the OBJ format allows);
// `o NAME` or `g NAME` names the lines that follow. Comments (#), blank lines and other records
// (vn, vt, usemtl, s) are skipped. Refused in one line naming the file and line: a face (`f`: a style
// holds lines, not a surface), a number that is not one, an index out of range, a line of fewer than
// two points, a file without lines, two lines of one name.
#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace lastcut {

struct StyleLine {
  std::string name;                         // from `o` / `g`; "line N" (1-based) when unnamed
  std::vector<Eigen::Vector3d> points_mm;   // >= 2, in the order of the `l` record
};

// Throws EngineError (one line) as above.
std::vector<StyleLine> read_style_lines_obj(const std::filesystem::path& path);

// Writes `o NAME`, the points as `v` and one `l` per line, durably. Throws EngineError when it cannot.
void write_style_lines_obj(const std::filesystem::path& path, const std::vector<StyleLine>& lines);

}  // namespace lastcut
