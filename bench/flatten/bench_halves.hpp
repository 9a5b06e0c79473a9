#pragma once
// The half-last meshes the flattening benchmark runs on: the shared reference half (a real scanned
// foot template, FIND, MIT) at its own size, decimated and subdivided, and halves of generated lasts
// cut by the segmentation module when it is built.
#include <string>
#include <vector>

#include "engine/core/tri_mesh.hpp"

namespace lastcut::bench {

struct BenchHalf {
  std::string name;  // what it is and how it was made
  TriMesh mesh;      // mm, a disk
};

// Reference half (52,800 triangles), QEM-decimated to ~25k, subdivided+decimated to ~100k, and that
// subdivided again (~400k). `largest` false skips the ~400k one.
std::vector<BenchHalf> reference_halves(bool largest);

// Medial halves of generated EU 42 lasts (lastgen + orient + segment), sized near 25k and 100k triangles.
// Empty when the segmentation module is not built.
std::vector<BenchHalf> generated_halves();

}  // namespace lastcut::bench
