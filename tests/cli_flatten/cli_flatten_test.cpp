// `lastcut flatten` as an operator runs it: the real binary on real files. Every class of bad
// scan ends with a non-zero exit and exactly one clear line on stderr, never a crash; a good scan
// leaves the files of the output contract.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

using test::CommandRun;
using test::read_text;

class CliFlatten : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = lastcut::test::make_temp_dir("cli-flatten");
  }
  static void TearDownTestSuite() { fs::remove_all(dir_); }

  static CommandRun flatten(const std::string& arguments) { return test::run_lastcut("flatten " + arguments, dir_); }

  // Non-zero exit, no crash, exactly one line "lastcut: error: ..." that contains `reason`.
  static void expect_refused(const fs::path& scan, const std::string& extra, const std::string& reason) {
    const CommandRun run = flatten("'" + scan.string() + "' -o '" + (dir_ / "refused").string() + "' " + extra);
    EXPECT_FALSE(run.crashed) << scan << ": " << run.err;
    EXPECT_NE(run.exit_code, 0) << scan;
    EXPECT_TRUE(run.err.starts_with("lastcut: error: ")) << scan << ": " << run.err;
    EXPECT_EQ(std::count(run.err.begin(), run.err.end(), '\n'), 1) << scan << ": " << run.err;
    EXPECT_NE(run.err.find(reason), std::string::npos) << scan << ": " << run.err;
    EXPECT_FALSE(fs::exists(dir_ / "refused" / "report.json")) << scan;
  }

  static fs::path write_file(const std::string& name, const std::string& content) {
    const fs::path path = dir_ / name;
    std::ofstream(path, std::ios::binary) << content;
    return path;
  }

  static inline fs::path dir_;
};

