// Mold files: DXF written and read back, DXF readers refusing bad files, the SVG stretch picture.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "engine/core/engine_error.hpp"
#include "engine/mold/mold.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "engine/mold/mold_svg.hpp"
#include "tests/mold/synthetic_patch.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

class MoldFiles : public ::testing::Test {
 protected:
  fs::path file(const std::string& name) const { return dir_ / name; }
  void write_text(const fs::path& path, const std::string& text) const { std::ofstream(path, std::ios::binary) << text; }
  static std::string read_text(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
  }
  const lastcut::test::TempDir dir_{std::string("mold-files-") + ::testing::UnitTest::GetInstance()->current_test_info()->name()};
};

Mold sample_mold(double allowance_mm = 0.0) {
  const auto patch = test::wavy_disk(360, 4);
  return make_mold("medial", patch.UV, patch.F, {{"toe", patch.rim_first}, {"heel", patch.rim_first + 180}},
                   {0.02, allowance_mm});
}

TEST_F(MoldFiles, DxfRoundTripKeepsOutlineMarksAndName) {
  for (double allowance_mm : {0.0, 4.0}) {
    const Mold mold = sample_mold(allowance_mm);
    write_mold_dxf(file("medial.dxf"), mold);
    const Mold back = read_mold_dxf(file("medial.dxf"));
    EXPECT_EQ(back.name, "medial");
    ASSERT_EQ(back.outline.points.size(), mold.outline.points.size());
    for (size_t i = 0; i < mold.outline.points.size(); ++i)
      ASSERT_LT((back.outline.points[i] - mold.outline.points[i]).norm(), 2e-6);
    ASSERT_EQ(back.marks.size(), mold.marks.size());
    for (size_t i = 0; i < mold.marks.size(); ++i) {
      EXPECT_EQ(back.marks[i].name, mold.marks[i].name);
      EXPECT_LT((back.marks[i].position_mm - mold.marks[i].position_mm).norm(), 2e-6);
      EXPECT_LT((back.marks[i].inward_direction - mold.marks[i].inward_direction).norm(), 1e-5);
    }
  }
}

TEST_F(MoldFiles, DxfDeclaresMillimetresAndLayers) {
  write_mold_dxf(file("m.dxf"), sample_mold());
  const std::string text = read_text(file("m.dxf"));
  EXPECT_NE(text.find("$INSUNITS\n70\n4\n"), std::string::npos);
  EXPECT_NE(text.find("POLYLINE\n8\nCUT\n"), std::string::npos);
  EXPECT_NE(text.find("LINE\n8\nMARK\n"), std::string::npos);
  EXPECT_TRUE(text.ends_with("\n0\nEOF\n"));
}

TEST_F(MoldFiles, DxfReaderAcceptsLwPolylineWithCrLf) {
  // A clockwise rectangle as an R2000-style LWPOLYLINE with Windows line ends.
  write_text(file("lw.dxf"),
             "0\r\nSECTION\r\n2\r\nENTITIES\r\n0\r\nLWPOLYLINE\r\n8\r\nCUT\r\n90\r\n4\r\n70\r\n1\r\n"
             "10\r\n0\r\n20\r\n0\r\n10\r\n0\r\n20\r\n50\r\n10\r\n100\r\n20\r\n50\r\n10\r\n100\r\n20\r\n0\r\n"
             "0\r\nENDSEC\r\n0\r\nEOF\r\n");
  const Mold mold = read_mold_dxf(file("lw.dxf"));
  ASSERT_EQ(mold.outline.points.size(), 4u);
  EXPECT_NEAR(signed_area(mold.outline), 5000.0, 1e-9);  // made counter-clockwise
}

TEST_F(MoldFiles, DxfReaderRefusesBadFilesWithOneLine) {
  auto expect_refused = [&](const std::string& name, const std::string& text, const std::string& reason) {
    write_text(file(name), text);
    try {
      read_mold_dxf(file(name));
      ADD_FAILURE() << name << " was accepted";
    } catch (const EngineError& error) {
      const std::string message = error.what();
      EXPECT_NE(message.find(reason), std::string::npos) << message;
      EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
  };
  expect_refused("empty.dxf", "", "no closed outline");
  expect_refused("garbage.dxf", "hello\nworld\n", "not a DXF file");
  expect_refused("odd.dxf", "0\nSECTION\n2\n", "ends in the middle");
  expect_refused("no-cut.dxf", "0\nSECTION\n2\nENTITIES\n0\nLINE\n8\nMARK\n10\n0\n20\n0\n11\n1\n21\n1\n0\nENDSEC\n0\nEOF\n",
                 "no closed outline on layer CUT");
  expect_refused("open.dxf",
                 "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nCUT\n70\n0\n10\n0\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n"
                 "0\nENDSEC\n0\nEOF\n",
                 "not closed");
  expect_refused("nan.dxf",
                 "0\nSECTION\n2\nENTITIES\n0\nLWPOLYLINE\n8\nCUT\n70\n1\n10\nnan\n20\n0\n10\n1\n20\n0\n10\n1\n20\n1\n"
                 "0\nENDSEC\n0\nEOF\n",
                 "not a coordinate");
  std::string two;
  write_mold_dxf(file("one.dxf"), sample_mold());
  two = read_text(file("one.dxf"));
  const auto entities = two.find("ENTITIES\n") + 9;
  const auto seqend = two.find("SEQEND\n8\nCUT\n") + 13;
  two.insert(entities, two.substr(entities, seqend - entities));
  expect_refused("two.dxf", two, "2 outlines on layer CUT");
  EXPECT_THROW(read_mold_dxf(file("missing.dxf")), EngineError);
}

TEST_F(MoldFiles, SvgShowsStretchOutlineMarksAndLegend) {
  const auto patch = test::wavy_disk(360, 4);
  const Mold mold = make_mold("lateral", patch.UV, patch.F, {{"toe", patch.rim_first}});
  Eigen::VectorXd stretch(patch.F.rows());
  for (Eigen::Index f = 0; f < stretch.size(); ++f) stretch(f) = f % 2 ? 1.05 : 1.0;
  write_mold_svg(file("lateral.svg"), mold, patch.UV, patch.F, stretch);
  const std::string svg = read_text(file("lateral.svg"));
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("mm\" height=\""), std::string::npos);
  EXPECT_NE(svg.find("id=\"outline\""), std::string::npos);
  EXPECT_NE(svg.find(">toe</text>"), std::string::npos);
  EXPECT_NE(svg.find("id=\"legend\""), std::string::npos);
  EXPECT_NE(svg.find("1.050"), std::string::npos);  // top of the colour scale (99th percentile)
  EXPECT_NE(svg.find("50 mm"), std::string::npos);
  EXPECT_TRUE(svg.ends_with("</svg>\n"));
  // Stretch values must match the triangles.
  EXPECT_THROW(write_mold_svg(file("bad.svg"), mold, patch.UV, patch.F, Eigen::VectorXd::Ones(3)), EngineError);
  EXPECT_THROW(write_mold_svg(dir_ / "no-such-dir" / "x.svg", mold, patch.UV, patch.F, stretch), EngineError);
}

}  // namespace
}  // namespace lastcut
