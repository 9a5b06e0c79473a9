// DXF-AAMA interop (issue 35): one pattern set drawn with ezdxf's own API (aama_ezdxf_write.py, as
// R12 and as R2000) and the same pieces written by lastcut's writer read back into the same pieces:
// names, labels and quantities; areas within 0.01 %; each notch (count, position within 0.01 mm,
// direction) and the grain line kept. The reference is what the script says it drew (its JSON),
// not what lastcut reads. The test is skipped only when Debian's interpreter cannot import ezdxf;
// scripts/setup.sh installs python3-ezdxf, so CI runs it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/pattern/aama_dxf.hpp"
#include "tests/support/child_process.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut::test {
namespace {

constexpr double kAreaTolerance = 1e-4;       // relative: 0.01 %
constexpr double kPositionTolerance_mm = 0.01;

Point2 point_of(const nlohmann::json& xy) { return {xy[0].get<double>(), xy[1].get<double>()}; }

double area_of(const std::vector<Point2>& outline) { return std::abs(signed_area(Polygon2{outline})); }

// What the script drew, as pieces.
std::vector<PatternPiece> drawn_pieces(const nlohmann::json& reference) {
  std::vector<PatternPiece> pieces;
  for (const nlohmann::json& drawn : reference["pieces"]) {
    PatternPiece piece;
    piece.name = drawn["name"];
    piece.size = drawn["size"];
    piece.category = drawn["category"];
    piece.quantity = drawn["quantity"];
    for (const nlohmann::json& p : drawn["cut_line"]) piece.cut_line_mm.push_back(point_of(p));
    for (const nlohmann::json& notch : drawn["notches"])
      piece.notches.push_back({point_of(notch["at"]), point_of(notch["inward"])});
    if (!drawn["grain_line"].is_null())
      piece.grain_line_mm = std::array<Point2, 2>{point_of(drawn["grain_line"][0]), point_of(drawn["grain_line"][1])};
    pieces.push_back(piece);
  }
  return pieces;
}

// The largest relative area difference seen, for the figures in docs/aama-dxf.md.
double expect_same_pieces(const std::vector<PatternPiece>& read, const std::vector<PatternPiece>& drawn) {
  double worst_area = 0;
  EXPECT_EQ(read.size(), drawn.size());
  for (size_t i = 0; i < std::min(read.size(), drawn.size()); ++i) {
    const PatternPiece& r = read[i];
    const PatternPiece& d = drawn[i];
    SCOPED_TRACE(d.name);
    EXPECT_EQ(r.name, d.name);
    EXPECT_EQ(r.size, d.size);
    EXPECT_EQ(r.category, d.category);
    EXPECT_EQ(r.quantity, d.quantity);
    const double difference = std::abs(area_of(r.cut_line_mm) - area_of(d.cut_line_mm)) / area_of(d.cut_line_mm);
    EXPECT_LE(difference, kAreaTolerance) << "area " << area_of(r.cut_line_mm) << " mm^2, drawn " << area_of(d.cut_line_mm);
    worst_area = std::max(worst_area, difference);
    EXPECT_EQ(r.notches.size(), d.notches.size());
    for (size_t k = 0; k < std::min(r.notches.size(), d.notches.size()); ++k) {
      EXPECT_LE((r.notches[k].at_mm - d.notches[k].at_mm).norm(), kPositionTolerance_mm) << "notch " << k;
      EXPECT_LE((r.notches[k].inward - d.notches[k].inward).norm(), 1e-6) << "notch " << k;
    }
    EXPECT_EQ(r.grain_line_mm.has_value(), d.grain_line_mm.has_value());
    if (r.grain_line_mm && d.grain_line_mm) {
      for (int end = 0; end < 2; ++end)
        EXPECT_LE(((*r.grain_line_mm)[end] - (*d.grain_line_mm)[end]).norm(), kPositionTolerance_mm) << "grain end " << end;
    }
  }
  return worst_area;
}

bool ezdxf_importable(const TempDir& dir) {
  return run_to_exit({"/usr/bin/python3", "-c", "import ezdxf"}, dir / "import.log", 60.0) == 0;
}

nlohmann::json write_with_ezdxf(const TempDir& dir, const std::string& version) {
  const std::filesystem::path dxf = dir / (version + ".dxf"), reference = dir / (version + ".json");
  const int status = run_to_exit({"/usr/bin/python3", std::string(LASTCUT_SOURCE_DIR) + "/tests/pattern/aama_ezdxf_write.py",
                                  version, dxf.string(), reference.string()},
                                 dir / (version + ".log"), 120.0);
  EXPECT_EQ(status, 0) << "aama_ezdxf_write.py " << version << " failed: see " << (dir / (version + ".log"));
  return nlohmann::json::parse(std::ifstream(reference));
}

TEST(AamaDxfInterop, EzdxfAndLastcutSetsReadBackIntoTheSamePieces) {
  const TempDir dir("aama-interop");
  if (!ezdxf_importable(dir)) GTEST_SKIP() << "/usr/bin/python3 cannot import ezdxf (scripts/setup.sh installs python3-ezdxf)";
  for (const std::string version : {"R12", "R2000"}) {
    SCOPED_TRACE("ezdxf " + version);
    const nlohmann::json reference = write_with_ezdxf(dir, version);
    const std::vector<PatternPiece> drawn = drawn_pieces(reference);
    const std::vector<PatternPiece> from_ezdxf = read_aama_dxf(dir / (version + ".dxf"));
    const double ezdxf_area = expect_same_pieces(from_ezdxf, drawn);
    // The pieces lastcut read, written by lastcut's writer and read once more: nothing drifts.
    write_aama_dxf(dir / (version + "-lastcut.dxf"), from_ezdxf);
    const double lastcut_area = expect_same_pieces(read_aama_dxf(dir / (version + "-lastcut.dxf")), drawn);
    std::cout << "ezdxf " << reference["ezdxf"].get<std::string>() << " " << version
              << ": largest area difference " << ezdxf_area * 100 << " % (ezdxf's file), " << lastcut_area * 100
              << " % (lastcut's writer)\n";
  }
  // The same pieces written by lastcut's writer straight from what the script drew.
  const std::vector<PatternPiece> drawn = drawn_pieces(nlohmann::json::parse(std::ifstream(dir / "R12.json")));
  write_aama_dxf(dir / "lastcut.dxf", drawn);
  expect_same_pieces(read_aama_dxf(dir / "lastcut.dxf"), drawn);
}

}  // namespace
}  // namespace lastcut::test
