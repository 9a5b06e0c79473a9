// Half-last meshes for the flattening benchmark; see bench_halves.hpp.
#include "bench/flatten/bench_halves.hpp"

#include <OpenMesh/Tools/Decimater/DecimaterT.hh>
#include <OpenMesh/Tools/Decimater/ModAspectRatioT.hh>
#include <OpenMesh/Tools/Decimater/ModNormalFlippingT.hh>
#include <OpenMesh/Tools/Decimater/ModQuadricT.hh>

#include <cstdio>

#include "engine/core/engine_error.hpp"
#include "engine/mesh/openmesh_types.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

#ifdef LASTCUT_BENCH_HAS_SEGMENT
#include "engine/lastgen/generate_last.hpp"
#include "engine/orient/orient_last.hpp"
#include "engine/segment/segment_last.hpp"
#endif

namespace lastcut::bench {
namespace {

// Garland-Heckbert quadric decimation (OpenMesh), refusing collapses that flip normals or make slivers
// (aspect ratio worse than 5), so the decimated half stays a valid mesh to flatten.
TriMesh decimate(const TriMesh& mesh, int target_triangles) {
  OmMesh om = to_openmesh(mesh);
  om.request_face_normals();
  om.update_face_normals();
  OpenMesh::Decimater::DecimaterT<OmMesh> decimater(om);
  OpenMesh::Decimater::ModQuadricT<OmMesh>::Handle quadric;
  OpenMesh::Decimater::ModNormalFlippingT<OmMesh>::Handle normal_flipping;
  OpenMesh::Decimater::ModAspectRatioT<OmMesh>::Handle aspect_ratio;
  decimater.add(quadric);
  decimater.add(normal_flipping);
  decimater.add(aspect_ratio);
  decimater.module(quadric).unset_max_err();
  decimater.initialize();
  decimater.decimate_to_faces(0, static_cast<size_t>(target_triangles));
  om.garbage_collection();
  return from_openmesh(om);
}

}  // namespace

std::vector<BenchHalf> reference_halves(bool largest) {
  const TriMesh reference =
      testing::read_off(std::string(LASTCUT_SHARED_DATA_DIR) + "/meshes/find-template-half-52k.off", 1000.0);
  std::vector<BenchHalf> halves;
  halves.push_back({"FIND half, QEM-decimated", decimate(reference, 25000)});
  halves.push_back({"FIND half (reference file)", reference});
  TriMesh hundred = decimate(testing::subdivide_midpoint(reference), 100000);
  halves.push_back({"FIND half, subdivided + decimated", hundred});
  if (largest) halves.push_back({"FIND half, subdivided + decimated + subdivided", testing::subdivide_midpoint(hundred)});
  return halves;
}

std::vector<BenchHalf> generated_halves() {
  std::vector<BenchHalf> halves;
#ifdef LASTCUT_BENCH_HAS_SEGMENT
  for (int last_triangles : {60000, 240000}) {
    LastParams params = LastParams::for_eu_size(42, FootSide::Left);
    params.target_triangles = last_triangles;
    try {
      const GeneratedLast last = generate_last(params);
      // Generated lasts are already in the canonical frame (no random pose): no orientation step needed.
      OrientedLast oriented{last.mesh, Eigen::Affine3d::Identity(), FootSide::Left, {}};
      const Segmentation halves_of_last = segment_last(oriented);
      halves.push_back({"generated EU42 last (" + std::to_string(last_triangles / 1000) + "k), medial half",
                        halves_of_last.medial.mesh});
    } catch (const EngineError& e) {
      std::printf("(generated %dk last skipped: %s)\n", last_triangles / 1000, e.what());
    }
  }
#endif
  return halves;
}

}  // namespace lastcut::bench
