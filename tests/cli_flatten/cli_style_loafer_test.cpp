// The shipped loafer (config/styles/loafer) cut by the real `lastcut style pieces` from generated lasts of
// other sizes and either foot (it is drawn on an EU 42 right last), posed, as a shop runs it. Checked on
// pieces.json: the five pieces by name, their 3D areas adding up to the upper's within 0.1 % (summed
// here), the underlay on the piece under each line, 18 mm on every stretch on the feather line and one on every piece but the apron (which lies
// on top of the forefoot), the top edge folded by 5 mm, no flipped triangle; each piece's DXF read back.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/mold/mold_dxf.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kLoafer = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "loafer";

TEST(CliStyleLoafer, ShippedLoaferOnOtherSizesAndTheLeftFoot) {
  const test::TempDir dir("cli-style-loafer");
  for (const auto& [size, side] : std::vector<std::pair<int, FootSide>>{{38, FootSide::Right}, {46, FootSide::Left}}) {
    SCOPED_TRACE("EU " + std::to_string(size));
    LastParams params = LastParams::for_eu_size(size, side);
    params.target_triangles = 30000;
    params.random_pose = true;
    params.seed = static_cast<std::uint64_t>(size);
    write_mesh(dir / "last.stl", generate_last(params).mesh);
    const fs::path out = dir / ("out-" + std::to_string(size));
    const test::CommandRun run = test::run_lastcut("style pieces '" + kLoafer.string() + "' '" + (dir / "last.stl").string() +
                                                       "' -o '" + out.string() + "' --side " + (side == FootSide::Left ? "left" : "right"),
                                                   dir);
    ASSERT_EQ(run.exit_code, 0) << run.all();

    const nlohmann::json report = nlohmann::json::parse(test::read_text(out / "pieces.json"));
    std::set<std::string> names;
    double pieces_mm2 = 0;
    for (const auto& piece : report["pieces"]) {
      const std::string name = piece["name"];
      names.insert(name);
      pieces_mm2 += piece["area_3d_mm2"].get<double>();
      EXPECT_EQ(piece["flipped_triangles"], 0) << name;
      int lasting = 0, folded = 0;
      for (const auto& edge : piece["edges"]) {
        if (edge["on"] == "feather line") {
          EXPECT_EQ(edge["allowance_mm"], 18.0) << name;
          ++lasting;
        }
        if (edge["on"] == "top edge") {
          EXPECT_EQ(edge["allowance_mm"], 5.0) << name;
          ++folded;
        }
        // The vamp lies under the apron and the quarters, the quarters under the counter (8 mm underlay);
        // the piece on top of a line keeps a raw edge.
        const std::string on = edge["on"];
        if (on.starts_with("line ")) {
          const bool under = name == "vamp" || (name.ends_with("quarter") && on == "line counter");
          EXPECT_EQ(edge["allowance_mm"], under ? 8.0 : 0.0) << name << " on " << on;
        }
      }
      EXPECT_EQ(lasting > 0, name != "apron") << name << ": the apron alone does not reach the feather line";
      EXPECT_EQ(folded > 0, name != "counter") << name << ": every piece but the counter reaches the top edge";
      EXPECT_GT(read_mold_dxf(out / piece["file"].get<std::string>()).outline.points.size(), 10u) << name;
    }
    EXPECT_EQ(names, (std::set<std::string>{"apron", "vamp", "medial quarter", "lateral quarter", "counter"}));
    const double upper_mm2 = report["upper_area_3d_mm2"];
    EXPECT_NEAR(pieces_mm2, upper_mm2, 1e-3 * upper_mm2);
    EXPECT_GT(upper_mm2, 30000);  // a whole upper, not a part of one
  }
}

}  // namespace
}  // namespace lastcut
