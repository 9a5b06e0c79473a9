#pragma once
// Fairing of chosen vertices: they are moved so that the bi-Laplacian vanishes at each of them, every
// other vertex staying where it is. The discrete thin-plate condition of L. Kobbelt, S. Campagna,
// J. Vorsatz, H.-P. Seidel, "Interactive Multi-Resolution Modeling on Arbitrary Meshes", SIGGRAPH 1998
// (umbrella operator U(p) = weighted mean of the neighbours - p, applied twice), as P. Liepa's hole
// filling (SGP 2003) uses it: a patch faired this way continues the slope of the surface around it.
// The weights are the inverse edge lengths of the mesh as it is when called (the scale-dependent
// umbrella of M. Desbrun, M. Meyer, P. Schroeder, A. Barr, "Implicit Fairing of Irregular Meshes using
// Diffusion and Curvature Flow", SIGGRAPH 1999), so a patch finer than the scan around it is not
// pulled towards its denser side.
#include <vector>

#include "engine/core/mesh_topology.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// mesh: V #V x 3 mm, F #F x 3; topology: mesh's (build_mesh_topology(mesh.F, mesh.V.rows())), still
// the mesh's afterwards (only vertices move); free: vertex indices to move (each must have a
// neighbour). Solves the linear system U(U(p))_v = 0 for the free vertices v (SparseLU) and writes
// them into mesh.V.
// directions: empty, or one unit vector per free vertex: the vertex then moves only along it (from
// where it is), and the condition holds along it (a height field over a plane: a patch laid out
// flat without folds stays without folds, only its heights are faired).
// Throws EngineError when the system is singular (a free region with no fixed vertex around it), or
// the topology was built for another mesh.
void fair_vertices_bilaplacian(TriMesh& mesh, const MeshTopology& topology, const std::vector<int>& free,
                               const std::vector<Eigen::Vector3d>& directions = {});

}  // namespace lastcut
