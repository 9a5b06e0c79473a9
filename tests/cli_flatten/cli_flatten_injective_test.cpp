// `lastcut flatten --no-segment` on a patch whose plain ARAP outline overlaps itself (a helicoidal ramp over
// 420 degrees: the mold used to be refused with "the flattened outline overlaps itself"): the real binary
// now writes a mold, says in report.json that ARAP was rerun injectively, and the flat mesh's outline keeps
// the 0.1 mm clearance (checked here by brute force over all pairs of boundary edges).
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "engine/flatten/disk_topology.hpp"
#include "engine/flatten/outline_clearance.hpp"
#include "tests/support/lastcut_cli.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

// The ramp of tests/flatten/injective_outline_test.cpp as OBJ text: radii 40-80 mm, 420 degrees, 20 mm
// rise per turn, 10 x 240 quads on alternating diagonals.
std::string ramp_obj() {
  constexpr int kRadial = 10, kAround = 240;
  std::ostringstream obj;
  obj.precision(12);
  for (int j = 0; j <= kAround; ++j) {
    const double theta = 420.0 * std::numbers::pi / 180.0 * j / kAround;
    for (int i = 0; i <= kRadial; ++i) {
      const double r = 40.0 + 40.0 * i / kRadial;
      obj << "v " << r * std::cos(theta) << ' ' << r * std::sin(theta) << ' ' << 20.0 * theta / (2 * std::numbers::pi)
          << '\n';
    }
  }
  for (int j = 0; j < kAround; ++j) {
    for (int i = 0; i < kRadial; ++i) {
      const int a = j * (kRadial + 1) + i + 1, b = a + 1, c = a + kRadial + 2, d = a + kRadial + 1;
      if ((i + j) % 2 == 0)
        obj << "f " << a << ' ' << b << ' ' << c << "\nf " << a << ' ' << c << ' ' << d << '\n';
      else
        obj << "f " << a << ' ' << b << ' ' << d << "\nf " << b << ' ' << c << ' ' << d << '\n';
    }
  }
  return obj.str();
}

// v x y z / f a b c (1-based) lines of the flat mesh lastcut writes.
TriMesh read_flat_obj(const fs::path& path) {
  std::ifstream in(path);
  std::vector<double> xyz;
  std::vector<int> faces;
  for (std::string line; std::getline(in, line);) {
    std::istringstream fields(line);
    std::string tag;
    fields >> tag;
    if (tag == "v") {
      double x = 0, y = 0, z = 0;
      fields >> x >> y >> z;
      xyz.insert(xyz.end(), {x, y, z});
    } else if (tag == "f") {
      for (int k = 0; k < 3; ++k) {
        std::string corner;
        fields >> corner;
        faces.push_back(std::stoi(corner) - 1);
      }
    }
  }
  TriMesh mesh;
  mesh.V = Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>>(xyz.data(), xyz.size() / 3, 3);
  mesh.F = Eigen::Map<Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>>(faces.data(), faces.size() / 3, 3);
  return mesh;
}

TEST(CliFlattenInjective, OverlappingRampGetsAMoldWithAClearOutline) {
  const fs::path dir = fs::temp_directory_path() / ("lastcut-cli-injective-" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "ramp.obj") << ramp_obj();
  const std::string arguments =
      "flatten --no-segment '" + (dir / "ramp.obj").string() + "' -o '" + (dir / "out").string() + "'";
  const test::CommandRun run = test::run_lastcut(arguments, dir);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(fs::exists(dir / "out" / "patch.dxf"));

  const nlohmann::json report = nlohmann::json::parse(test::read_text(dir / "out" / "report.json"));
  bool reran = false;
  for (const auto& note : report["notes"])
    reran = reran || note.get<std::string>().find("reran injective ARAP") != std::string::npos;
  EXPECT_TRUE(reran) << report["notes"].dump();
  EXPECT_EQ(report["segments"][0]["flipped"].get<int>(), 0);

  const TriMesh flat = read_flat_obj(dir / "out" / "patch-flat.obj");
  const MeshTopology topology = check_disk(flat);
  const OutlineClearance outline(topology.boundary_loops[0], 0.1);
  EXPECT_FALSE(outline.crosses(flat.V.leftCols(2)));
  EXPECT_GE(outline.smallest_gap_mm(flat.V.leftCols(2), 1), 0.1 - 1e-5);  // written with 6 decimals
  fs::remove_all(dir);
}

}  // namespace
}  // namespace lastcut
