// `lastcut style check` through the real binary. The shipped derby and loafer are OK: one line per piece
// on standard output, and an SVG (by default in the style folder) that holds, read here as text, one
// filled region per piece of style.toml under its name, whose area (shoelace over its rings, both halves)
// is the piece's printed 3D area within 2 % (the halves' flattenings hardly stretch), and one name text
// per piece. Broken styles are refused with their exact line, the folder reader's with exit 2 and the
// engine's with exit 1, and write no picture.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/lastcut_cli.hpp"
#include "tests/support/temp_dir.hpp"

namespace lastcut {
namespace {

namespace fs = std::filesystem;

const fs::path kStyles = fs::path(LASTCUT_SOURCE_DIR) / "config" / "styles";

// The piece names of a style.toml, in order, read from its text.
std::vector<std::string> piece_names(const std::string& toml) {
  std::vector<std::string> names;
  const std::regex piece(R"re(\[\[piece\]\]\s*\nname = "([^"]+)")re");
  for (auto it = std::sregex_iterator(toml.begin(), toml.end(), piece); it != std::sregex_iterator(); ++it) names.push_back((*it)[1]);
  return names;
}

// The area enclosed by an SVG path of straight segments (M, L, Z), its rings' signed areas added up: one
// winding for outer rings and the other for holes, as a union of triangles comes out of Clipper.
double path_area_mm2(const std::string& d) {
  double twice_area = 0;
  std::vector<std::pair<double, double>> ring;
  const auto close_ring = [&] {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const auto& [x0, y0] = ring[i];
      const auto& [x1, y1] = ring[(i + 1) % ring.size()];
      twice_area += x0 * y1 - x1 * y0;
    }
    ring.clear();
  };
  std::istringstream in(d);
  char command = 0;
  while (in >> command) {
    if (command == 'Z') {
      close_ring();
      continue;
    }
    double x = 0, y = 0;
    char comma = 0;
    in >> x >> comma >> y;
    ring.emplace_back(x, y);
  }
  close_ring();
  return std::abs(twice_area) / 2;
}

// A regular expression that matches `text` to the letter.
std::string literal(const std::string& text) { return std::regex_replace(text, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)"); }

// Each name in `names` with how often `pattern` (its group 1 the name) occurs in `text`.
std::map<std::string, int> counted(const std::string& text, const std::regex& pattern) {
  std::map<std::string, int> count;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), pattern); it != std::sregex_iterator(); ++it) ++count[(*it)[1]];
  return count;
}

// The style folder `name` copied to `dir`, the text `from` of its style.toml replaced by `to`.
fs::path copied_style(const fs::path& dir, const std::string& name, const std::string& from = "", const std::string& to = "") {
  const fs::path folder = dir / name;
  fs::create_directories(folder);
  fs::copy_file(kStyles / name / "lines.obj", folder / "lines.obj");
  std::string toml = test::read_text(kStyles / name / "style.toml");
  if (!from.empty()) {
    const std::size_t at = toml.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    if (at != std::string::npos) toml.replace(at, from.size(), to);
  }
  std::ofstream(folder / "style.toml") << toml;
  return folder;
}

void expect_checked(const fs::path& style, const std::string& extra_arguments, const fs::path& svg_path, const fs::path& scratch) {
  const test::CommandRun run = test::run_lastcut("style check '" + style.string() + "'" + extra_arguments, scratch);
  ASSERT_EQ(run.exit_code, 0) << run.all();
  const std::vector<std::string> names = piece_names(test::read_text(style / "style.toml"));
  ASSERT_GE(names.size(), 4u);
  EXPECT_NE(run.out.find("is OK: " + std::to_string(names.size()) + " pieces"), std::string::npos) << run.out;

  // One printed line per piece: "NAME  MATERIAL  xQ  AREA mm2  edges (mm): ...".
  std::map<std::string, double> printed_mm2;
  std::istringstream out(run.out);
  const std::regex area(R"((\d+) mm2  edges \(mm\): )");
  for (std::string line; std::getline(out, line);)
    for (const std::string& name : names)
      if (std::smatch found; line.starts_with(name + " ") && std::regex_search(line, found, area)) printed_mm2[name] = std::stod(found[1]);

  const std::string svg = test::read_text(svg_path);
  const std::regex region(R"re(<path class="piece-region" data-piece="([^"]+)"[^>]* d="([^"]+)"/>)re");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), region); it != std::sregex_iterator(); ++it) {
    if (const std::string name = (*it)[1]; printed_mm2.count(name)) {
      EXPECT_NEAR(path_area_mm2((*it)[2]), printed_mm2[name], 0.02 * printed_mm2[name]) << name;
    }
  }
  const std::map<std::string, int> regions = counted(svg, region);
  const std::map<std::string, int> texts = counted(svg, std::regex(R"re(<text class="piece-name"[^>]*>([^<]+)</text>)re"));
  EXPECT_EQ(regions.size(), names.size());
  EXPECT_EQ(texts.size(), names.size());
  for (const std::string& name : names) {
    EXPECT_EQ(printed_mm2.count(name), 1u) << name << ": no line in " << run.out;
    EXPECT_EQ(regions.count(name) ? regions.at(name) : 0, 1) << name << ": one region per piece";
    EXPECT_EQ(texts.count(name) ? texts.at(name) : 0, 1) << name << ": its name once on the sheet";
  }
}

