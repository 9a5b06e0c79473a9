#include "engine/lastgen/last_side_mesh.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "engine/core/engine_error.hpp"
#include "engine/lastgen/control_fit.hpp"
#include "engine/lastgen/control_relaxation.hpp"
#include "engine/lastgen/cube_sphere.hpp"

namespace lastcut {
namespace {

constexpr int kRelaxationSteps = 60;
constexpr double kGroundBandMm = 0.5;    // samples whose foot point is this close to the ground
constexpr double kGroundWeight = 100.0;  // count this many times
constexpr double kRimSearchStepMm = 1.0;

Eigen::Vector3d into_plane(const Eigen::Vector3d& p, const Eigen::Vector3d& point, const Eigen::Vector3d& normal) {
  return p - (p - point).dot(normal) * normal;
}

}  // namespace

Eigen::Vector3d rim_point(const LastShape& shape, const Eigen::Vector3d& cap_centre, const Eigen::Vector3d& normal,
                          const Eigen::Vector3d& p) {
  Eigen::Vector3d direction = p - cap_centre;
  direction -= direction.dot(normal) * normal;
  if (direction.norm() < 1e-9) throw EngineError("last side mesh: a rim point at the centre of the top cut");
  direction.normalize();
  double inside = 0.0, outside = kRimSearchStepMm;
  while (shape.body_value(cap_centre + outside * direction) <= 0.0) {
    inside = outside;
    outside += kRimSearchStepMm;
    if (outside > 1000.0) throw EngineError("last side mesh: the top cut has no rim");
  }
  for (int iteration = 0; iteration < 48; ++iteration) {
    const double middle = 0.5 * (inside + outside);
    (shape.body_value(cap_centre + middle * direction) > 0.0 ? outside : inside) = middle;
  }
  return cap_centre + 0.5 * (inside + outside) * direction;
}

LastSideMesh last_side_mesh(const LastShape& shape, const LastParams& params, const std::array<int, 3>& cells) {
  const CubeSphere sphere = cast_along_spine(shape, params, cells);

  LastSideMesh side;
  side.cut_normal = shape.top_cut_normal();
  side.cut_point_mm = Eigen::Vector3d(0.0, 0.0, shape.top_cut_z_mm(0.0));
  const auto on_flat = [&](const Eigen::Vector3d& p) {
    return std::abs((p - side.cut_point_mm).dot(side.cut_normal)) < 0.05 && shape.body_value(p) < -3.0;
  };

  // The cap: the bounding rectangle of the top face's cells that lie on the flat of the cut.
  const int top_axis = 2;
  int i0 = cells[0], i1 = -1, j0 = cells[1], j1 = -1;
  Eigen::Vector3d cap_centre = Eigen::Vector3d::Zero();
  int cap_points = 0;
  for (int q = 0; q < sphere.mesh.quad_count(); ++q) {
    const auto& [axis, high_side, i, j] = sphere.face_cell[static_cast<size_t>(q)];
    if (axis != top_axis || high_side == 0) continue;
    bool flat = true;
    for (int k = 0; k < 4; ++k) flat = flat && on_flat(sphere.mesh.V.row(sphere.mesh.Q(q, k)).transpose());
    if (!flat) continue;
    i0 = std::min(i0, i), i1 = std::max(i1, i + 1), j0 = std::min(j0, j), j1 = std::max(j1, j + 1);
    cap_centre += sphere.mesh.V.row(sphere.mesh.Q(q, 0)).transpose();
    ++cap_points;
  }
  if (i1 - i0 < 2 || j1 - j0 < 2) {
    throw EngineError("last side mesh: " + std::to_string(cells[0]) + " x " + std::to_string(cells[1]) + " x " +
                      std::to_string(cells[2]) + " control cells put fewer than 2 x 2 on the top cut; ask for more triangles");
  }
  cap_centre = into_plane(cap_centre / cap_points, side.cut_point_mm, side.cut_normal);

  // Everything but the cap cells, vertices renumbered in order of first use.
  std::vector<int> new_id(static_cast<size_t>(sphere.mesh.vertex_count()), -1);
  std::vector<Eigen::Vector4i> quads;
  std::vector<int> old_of_new;
  for (int q = 0; q < sphere.mesh.quad_count(); ++q) {
    const auto& [axis, high_side, i, j] = sphere.face_cell[static_cast<size_t>(q)];
    if (axis == top_axis && high_side == 1 && i >= i0 && i < i1 && j >= j0 && j < j1) continue;
    Eigen::Vector4i quad;
    for (int k = 0; k < 4; ++k) {
      int& id = new_id[static_cast<size_t>(sphere.mesh.Q(q, k))];
      if (id < 0) {
        id = static_cast<int>(old_of_new.size());
        old_of_new.push_back(sphere.mesh.Q(q, k));
      }
      quad(k) = id;
    }
    quads.push_back(quad);
  }
  QuadMesh& control = side.control;
  control.V.resize(static_cast<Eigen::Index>(old_of_new.size()), 3);
  for (size_t v = 0; v < old_of_new.size(); ++v) control.V.row(static_cast<Eigen::Index>(v)) = sphere.mesh.V.row(old_of_new[v]);
  control.Q.resize(static_cast<Eigen::Index>(quads.size()), 4);
  for (size_t q = 0; q < quads.size(); ++q) control.Q.row(static_cast<Eigen::Index>(q)) = quads[q].transpose();

  // The top face runs counter-clockwise seen from above, so the side's boundary runs the other way.
  const auto corner = [&](int i, int j) {
    for (size_t v = 0; v < old_of_new.size(); ++v) {
      const auto& lattice = sphere.lattice[static_cast<size_t>(old_of_new[v])];
      if (lattice[2] == cells[2] && lattice[0] == i && lattice[1] == j) return static_cast<int>(v);
    }
    throw EngineError("last side mesh: a corner of the top cut is missing");
  };
  side.cap_corners = {corner(i0, j0), corner(i0, j1), corner(i1, j1), corner(i1, j0)};
  side.cap_cells_u = j1 - j0;
  side.cap_cells_v = i1 - i0;

  const QuadTopology topology = build_quad_topology(control);
  const auto on_rim = [&topology](Eigen::Index v) { return topology.on_boundary[static_cast<size_t>(v)] != 0; };
  const auto onto_rim = [&](const Eigen::Vector3d& p) { return rim_point(shape, cap_centre, side.cut_normal, p); };

  for (Eigen::Index v = 0; v < control.V.rows(); ++v) {
    if (on_rim(v)) control.V.row(v) = onto_rim(control.V.row(v).transpose()).transpose();
  }
  RelaxationSurface surface;
  surface.project = [&shape](const Eigen::Vector3d& p) { return shape.project_to_body(p); };
  surface.normal = [&shape](const Eigen::Vector3d& p) { return Eigen::Vector3d(shape.body_gradient(p).normalized()); };
  surface.onto_rim = onto_rim;
  relax_control_cells(control, topology, surface, kRelaxationSteps);

  // The surface fitted to the body and the rim in the least-squares sense (control_fit.hpp), the
  // ground contact held harder, and so is every sample that dips below the ground: the sole must
  // touch z = 0 (within 0.05 mm at 5000 triangles) and not sink into the ground at the feather fillet.
  ControlFitTargets targets;
  targets.onto_surface = [&shape](const Eigen::Vector3d& p) { return shape.project_to_body(p); };
  targets.onto_rim = onto_rim;
  targets.weight = [](const Eigen::Vector3d& position, const Eigen::Vector3d& foot) {
    return foot.z() < kGroundBandMm || position.z() < 0.0 ? kGroundWeight : 1.0;
  };
  fit_control_least_squares(control, topology, targets, ControlFitOptions{});
  for (Eigen::Index v = 0; v < control.V.rows(); ++v) {
    if (on_rim(v)) control.V.row(v) = into_plane(control.V.row(v).transpose(), side.cut_point_mm, side.cut_normal).transpose();
  }
  return side;
}

}  // namespace lastcut
