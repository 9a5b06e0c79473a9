#pragma once
// A piece's surface moved off the last by its material's thickness before it is flattened (issue 34,
// point 3; shoe CAD's "average piece thickness").
//
// Which surface: the leather's inner face lies on the last and its outer face a thickness further out.
// Bent round the last, the inner face is compressed and the outer one stretched; the surface half way
// between keeps its length (the neutral surface of a bent plate), so the flat piece must have the
// lengths of that mid-surface. A piece of thickness t is flattened from its surface moved t/2 outward.
// Shoe CAD's "average piece thickness" is that mid-surface's distance rule; this uses the same.
//
// How: every vertex moves along the surface's unit normal there: the area-weighted mean of the triangle
// normals within kNormalRadius_mm of it. The triangles and the vertices' order are kept, so what is found
// on the surface as cut (the outline's stretches, notches, seam arc lengths) carries over to the moved
// surface by vertex index. On a sphere of radius R the area grows by (1 + d/R)^2, on a cylinder by
// (1 + d/R); where the last is concave it shrinks, and moved further than the radius of curvature there
// the surface folds: that is refused.
//
// Why over a radius, not over each vertex's own triangles (tri_mesh.hpp, vertex_normals): along a piece's
// outline the cut leaves needles (see kNeedleHeight_mm), whose normals point anywhere. On the derby's vamp
// an outline vertex with needles for its own triangles got a normal 151 degrees off the mean over 3 mm;
// moved 0.75 mm along such normals, the vamp's side of the vamp line came out 2.5 mm longer than the
// quarters' side (issue 34 allows 0.5 mm; over 2 mm: 0.01 mm). Over 2 mm the needles weigh nothing
// against the whole triangles around.
//
// What it costs: on the outline the mean is one-sided and leans towards the piece, most where the last
// turns sharply into its bottom at the feather line, so the outline moves a little inward as well as
// outward. Measured on the derby at 0.75 mm from the area the pieces fall short of the parallel surface's:
// 0.06-0.09 mm on average along the outline (the pieces grow 0.80-0.91 of what their curvature says).
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// Beyond any upper material (upper leather 0.8-2.5 mm, a padded collar laminate a few mm): style.toml's
// thickness_mm is refused above it.
inline constexpr double kMaxPieceThickness_mm = 10;

// The mid-surface's distance from the last for a material thickness_mm (mm): half of it.
double mid_surface_offset_mm(double thickness_mm);

// The radius the surface's normal is averaged over: a few of a scanned last's triangles (1.5-2.5 mm edges).
inline constexpr double kNormalRadius_mm = 2;

// A triangle lower than this is a needle: three corners nearly in a row, as the cut leaves them where it
// clips a triangle of the last (piece_surface.hpp; the derby's that turned over: 0.0002-0.003 mm high). The corners'
// normals differ by the last's turn between its triangles, and moved 0.75 mm a needle turns over; that
// folds nothing, and the flattening lays each triangle out in its own plane, whichever side it faces.
inline constexpr double kNeedleHeight_mm = 0.05;

// mesh: #V x 3 mm, its triangles counter-clockwise seen from outside. Returns the mesh with every vertex
// moved offset_mm along the surface's unit normal (above; a vertex on no triangle stays); F is the same.
// Throws EngineError (one line) when offset_mm is negative or not finite, or when a triangle that is no
// needle turns over (its normal against the one it had): the surface curves inward tighter than offset_mm.
TriMesh offset_along_normals(const TriMesh& mesh, double offset_mm);

}  // namespace lastcut