TEST(CliStyleCheck, ShippedStylesAreOkAndDrawn) {
  const test::TempDir dir("cli-style-check");
  // The derby copied and drawn into its own folder (the default picture); the loafer where it is, drawn elsewhere.
  const fs::path derby = copied_style(dir, "derby");
  expect_checked(derby, "", derby / "check.svg", dir);
  expect_checked(kStyles / "loafer", " -o '" + (dir / "loafer.svg").string() + "'", dir / "loafer.svg", dir);
}

struct Refusal {
  std::string from, to;  // the change to the loafer's style.toml
  int exit_code;
  std::string error;     // all of standard error, as a regular expression
};

TEST(CliStyleCheck, BrokenStylesAreRefusedWithTheirLine) {
  const test::TempDir dir("cli-style-check-bad");
  const std::vector<Refusal> refusals = {
      // The vamp's label 50 mm above the side of the forefoot, off the last.
      {"label = [199.83, -40.55, 45.50]", "label = [199.83, -40.55, 95.50]", 1,
       literal("lastcut: error: the label of piece vamp is not on the reference last's upper\n")},
      // A piece without its label: the folder reader names the key.
      {"label = [199.83, -40.55, 45.50]\n", "", 2,
       literal("lastcut: error: " + (dir / "loafer" / "style.toml").string() + ": piece[2].label: missing (required)\n")},
      // The apron's piece left out: its region has no label.
      {"[[piece]]\nname = \"apron\"\nlabel = [215.12, 0.08, 49.84]\nmaterial = \"upper leather\"\nquantity = 1\n"
       "grain_tolerance_deg = 10.0   # along the backbone\nmin_quality = 3\n", "", 1,
       R"(lastcut: error: the region at the (medial|lateral) forme \(-?\d+, -?\d+\) mm has no piece: a label is missing or a line does not reach an edge\n)"},
      // A rule for a line the lines file does not have.
      {"[[line]]\nname = \"apron\"", "[[line]]\nname = \"aprn\"", 1,
       literal("lastcut: error: a line rule names the line aprn, which the style's lines do not have\n")},
  };
  for (const Refusal& refusal : refusals) {
    SCOPED_TRACE(refusal.error);
    fs::remove_all(dir / "loafer");
    const fs::path style = copied_style(dir, "loafer", refusal.from, refusal.to);
    const test::CommandRun run = test::run_lastcut("style check '" + style.string() + "'", dir);
    EXPECT_EQ(run.exit_code, refusal.exit_code) << run.all();
    EXPECT_TRUE(std::regex_match(run.err, std::regex(refusal.error))) << run.err;
    EXPECT_EQ(run.out, "");
    EXPECT_FALSE(fs::exists(style / "check.svg"));
  }
}

}  // namespace
}  // namespace lastcut
