#pragma once
// Even control cells for the Bezier last: a box lattice cast onto the last (cube_sphere.hpp) has cells
// of uneven size (cast from one point inside it, small on the instep near that point and large at the
// toe: 84 : 1 in triangle area at 5000 triangles; from a spine, still large on the cap and small where
// the toe fan starts). Each step moves every
// control vertex towards the area-weighted mean of its quads' centres, within the surface's tangent
// plane, and puts it back on the surface: the tangential "area-equalising" relaxation of isotropic
// remeshing (M. Botsch, L. Kobbelt, "A remeshing approach to multiresolution modeling", SGP 2004;
// area weights as in Botsch et al., "Polygon Mesh Processing", AK Peters 2010, chapter 6), here
// on quads. A big cell pulls its corners towards itself, which shrinks it; the vertices never leave
// the surface, so the shape is kept.
#include <functional>
#include <vector>

#include "engine/subdiv/quad_mesh.hpp"

namespace lastcut {

struct RelaxationSurface {
  // Back onto the surface (mm in, mm out), for the vertices that are not on a rim.
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> project;
  // The surface's unit normal near p (mm in).
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> normal;
  // Back onto the rim curve, for the boundary vertices (they slide along the boundary only).
  std::function<Eigen::Vector3d(const Eigen::Vector3d&)> onto_rim;
};

// `steps` relaxation steps on control (V #V x 3, mm; Q #Q x 4), in place. Boundary vertices move
// towards the mean of their two boundary neighbours, along the rim; the others as above.
void relax_control_cells(QuadMesh& control, const QuadTopology& topology, const RelaxationSurface& surface, int steps);

}  // namespace lastcut
