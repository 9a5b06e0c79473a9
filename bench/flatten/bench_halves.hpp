#pragma once
// The half-last meshes the flattening benchmark runs on: the shared reference half (a real scanned
// foot template, FIND, MIT) at its own size, decimated and subdivided, and medial halves of generated
// lasts cut by the segmentation module when it is built, sized to ~25k, ~100k and ~400k triangles.
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"
#include "engine/segment/segment_last.hpp"

namespace lastcut::bench {

struct BenchHalf {
  std::string name;  // what it is and how it was made
  TriMesh mesh;      // mm, a disk
};

// Reference half (52,800 triangles), QEM-decimated to ~25k, subdivided+decimated to ~100k, and that
// subdivided again (~400k). `largest` false skips the ~400k one.
std::vector<BenchHalf> reference_halves(bool largest);

// Medial and lateral halves of the FIND foot template (a real scanned foot, MIT, 1,750 triangles):
// subdivided 1:256 (midpoint), QEM-decimated so that each half has about half_triangles triangles,
// then stood up and cut by the same orient + segment steps a scan goes through.
std::vector<BenchHalf> find_foot_halves(int half_triangles);

// The FIND foot template subdivided 1:256 (midpoint), QEM-decimated to foot_triangles and cut by
// lastcut's own orient + segment steps: both halves with their landmarks.
Segmentation find_foot_segmentation(int foot_triangles);

// Medial halves of generated EU 42 lasts (lastgen + segment) with half_triangles[i] triangles +/- 2 %
// (the last's triangle count is corrected from the half it gave until the half is within 2 %), and the
// lateral half too for the 100,000 target.
std::vector<BenchHalf> generated_halves(const std::vector<int>& half_triangles);

// Every *.off file in `folder` (mm, as bench_flatten --save writes them), named by its file name.
std::vector<BenchHalf> saved_halves(const std::string& folder);

// Wall seconds of segment_last on a generated EU 42 last of `last_triangles` triangles (best of
// `repeats`), or a negative value when the segmentation gives an empty half.
double segmentation_seconds(int last_triangles, int repeats);

}  // namespace lastcut::bench
