// `lastcut flatten --no-segment` on a patch whose plain ARAP outline overlaps itself (a helicoidal ramp over
// 420 degrees: the mold used to be refused with "the flattened outline overlaps itself", then held by the
// quality gate as not converged): the real binary writes a mold that passes the gate, says in report.json
// that ARAP was rerun bijectively, and the flat mesh's outline keeps the 0.1 mm clearance (checked here by
// brute force over all pairs of boundary edges).
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "tests/flatten/flatten_fixtures.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

TEST(CliFlattenInjective, OverlappingRampGetsAMoldWithAClearOutline) {
  const lastcut::test::TempDir dir("cli-injective");
  // The ramp of tests/flatten/injective_outline_test.cpp: radii 40-80 mm, 420 degrees, 20 mm rise per turn.
  write_mesh(dir / "ramp.obj", testing::helicoidal_ramp(40.0, 80.0, 420.0, 20.0, 10, 240));
  const std::string arguments =
      "flatten --no-segment '" + (dir / "ramp.obj").string() + "' -o '" + (dir / "out").string() + "'";
  const test::CommandRun run = test::run_lastcut(arguments, dir);
  // Bijective ARAP converges with the outline's ends side by side: the gate passes the mold.
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "patch.dxf"));

  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir / "out" / "report.json"));
  bool reran = false;
  for (const auto& note : report["notes"])
    reran = reran || note.get<std::string>().find("reran bijective ARAP") != std::string::npos;
  EXPECT_TRUE(reran) << report["notes"].dump();
  EXPECT_TRUE(report["quality"]["passed"].get<bool>()) << report["quality"].dump();
  EXPECT_TRUE(report["segments"][0]["converged"].get<bool>());
  EXPECT_EQ(report["segments"][0]["flipped"].get<int>(), 0);

  const TriMesh flat = read_mesh(dir / "out" / "patch-flat.obj", {.unit = LengthUnit::Millimetre}).mesh;
  const MeshTopology topology = check_disk(flat);
  const OutlineClearance outline(topology.boundary_loops[0], 0.1);
  EXPECT_FALSE(outline.crosses(flat.V.leftCols(2)));
  EXPECT_GE(outline.smallest_gap_mm(flat.V.leftCols(2), 1), 0.1 - 1e-5);  // written with 6 decimals
}

}  // namespace
}  // namespace lastcut
