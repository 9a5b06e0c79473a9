// The written DXF-AAMA file read by programs that are not ours:
//  - ezdxf (Debian python3-ezdxf) audits it and reports what each inserted block holds
//    (aama_ezdxf_report.py); this test compares that with the pieces written;
//  - LibreCAD renders it to PDF headless (`librecad dxf2pdf`, Qt's offscreen platform), poppler's
//    pdftoppm turns the page into a grey picture, and the picture must show the pieces side by side:
//    as many separate columns of ink as pieces, each as wide as its piece relative to the layout.
// A missing program fails the test (it is an install step missing: scripts/setup.sh), never skips it.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "aama_test_files.hpp"
#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

std::vector<PatternPiece> layout_pieces() {
  PatternPiece quarter = sample_piece("quarter", "42", Point2(-300.0, 7.0), 90.0, 45.0);
  quarter.quantity = 4;
  quarter.grain_line_mm.reset();
  return {sample_piece("vamp", "42", Point2(130.25, 40.5), 120.0, 80.0), quarter,
          sample_piece("vamp", "43", Point2(0.0, 0.0), 125.0, 83.0)};
}

std::string log_text(const std::filesystem::path& log) {
  std::ifstream in(log);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs argv; a failure (also: the program is not installed, exit 127) fails the test with its log.
void run(const std::vector<std::string>& argv, const std::filesystem::path& log) {
  const int status = run_to_exit(argv, log, 120.0);
  ASSERT_EQ(status, 0) << argv[0] << " " << argv[1] << " failed; its output:\n" << log_text(log);
}

TEST(AamaDxfIndependentReaders, EzdxfAuditsCleanAndFindsEveryPiece) {
  TempDir dir("aama-ezdxf");
  const std::vector<PatternPiece> pieces = layout_pieces();
  write_aama_dxf(dir / "derby.dxf", pieces);
  // Debian's interpreter, where Debian's python3-ezdxf lives: a python3 earlier on PATH (pyenv,
  // a virtualenv) does not see it.
  run({"/usr/bin/python3", std::string(LASTCUT_SOURCE_DIR) + "/tests/pattern/aama_ezdxf_report.py",
       (dir / "derby.dxf").string(), (dir / "report.json").string()},
      dir / "ezdxf.log");
  const nlohmann::json report = nlohmann::json::parse(std::ifstream(dir / "report.json"));
  EXPECT_EQ(report["dxfversion"], "AC1009");
  EXPECT_EQ(report["insunits"], 4);
  EXPECT_TRUE(report["audit_errors"].empty()) << report["audit_errors"].dump();
  EXPECT_TRUE(report["audit_fixes"].empty()) << report["audit_fixes"].dump();
  EXPECT_EQ(report["modelspace_texts"], nlohmann::json::array({"Units: METRIC"}));
  const std::vector<std::string> block_names = {"vamp", "quarter", "vamp_2"};
  ASSERT_EQ(report["pieces"].size(), pieces.size());
  double previous_right = -1e300;
  for (size_t i = 0; i < pieces.size(); ++i) {
    const PatternPiece& piece = pieces[i];
    const nlohmann::json& found = report["pieces"][i];
    SCOPED_TRACE(block_names[i]);
    EXPECT_EQ(found["block"], block_names[i]);
    EXPECT_EQ(found["closed_cut_lines"], nlohmann::json::array({piece.cut_line_mm.size()}));
    EXPECT_EQ(found["open_cut_lines"], 0);
    EXPECT_EQ(found["notch_lines"], 0);
    ASSERT_EQ(found["notch_points"].size(), piece.notches.size());
    for (size_t k = 0; k < piece.notches.size(); ++k) {
      const PatternNotch& notch = piece.notches[k];
      const nlohmann::json& point = found["notch_points"][k];
      EXPECT_NEAR(point[0].get<double>(), notch.at_mm.x(), 1e-6);
      EXPECT_NEAR(point[1].get<double>(), notch.at_mm.y(), 1e-6);
      const double angle = point[2].get<double>() * M_PI / 180.0;
      EXPECT_LT((Point2(std::cos(angle), std::sin(angle)) - notch.inward).norm(), 1e-6) << "notch " << k;
    }
    ASSERT_EQ(found["grain_lines"].size(), piece.grain_line_mm ? 1u : 0u);
    if (piece.grain_line_mm) {
      const nlohmann::json& line = found["grain_lines"][0];
      EXPECT_NEAR(line[0].get<double>(), (*piece.grain_line_mm)[0].x(), 1e-6);
      EXPECT_NEAR(line[3].get<double>(), (*piece.grain_line_mm)[1].y(), 1e-6);
    }
    // ezdxf's counts of a closed line include its closing point again, as PatternPiece's do.
    std::vector<size_t> internal, sew;
    for (const auto& line : piece.internal_lines_mm) internal.push_back(line.size());
    for (const auto& line : piece.sew_lines_mm) sew.push_back(line.size());
    EXPECT_EQ(found["internal_lines"], nlohmann::json(internal));
    EXPECT_EQ(found["sew_lines"], nlohmann::json(sew));
    const nlohmann::json& texts = found["texts"];
    for (const std::string& expected : {"Piece Name: " + piece.name, "Quantity: " + std::to_string(piece.quantity),
                                       "Size: " + piece.size, "Style Name: " + piece.style, "Category: " + piece.category,
                                       "Annotation: " + piece.annotation})
      EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected << " in " << texts.dump();
    // Placed side by side: each cut line right of the previous one.
    const nlohmann::json& box = found["cut_box"];
    EXPECT_GT(box[0].get<double>(), previous_right) << box.dump();
    previous_right = box[2].get<double>();
  }
}

struct GreyPicture {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;  // row by row, 0 black .. 255 white
};

// A binary PGM (P5, maxval 255) as pdftoppm -gray writes it.
GreyPicture read_pgm(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxval = 0;
  GreyPicture picture;
  in >> magic >> picture.width >> picture.height >> maxval;
  in.get();  // the one whitespace byte before the pixels
  if (magic != "P5" || maxval != 255 || picture.width <= 0 || picture.height <= 0) return {};
  picture.pixels.resize(static_cast<size_t>(picture.width) * picture.height);
  in.read(reinterpret_cast<char*>(picture.pixels.data()), static_cast<std::streamsize>(picture.pixels.size()));
  return in ? picture : GreyPicture{};
}

// Runs of columns holding ink (a pixel darker than mid grey), as [first, last] column pairs.
std::vector<std::pair<int, int>> ink_columns(const GreyPicture& picture) {
  std::vector<std::pair<int, int>> runs;
  for (int x = 0; x < picture.width; ++x) {
    bool ink = false;
    for (int y = 0; y < picture.height && !ink; ++y) ink = picture.pixels[static_cast<size_t>(y) * picture.width + x] < 128;
    if (!ink) continue;
    if (!runs.empty() && runs.back().second == x - 1) {
      runs.back().second = x;
    } else {
      runs.emplace_back(x, x);
    }
  }
  return runs;
}

TEST(AamaDxfIndependentReaders, LibreCadDrawsThePiecesSideBySide) {
  TempDir dir("aama-librecad");
  const std::vector<PatternPiece> pieces = layout_pieces();
  write_aama_dxf(dir / "derby.dxf", pieces);
  // dxf2pdf: -a fits the drawing to the (A4) page, -m prints monochrome, -t names the folder of
  // derby.pdf (its -o takes no file name in LibreCAD 2.2). HOME keeps LibreCAD's settings file here.
  run({"env", "QT_QPA_PLATFORM=offscreen", "HOME=" + dir.path().string(), "librecad", "dxf2pdf", "-a", "-m", "-t",
       dir.path().string(), (dir / "derby.dxf").string()},
      dir / "librecad.log");
  ASSERT_TRUE(std::filesystem::exists(dir / "derby.pdf")) << log_text(dir / "librecad.log");
  run({"pdftoppm", "-gray", "-r", "100", "-singlefile", (dir / "derby.pdf").string(), (dir / "page").string()},
      dir / "pdftoppm.log");
  const GreyPicture page = read_pgm(dir / "page.pgm");
  ASSERT_GT(page.width, 500) << "no readable picture";
  // One column of ink per piece, the gaps between them blank: the pieces are drawn, apart.
  const std::vector<std::pair<int, int>> columns = ink_columns(page);
  ASSERT_EQ(columns.size(), pieces.size());
  // Each as wide as its piece (its cut line's width) relative to the whole layout, within 2 %.
  std::vector<double> widths_mm;
  double layout_mm = 20.0 * static_cast<double>(pieces.size() - 1);  // the gaps
  for (const PatternPiece& piece : pieces) {
    double low = 1e300, high = -1e300;
    for (const Point2& p : piece.cut_line_mm) low = std::min(low, p.x()), high = std::max(high, p.x());
    widths_mm.push_back(high - low);
    layout_mm += high - low;
  }
  const double layout_px = columns.back().second - columns.front().first + 1;
  EXPECT_GT(layout_px, 0.8 * page.width) << "fitted to the page";
  for (size_t i = 0; i < pieces.size(); ++i) {
    const double share = (columns[i].second - columns[i].first + 1) / layout_px;
    EXPECT_NEAR(share, widths_mm[i] / layout_mm, 0.02) << "piece " << i;
  }
}

}  // namespace
}  // namespace lastcut::test
