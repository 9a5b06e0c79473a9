// ARAP on the shared reference half (a real scanned foot template, 52,800 triangles, FIND, MIT):
// no flipped triangle in the mold, distortion near the ideal, sizes kept, repairs reported.
#include <gtest/gtest.h>

#include <string>

#include "engine/flatten/flatten.hpp"
#include "tests/flatten/flatten_fixtures.hpp"

namespace lastcut {
namespace {

TEST(ReferenceHalf, FlattensWithoutFlipsAndWithLowDistortion) {
  const TriMesh half =
      testing::read_off(std::string(LASTCUT_SHARED_DATA_DIR) + "/meshes/find-template-half-52k.off", 1000.0);
  ASSERT_EQ(half.triangle_count(), 52800);
  const FlattenResult result = flatten(half);
  const DistortionMeasures d = measure_distortion(half, result.UV);
  EXPECT_EQ(result.flipped_triangles, 0);
  EXPECT_EQ(d.flipped_triangles, 0);
  EXPECT_EQ(result.factorizations, 2);
  // A foot is far from developable (toes, heel cup): ARAP keeps distortion low but not ideal.
  EXPECT_LT(d.D_angle, 2.15);
  EXPECT_LT(d.D_area, 2.15);
  EXPECT_LT(std::abs(d.area_error_pct), 10.0);
  EXPECT_GT(d.max_stretch, 1.0);
  for (const std::string& note : result.notes) {
    EXPECT_EQ(note.find('\n'), std::string::npos);
    std::printf("note: %s\n", note.c_str());
  }
  std::printf("iterations %d, D_angle %.4f, D_area %.4f, area error %.2f %%, boundary error %.2f %%\n",
              result.iterations, d.D_angle, d.D_area, d.area_error_pct, d.boundary_error_pct);
}

}  // namespace
}  // namespace lastcut
