// `lastcut flatten --no-segment` on a patch whose plain ARAP outline overlaps itself (a helicoidal ramp over
// 420 degrees: the mold used to be refused with "the flattened outline overlaps itself"): the real binary
// now writes a mold (on request: the quality gate holds it as not converged), says in report.json that ARAP was rerun injectively, and the flat mesh's outline keeps
// the 0.1 mm clearance (checked here by brute force over all pairs of boundary edges).
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
      "flatten --no-segment '" + (dir / "ramp.obj").string() + "' -o '" + (dir / "out").string() + "' --keep-bad-molds";
  const test::CommandRun run = test::run_lastcut(arguments, dir);
  // The injective rerun keeps the outline clear but stops before ARAP's tolerance: the quality gate
  // holds that (exit 3) on "not converged" alone, every measure being within its limit; the mold is
  // written on request (--keep-bad-molds). Until the rerun converges (issue 36, point 2) this is
  // what an operator gets.
  ASSERT_EQ(run.exit_code, 3) << run.err;
  EXPECT_EQ(run.err,
            "lastcut: error: mold quality: patch ARAP not converged (molds written anyway: not for cutting; "
            "report.json quality.passed is false)\n");
  EXPECT_TRUE(fs::exists(dir / "out" / "patch.dxf"));

  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir / "out" / "report.json"));
  bool reran = false;
  for (const auto& note : report["notes"])
    reran = reran || note.get<std::string>().find("reran injective ARAP") != std::string::npos;
  EXPECT_TRUE(reran) << report["notes"].dump();
  EXPECT_EQ(report["segments"][0]["flipped"].get<int>(), 0);

  const TriMesh flat = read_mesh(dir / "out" / "patch-flat.obj", {.unit = LengthUnit::Millimetre}).mesh;
  const MeshTopology topology = check_disk(flat);
  const OutlineClearance outline(topology.boundary_loops[0], 0.1);
  EXPECT_FALSE(outline.crosses(flat.V.leftCols(2)));
  EXPECT_GE(outline.smallest_gap_mm(flat.V.leftCols(2), 1), 0.1 - 1e-5);  // written with 6 decimals
}

}  // namespace
}  // namespace lastcut