// A closed axis-aligned box as OBJ text (12 triangles, outward).
std::string box_obj(double x0, double y0, double z0, double sx, double sy, double sz, int first_vertex = 1) {
  std::ostringstream obj;
  for (int i = 0; i < 8; ++i)
    obj << "v " << x0 + sx * (i & 1) << ' ' << y0 + sy * ((i >> 1) & 1) << ' ' << z0 + sz * ((i >> 2) & 1) << '\n';
  const int faces[12][3] = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                            {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
  for (const auto& f : faces)
    obj << "f " << f[0] + first_vertex << ' ' << f[1] + first_vertex << ' ' << f[2] + first_vertex << '\n';
  return obj.str();
}

// An open, gently curved patch (a piece of a cylinder 200 x 90 mm), ~ 2 x nx x ny triangles.
TriMesh curved_patch(int nx = 60, int ny = 30) {
  TriMesh patch;
  patch.V.resize((nx + 1) * (ny + 1), 3);
  for (int i = 0; i <= nx; ++i)
    for (int j = 0; j <= ny; ++j) {
      const double angle = (static_cast<double>(j) / ny - 0.5) * 1.2;
      patch.V.row(i * (ny + 1) + j) << 200.0 * i / nx, 75.0 * std::sin(angle), 75.0 * (1.0 - std::cos(angle));
    }
  patch.F.resize(2 * nx * ny, 3);
  int f = 0;
  for (int i = 0; i < nx; ++i)
    for (int j = 0; j < ny; ++j) {
      const int a = i * (ny + 1) + j, b = a + 1, c = a + ny + 1, d = c + 1;
      patch.F.row(f++) << a, c, d;
      patch.F.row(f++) << a, d, b;
    }
  return patch;
}

TEST_F(CliFlatten, RefusesAnEmptyFile) { expect_refused(write_file("empty.stl", ""), "", ""); }

TEST_F(CliFlatten, RefusesATruncatedBinaryStl) {
  std::string stl(80, ' ');
  const std::uint32_t claimed = 5000;
  stl.append(reinterpret_cast<const char*>(&claimed), 4);
  stl.append(120 * 50, '\0');
  expect_refused(write_file("truncated.stl", stl), "", "truncated");
}

TEST_F(CliFlatten, RefusesANanVertex) {
  std::string obj = box_obj(0, 0, 0, 250, 90, 100);
  obj.replace(obj.find("v 0 0 0"), 7, "v nan 0 0");
  expect_refused(write_file("nan.obj", obj), "", "");
}

TEST_F(CliFlatten, RefusesANonManifoldMess) {
  // Ten triangles hinged on one edge, plus a stray box: no surface a last could be.
  std::ostringstream obj;
  obj << "v 0 0 0\nv 0 0 100\n";
  for (int k = 0; k < 10; ++k) {
    const double angle = 2.0 * std::numbers::pi * k / 10;
    obj << "v " << 80 * std::cos(angle) << ' ' << 80 * std::sin(angle) << " 50\n";
  }
  for (int k = 0; k < 10; ++k) obj << "f 1 2 " << k + 3 << '\n';
  expect_refused(write_file("non-manifold.obj", obj.str()), "", "");
}

TEST_F(CliFlatten, RefusesSeveralDisconnectedPieces) {
  expect_refused(write_file("pieces.obj", box_obj(0, 0, 0, 120, 90, 100) + box_obj(200, 0, 0, 120, 90, 100, 9) +
                                              box_obj(400, 0, 0, 120, 90, 100, 17)),
                 "", "");
}

TEST_F(CliFlatten, RefusesAFlatPlate) {
  expect_refused(write_file("plate.obj", box_obj(0, 0, 0, 260, 100, 1)), "", "");
}

TEST_F(CliFlatten, RefusesAnOpenPatchWithoutNoSegment) {
  const fs::path patch = dir_ / "patch.obj";
  write_mesh(patch, curved_patch());
  expect_refused(patch, "", "--no-segment");
}

TEST_F(CliFlatten, RefusesAMissingFileAndBadOptions) {
  expect_refused(dir_ / "no-such-scan.stl", "", "");
  const fs::path patch = dir_ / "patch-for-options.obj";
  write_mesh(patch, curved_patch(10, 5));
  expect_refused(patch, "--no-segment --allowance=-3", "allowance");
}

TEST_F(CliFlatten, RefusesBadEdgeAllowancesAndNotchSpacingsInOneLine) {
  const fs::path patch = dir_ / "patch-for-edges.obj";
  write_mesh(patch, curved_patch(10, 5));
  expect_refused(patch, "--no-segment --lasting=-1", "--lasting must be between 0 and 50 mm, not -1");
  expect_refused(patch, "--no-segment --seam 80", "--seam must be between 0 and 50 mm, not 80");
  expect_refused(patch, "--no-segment --top nan", "--top must be between 0 and 50 mm, not nan");
  expect_refused(patch, "--no-segment --allowance 2 --seam 4",
                 "give --allowance (all edges) or --lasting/--seam/--top (per edge), not both");
  expect_refused(patch, "--no-segment --balance-notches 2",
                 "--balance-notches must be off, a spacing in mm (0 or 5 to 500) or SEAM_MM,FEATHER_MM, not \"2\"");
  expect_refused(patch, "--no-segment --balance-notches 20,x", "--balance-notches must be off");
  // A patch has no landmarks, so it has no edges to give allowances to.
  expect_refused(patch, "--no-segment --lasting 15", "mold patch: per-edge allowances need the landmark");
}

TEST_F(CliFlatten, PerEdgeAllowancesAndBalanceNotchesReachTheMoldFiles) {
  LastParams params = LastParams::for_eu_size(39, FootSide::Left);
  params.target_triangles = 8000;
  const fs::path scan = dir_ / "last-edges.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  const fs::path out = dir_ / "molds-edges";
  const CommandRun run = flatten("'" + scan.string() + "' -o '" + out.string() +
                                 "' --lasting 16 --seam 5 --top 0 --balance-notches 20,50");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  for (const char* name : {"medial", "lateral"}) {
    const Mold mold = read_mold_dxf(out / (std::string(name) + ".dxf"));
    ASSERT_GE(mold.net.points.size(), 3u) << name;
    EXPECT_GT(signed_area(mold.outline), signed_area(mold.net) + 100 * 16.0) << name;  // a 16 mm margin on >= 100 mm
    std::map<std::string, int> count;
    for (const MoldMark& mark : mold.marks) count[mark.name.substr(0, mark.name.find_last_of('_'))]++;
    EXPECT_GE(count["balance_seam_front"], 2) << name;
    EXPECT_GE(count["balance_seam_back"], 1) << name;
    EXPECT_GE(count["balance_feather"], 2) << name;
    const std::string svg = read_text(out / (std::string(name) + ".svg"));
    EXPECT_NE(svg.find("<polygon id=\"net\""), std::string::npos) << name;
  }
}

void expect_same_mesh_layout(const fs::path& mesh3d, const fs::path& flat) {
  auto count = [](const fs::path& path, const std::string& prefix) {
    std::ifstream in(path);
    std::string line;
    int n = 0;
    while (std::getline(in, line)) n += line.starts_with(prefix);
    return n;
  };
  auto faces = [](const fs::path& path) {
    std::ifstream in(path);
    std::string line, all;
    while (std::getline(in, line))
      if (line.starts_with("f ")) all += line + '\n';
    return all;
  };
  EXPECT_GT(count(mesh3d, "v "), 0);
  EXPECT_EQ(count(mesh3d, "v "), count(flat, "v "));
  EXPECT_EQ(faces(mesh3d), faces(flat));
  std::ifstream in(flat);
  std::string line;
  while (std::getline(in, line)) {
    if (line.starts_with("v ")) {
      ASSERT_TRUE(line.ends_with(" 0")) << line;
    }
  }
}

TEST_F(CliFlatten, FlattensALastIntoTheContractFiles) {
  LastParams params = LastParams::for_eu_size(40, FootSide::Right);
  params.target_triangles = 20000;
  params.random_pose = true;
  params.noise_mm = 0.1;
  params.seed = 3;
  const fs::path scan = dir_ / "last.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  const fs::path out = dir_ / "molds";
  const CommandRun run = flatten("'" + scan.string() + "' -o '" + out.string() + "' --allowance 2");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;

  const auto report = nlohmann::json::parse(read_text(out / "report.json"));
  EXPECT_EQ(report["units"], "mm");
  EXPECT_EQ(report["input"], scan.string());
  EXPECT_EQ(report["side"], "right");
  EXPECT_GT(report["seconds_total"].get<double>(), 0.0);
  ASSERT_EQ(report["segments"].size(), 2u);
  for (const auto& segment : report["segments"]) {
    const std::string name = segment["name"];
    EXPECT_TRUE(name == "medial" || name == "lateral") << name;
    for (const char* file : {"-3d.obj", "-flat.obj", ".dxf", ".svg"}) EXPECT_TRUE(fs::exists(out / (name + file)));
    expect_same_mesh_layout(out / (name + "-3d.obj"), out / (name + "-flat.obj"));
    EXPECT_GT(segment["triangles"].get<int>(), 3000);
    EXPECT_EQ(segment["flipped"], 0);
    EXPECT_GE(segment["D_angle"].get<double>(), 2.0);
    EXPECT_LT(segment["D_angle"].get<double>(), 2.1);
    EXPECT_GE(segment["D_area"].get<double>(), 2.0);
    EXPECT_LT(segment["D_area"].get<double>(), 2.1);
    EXPECT_GT(segment["area_3d_mm2"].get<double>(), 5000.0);
    EXPECT_NEAR(segment["area_2d_mm2"].get<double>() / segment["area_3d_mm2"].get<double>(), 1.0, 0.03);
    EXPECT_GT(segment["boundary_3d_mm"].get<double>(), 300.0);
    EXPECT_NEAR(segment["boundary_2d_mm"].get<double>() / segment["boundary_3d_mm"].get<double>(), 1.0, 0.03);
    EXPECT_GE(segment["max_stretch"].get<double>(), 1.0);
    EXPECT_GT(segment["seconds_flatten"].get<double>(), 0.0);
    const Mold mold = read_mold_dxf(out / (name + ".dxf"));
    EXPECT_EQ(mold.marks.size(), 4u) << name;
    EXPECT_GT(signed_area(mold.outline), segment["area_2d_mm2"].get<double>());  // 2 mm allowance
  }
  // The profile names every stage from reading to the last picture, each with its wall time, and
  // the stages before writing add up to no more than the pipeline's total.
  std::vector<std::string> stages;
  double before_writing_s = 0.0;
  for (const auto& stage : report["profile"]) {
    stages.push_back(stage["stage"]);
    EXPECT_GE(stage["seconds"].get<double>(), 0.0);
    if (stages.back().find("write") == std::string::npos) before_writing_s += stage["seconds"].get<double>();
  }
  const std::vector<std::string> expected = {
      "read and repair", "last check", "denoise", "orient", "segment", "medial: flatten", "medial: distortion",
      "medial: mold outline", "medial: quality gate", "lateral: flatten", "lateral: distortion",
      "lateral: mold outline", "lateral: quality gate",
      "medial: write 3d obj", "medial: write flat obj", "medial: write dxf", "medial: write svg",
      "lateral: write 3d obj", "lateral: write flat obj", "lateral: write dxf", "lateral: write svg"};
  EXPECT_EQ(stages, expected);
  EXPECT_LE(before_writing_s, report["seconds_total"].get<double>());
}

TEST_F(CliFlatten, SplitExpertCutsTwoValidMoldsOfLeftAndRightLasts) {
  for (FootSide side : {FootSide::Left, FootSide::Right}) {
    LastParams params = LastParams::for_eu_size(side == FootSide::Left ? 39 : 45, side);
    params.target_triangles = 16000;
    params.random_pose = true;
    params.noise_mm = 0.1;
    params.seed = 11;
    const std::string name(to_string(side));
    const fs::path scan = dir_ / ("expert-" + name + ".stl");
    write_stl_binary(scan, generate_last(params).mesh);
    double medial_area_mm2[2] = {0, 0};
    for (int expert = 0; expert < 2; ++expert) {
      const fs::path out = dir_ / ("expert-" + name + std::to_string(expert));
      const CommandRun run = flatten("'" + scan.string() + "' -o '" + out.string() + "'" + (expert ? " --split expert" : ""));
      ASSERT_EQ(run.exit_code, 0) << run.err;
      const auto report = nlohmann::json::parse(read_text(out / "report.json"));
      EXPECT_EQ(report["side"], name);
      ASSERT_EQ(report["segments"].size(), 2u);
      for (const auto& segment : report["segments"]) {
        const std::string half = segment["name"];
        EXPECT_EQ(segment["flipped"], 0) << half;
        EXPECT_LT(segment["D_angle"].get<double>(), 2.1) << half;
        EXPECT_NEAR(segment["area_2d_mm2"].get<double>() / segment["area_3d_mm2"].get<double>(), 1.0, 0.03) << half;
        EXPECT_EQ(read_mold_dxf(out / (half + ".dxf")).marks.size(), 4u) << half;
        if (half == "medial") medial_area_mm2[expert] = segment["area_3d_mm2"].get<double>();
      }
      bool noted = false;
      for (const auto& note : report["notes"]) noted = noted || note.get<std::string>().starts_with("expert split: second toe at");
      EXPECT_EQ(noted, expert == 1) << name;
    }
    // The expert's plane is another plane: the medial half changes.
    EXPECT_GT(std::abs(medial_area_mm2[1] - medial_area_mm2[0]), 100.0) << name;
  }
}

TEST_F(CliFlatten, RefusesAnUnknownSplitRule) {
  const fs::path out = dir_ / "bad-split";
  const CommandRun run = flatten("'" + (dir_ / "any.stl").string() + "' -o '" + out.string() + "' --split sideways");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.err, "lastcut: error: --split must be auto or expert, not \"sideways\"\n");
}

