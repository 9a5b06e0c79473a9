// `lastcut style new REFERENCE_SCAN -o DIR [--side left|right]`: the start of a style drawn the way
// pattern makers work (issue 34, point 1). The reference last goes through the scan-to-molds pipeline;
// DIR gets a copy of the scan (reference.<ext>), its forme to draw on (forme.dxf, engine/style/forme_dxf.hpp)
// and a commented style.toml naming both, with the default allowances and one example of each table.
// Then a few lines say what the pattern maker does next (docs/style-authoring.md).
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include "daemon/cli/cli_support.hpp"
#include "daemon/cli/commands.hpp"
#include "engine/core/durable_file.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/forme_dxf.hpp"
#include "engine/style/forme_layout.hpp"

namespace lastcut::cli {
namespace {

namespace fs = std::filesystem;

struct StyleNewArguments {
  std::string scan, out_dir, side;  // side: "", left or right
};

int refuse_style_new(const std::string& reason, int code) {
  print_error(reason);
  return code;
}

// A TOML basic string holding `text`.
std::string toml_string(const std::string& text) {
  std::string quoted = "\"";
  for (const char c : text) {
    if (c == '"' || c == '\\') quoted += '\\';
    if (c != '\n' && c != '\r') quoted += c;
  }
  return quoted + "\"";
}

std::string style_template(const std::string& name, const std::string& scan_file, FootSide side) {
  return "# Style " + name + ", drawn on the forme of the reference last below (made by `lastcut style new`).\n"
         "# Draw it in forme.dxf (docs/style-authoring.md): each style line on a layer LINE-<name>\n"
         "# (LINE-medial-<name> or LINE-lateral-<name> for one half), each piece's name as a TEXT on layer\n"
         "# PIECES inside the piece. Then: lastcut style pieces THIS_FOLDER SCAN -o OUT\n"
         "name = " + toml_string(name) + "\n"
         "forme = \"forme.dxf\"\n"
         "# thickness_mm = 1.2        # the leather's: pieces flattened from its mid-surface (0 or absent: off)\n"
         "\n"
         "[reference]                # the last forme.dxf was made from: keep it here, unchanged\n"
         "scan = " + toml_string(scan_file) + "\n"
         "side = \"" + (side == FootSide::Left ? "left" : "right") + "\"\n"
         "\n"
         "[allowances]               # mm, shoemaking's defaults\n"
         "lasting = 18.0             # the feather line, folded under the insole\n"
         "folding = 5.0              # the top edge\n"
         "underlay = 8.0             # a piece lying under its neighbour along a style line\n"
         "butted = 0.0               # the other side of a line, and the cut seams\n"
         "\n"
         "# Which piece lies under its neighbour along a line (it gets the underlay there):\n"
         "# [[line]]\n"
         "# name = \"vamp\"\n"
         "# under = \"vamp\"\n"
         "\n"
         "# A stretch of a centre seam the pieces are cut apart along, from where a line crosses it up to the\n"
         "# top edge (a derby's lacing opening); elsewhere a piece runs on across the seam:\n"
         "# [[seam_cut]]\n"
         "# seam = \"front\"           # \"front\" or \"back\"\n"
         "# from_line = \"vamp\"\n"
         "\n"
         "# A piece's material and quantity (a piece with a text and no [[piece]]: upper leather, 1 per shoe):\n"
         "# [[piece]]\n"
         "# name = \"vamp\"\n"
         "# material = \"upper leather\"\n"
         "# quantity = 1\n";
}

int run_style_new(const StyleNewArguments& arguments) {
  if (!arguments.side.empty() && arguments.side != "left" && arguments.side != "right")
    return refuse_style_new("--side must be left or right, not \"" + arguments.side + "\"", 2);
  const fs::path dir = arguments.out_dir;
  for (const char* file : {"style.toml", "forme.dxf"})
    if (fs::exists(dir / file))
      return refuse_style_new((dir / file).string() + " exists: a style is made in a new folder, its drawing is never overwritten", 2);
  try {
    const ScanResult reference = segmented(arguments.scan, side_named(arguments.side));
    const FormeLayout layout = forme_layout(reference);
    fs::create_directories(dir);
    const std::string scan_file = "reference" + fs::path(arguments.scan).extension().string();
    std::string name = fs::absolute(dir).lexically_normal().filename().string();
    if (name.empty()) name = fs::absolute(dir).lexically_normal().parent_path().filename().string();
    const Status written = [&] {
      if (Status copied = copy_file_durably(arguments.scan, dir / scan_file); !copied) return copied;
      if (Status forme = write_file_durably(dir / "forme.dxf", forme_dxf(layout)); !forme) return forme;
      return write_file_durably(dir / "style.toml", style_template(name, scan_file, *reference.side));
    }();
    if (!written) return refuse_style_new(written.error(), 1);
    std::printf("style %s in %s: %s (the reference last), forme.dxf, style.toml\n", name.c_str(), dir.c_str(), scan_file.c_str());
    std::printf("the forme: lateral half as flattened, medial half mirrored onto it (centre lines %.2f mm rms, %.2f mm at worst)\n",
                layout.centre_rms_mm, layout.centre_worst_mm);
    std::printf("next:\n"
                "  1. open forme.dxf in a CAD program (LibreCAD); draw each style line on a layer LINE-<name>\n"
                "     (LINE-medial-<name> or LINE-lateral-<name>: one half), ending on an edge or another line\n"
                "  2. write each piece's name as a TEXT on layer PIECES inside it; save as DXF in place\n"
                "  3. in style.toml: which piece lies under each line, the seam cuts, materials\n"
                "  4. lastcut style pieces %s SCAN -o OUT\n",
                dir.c_str());
    return 0;
  } catch (const std::exception& error) {  // EngineError among them: one line either way
    std::string reason = error.what();
    for (char& c : reason)
      if (c == '\n' || c == '\r') c = ' ';
    return refuse_style_new(reason, 1);
  }
}

}  // namespace

void add_style_new_command(CLI::App& style, int& exit_code) {
  auto arguments = std::make_shared<StyleNewArguments>();
  auto* make = style.add_subcommand("new", "a new style folder: the reference last's forme (DXF) to draw the style on, style.toml");
  make->add_option("reference", arguments->scan, "scan of the reference last the style is drawn on")->required();
  make->add_option("-o,--out", arguments->out_dir, "the style folder (created; must not hold a style yet)")->required();
  make->add_option("--side", arguments->side, "the foot the reference last is for (left or right)");
  make->callback([arguments, &exit_code] { exit_code = run_style_new(*arguments); });
}

}  // namespace lastcut::cli
