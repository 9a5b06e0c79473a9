// The shipped loafer (config/styles/loafer) is what tests/support/loafer_lines.hpp draws on its reference
// last: every point of its lines.obj within 1 um of the drawing and every label of its style.toml within
// 0.01 mm, so the file can be made again and a change of the generated last or of the drawing is seen.
// `LASTCUT_WRITE_LOAFER_LINES=1 test_style_loafer_lines` writes lines.obj again (and prints the labels
// for style.toml) instead of comparing.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "daemon/config/style_folder.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/read_mesh.hpp"
#include "tests/support/lastcut_cli.hpp"
#include "tests/support/loafer_lines.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kLoafer = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles" / "loafer";

constexpr const char* kLinesHeader =
    "# The loafer's style lines on lastcut's generated EU 42 right last (`lastcut generate --size 42 --side right\n"
    "# --triangles 40000`), in that last's frame, mm. apron: the plug's seam, the feather line's outline round\n"
    "# the forefoot moved inward and laid on the last from above, closing across the top cut; vamp and counter:\n"
    "# plane sections. Made by tests/support/loafer_lines.hpp; `LASTCUT_WRITE_LOAFER_LINES=1\n"
    "# test_style_loafer_lines` writes this file again.\n";

TEST(LoaferLines, ShippedFileIsTheDrawingOnTheReferenceLast) {
  const Result<daemon::StyleFolder> folder = daemon::read_style_folder(kLoafer);
  ASSERT_TRUE(folder) << folder.error();
  ASSERT_TRUE(folder->generated_reference);
  const test::TempDir dir("loafer-lines");
  write_mesh(dir / "reference.stl", generate_last(*folder->generated_reference).mesh);
  ScanOptions options;
  options.side = folder->reference_side;
  const ScanResult reference = scan_to_molds(dir / "reference.stl", options);
  const test::LoaferDrawing drawing = test::draw_loafer(read_mesh(dir / "reference.stl").mesh, reference);

  if (std::getenv("LASTCUT_WRITE_LOAFER_LINES")) {
    write_style_lines_obj(dir / "lines.obj", drawing.lines);
    const Status written = write_file_durably(kLoafer / "lines.obj", kLinesHeader + test::read_text(dir / "lines.obj"));
    ASSERT_TRUE(written) << written.error();
    for (const auto& [name, at] : drawing.labels) std::printf("%-16s label = [%.2f, %.2f, %.2f]\n", name.c_str(), at.x(), at.y(), at.z());
    GTEST_SKIP() << "wrote " << (kLoafer / "lines.obj").string();
  }

  ASSERT_EQ(folder->style.lines.size(), drawing.lines.size());
  for (std::size_t i = 0; i < drawing.lines.size(); ++i) {
    const StyleLine& shipped = folder->style.lines[i];
    const StyleLine& drawn = drawing.lines[i];
    EXPECT_EQ(shipped.name, drawn.name);
    ASSERT_EQ(shipped.points_mm.size(), drawn.points_mm.size()) << drawn.name;
    double worst_mm = 0;
    for (std::size_t k = 0; k < drawn.points_mm.size(); ++k)
      worst_mm = std::max(worst_mm, (shipped.points_mm[k] - drawn.points_mm[k]).norm());
    EXPECT_LT(worst_mm, 1e-3) << drawn.name;  // the file holds 4 decimals
  }
  ASSERT_EQ(folder->style.pieces.size(), drawing.labels.size());
  for (const auto& [name, at] : drawing.labels) {
    const auto piece = std::find_if(folder->style.pieces.begin(), folder->style.pieces.end(),
                                    [&](const StylePiece& p) { return p.name == name; });
    ASSERT_NE(piece, folder->style.pieces.end()) << name;
    EXPECT_LT((piece->label_mm - at).norm(), 0.01) << name;  // style.toml holds 2 decimals
  }
}

}  // namespace
}  // namespace lastcut