// ABF++ end to end: both halves flip-free, scaled to their 3D area exactly, molds enclosing that area.
TEST_F(CliFlatten, FlattensALastWithAbf) {
  LastParams params = LastParams::for_eu_size(43, FootSide::Left);
  params.target_triangles = 20000;
  params.random_pose = true;
  params.seed = 5;
  const fs::path scan = dir_ / "last-abf.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  const fs::path out = dir_ / "molds-abf";
  const CommandRun run = flatten("'" + scan.string() + "' -o '" + out.string() + "' --method abf");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(run.err.empty()) << run.err;
  const auto report = nlohmann::json::parse(read_text(out / "report.json"));
  ASSERT_EQ(report["segments"].size(), 2u);
  for (const auto& segment : report["segments"]) {
    const std::string name = segment["name"];
    for (const char* file : {"-3d.obj", "-flat.obj", ".dxf", ".svg"}) EXPECT_TRUE(fs::exists(out / (name + file)));
    EXPECT_EQ(segment["flipped"], 0);
    EXPECT_GE(segment["D_angle"].get<double>(), 2.0);
    EXPECT_LT(segment["D_angle"].get<double>(), 2.02);
    EXPECT_NEAR(segment["area_2d_mm2"].get<double>() / segment["area_3d_mm2"].get<double>(), 1.0, 1e-6);
    const Mold mold = read_mold_dxf(out / (name + ".dxf"));
    EXPECT_EQ(mold.marks.size(), 4u) << name;
    EXPECT_NEAR(signed_area(mold.outline), segment["area_2d_mm2"].get<double>(),
                0.005 * segment["area_2d_mm2"].get<double>());
  }
  // A method name that is not offered is refused by the option parser, naming the option.
  const CommandRun wrong = flatten("'" + scan.string() + "' -o '" + (dir_ / "refused").string() + "' --method abf++");
  EXPECT_FALSE(wrong.crashed);
  EXPECT_NE(wrong.exit_code, 0);
  EXPECT_EQ(wrong.exit_code, 2);
  EXPECT_EQ(wrong.err, "lastcut: error: --method must be arap, lscm or abf, not \"abf++\"\n");
  const CommandRun unit = flatten("'" + scan.string() + "' -o '" + (dir_ / "refused").string() + "' --unit furlong");
  EXPECT_EQ(unit.exit_code, 2);
  EXPECT_EQ(unit.err, "lastcut: error: --unit must be auto, mm, cm, m or in, not \"furlong\"\n");
}

