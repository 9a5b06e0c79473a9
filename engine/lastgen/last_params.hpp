#pragma once
// The parameters of a parametric shoe last and of the simulated scan made of it.
// Canonical frame: sole down, ground plane z = 0 (the ball tread touches it), +X from heel to
// toe (heel back at x = 0, toe tip at x = length), +Z up; the medial (big-toe) side is -Y for a
// left last and +Y for a right last (see engine/core/foot_side.hpp).
#include <Eigen/Geometry>
#include <cstdint>

#include "engine/core/foot_side.hpp"
#include "engine/core/tri_mesh.hpp"

namespace lastcut {

// How the surface is made: marching tetrahedra + isotropic remeshing onto the solid with its 2 mm top-cut
// fillet (the default; `lastcut generate --surface legacy`), or the C2 bicubic Bezier surface of a quad
// control mesh with a sharp, flat top cut (engine/lastgen/bezier_last.hpp; `--surface bezier`). Bezier is
// not yet the default: with it flipped, one lastgen test (triangle areas 16.7 : 1 at 5000 triangles, asked
// < 8) and four scan and command-line tests still fail (docs/subdivision.md, "The sample last").
// LastSurface::Lofted is a scanner export's or CAD mesher's triangulation rather than a good one:
// rings of vertices across the last, joined by long thin triangles, and a fan of slivers at the
// heel and toe poles (engine/lastgen/lofted_last.hpp).
enum class LastSurface { Remeshed, Bezier, Lofted };

// How scanner noise moves a vertex: along its normal (an even error in depth), or in all three
// directions (a point error, as structured-light and laser scanners make it).
enum class ScanNoise { AlongNormal, Isotropic };

struct LastParams {
  double length_mm = 270;       // heel back to toe tip
  double ball_width_mm = 95;    // widest, at the ball (~ 64-72% of length from heel)
  double heel_width_mm = 62;    // widest at the heel seat (~ 17% of length from heel)
  double heel_height_mm = 25;   // heel pitch: how far the heel seat is raised above the ground plane
  double toe_spring_mm = 12;    // how far the toe tip rises above the ground
  double top_height_mm = 110;   // height of the flat top cut (cone) above the heel seat
  FootSide side = FootSide::Left;
  bool symmetric = false;       // a straight last for either foot: the plan outline's medial side mirrored
                                // onto the lateral one, toe and heel centred on the long axis
  int target_triangles = 50000; // the result has this many (Bezier: rounded down to even; legacy: to within 2)
  double noise_mm = 0.0;        // scanner noise, Gaussian sigma (along the normal, or per axis)
  ScanNoise noise_kind = ScanNoise::AlongNormal;
  int holes = 0;                // small scan holes (a few mm across), never on the top cut
  int seams = 0;                // stitching seams where two scan passes were merged (stitching_seam.hpp)
  double seam_step_mm = 0.2;    // the passes' misregistration: the step at a seam
  bool random_pose = false;     // arbitrary rotation + translation of the whole scan
  uint64_t seed = 1;
  LastSurface surface = LastSurface::Remeshed;

  // Plausible proportions for a medium-width everyday last of EU (Paris point) size 35..47:
  // length = size x 6.667 mm, widths and heights proportional. Throws EngineError outside 35..47.
  static LastParams for_eu_size(int eu_size, FootSide side);
};

// Throws EngineError with one readable line when the parameters cannot make a last
// (non-positive or out-of-proportion sizes, too few or too many triangles, negative noise...).
void validate(const LastParams& params);

struct GeneratedLast {
  TriMesh mesh;                       // mm, closed (unless holes), outward-oriented
  Eigen::Affine3d canonical_to_scan;  // identity unless random_pose
};

}  // namespace lastcut