TEST_F(CliFlatten, FlattensAnOpenPatchWithNoSegment) {
  const fs::path patch = dir_ / "open-patch.obj";
  write_mesh(patch, curved_patch());
  const fs::path out = dir_ / "patch-molds";
  const CommandRun run = flatten("'" + patch.string() + "' -o '" + out.string() + "' --no-segment --method lscm");
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto report = nlohmann::json::parse(read_text(out / "report.json"));
  ASSERT_EQ(report["segments"].size(), 1u);
  EXPECT_EQ(report["segments"][0]["name"], "patch");
  EXPECT_EQ(report["segments"][0]["triangles"], 3600);
  EXPECT_TRUE(report["side"].is_null());
  expect_same_mesh_layout(out / "patch-3d.obj", out / "patch-flat.obj");
  EXPECT_TRUE(fs::exists(out / "patch.dxf"));
  EXPECT_TRUE(fs::exists(out / "patch.svg"));
  // A cylinder piece develops exactly: its mold is the 200 mm x arc-length rectangle.
  const Mold mold = read_mold_dxf(out / "patch.dxf");
  EXPECT_NEAR(signed_area(mold.outline), 200.0 * 75.0 * 1.2, 0.01 * 200.0 * 75.0 * 1.2);
}

}  // namespace
}  // namespace lastcut
