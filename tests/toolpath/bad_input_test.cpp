// Bad layouts and bad machine profiles are refused with one clear line, by the engine and by
// the real `lastcut toolpath` command.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "engine/core/engine_error.hpp"
#include "engine/nest/nest_json.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/machine_profile.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "interpreters.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

// The EngineError message of `action`, or "" when it did not throw.
template <typename Action>
std::string error_of(Action action) {
  try {
    action();
  } catch (const EngineError& error) {
    return error.what();
  }
  return "";
}

std::vector<PlacedPiece> pieces_of(const Layout& layout) { return placed_pieces(layout, shoe_instance(), SheetRef{}); }

TEST(ToolpathBadLayout, UnknownItemIsRefused) {
  Layout layout = shoe_layout();
  layout.placements[2].item = 99;
  const std::string message = error_of([&] { pieces_of(layout); });
  EXPECT_NE(message.find("item 99"), std::string::npos) << message;
}

TEST(ToolpathBadLayout, NotANumberIsRefused) {
  for (int field = 0; field < 3; ++field) {
    Layout layout = shoe_layout();
    double& value = field == 0 ? layout.placements[1].x : field == 1 ? layout.placements[1].y : layout.placements[1].rotation_deg;
    value = std::numeric_limits<double>::quiet_NaN();
    const std::string message = error_of([&] { pieces_of(layout); });
    EXPECT_NE(message.find("not a number"), std::string::npos) << message;
  }
  std::vector<PlacedPiece> pieces = pieces_of(shoe_layout());
  pieces[0].outline.points[3].y() = std::numeric_limits<double>::infinity();
  const std::string message = error_of([&] { plan_cut_program(pieces, profile_named("hpgl-pen-plotter")); });
  EXPECT_NE(message.find("not a number"), std::string::npos) << message;
}

TEST(ToolpathBadLayout, PieceOutsideTheWorkAreaIsRefusedNamingThePiece) {
  Layout layout = shoe_layout();
  layout.placements[6].x = 1180.0;  // strap rotated 90 deg: reaches x = 1180 but starts at 1150
  layout.placements[0].x = 1100.0;  // strap: 1100..1220, beyond the plotter's 1189 mm
  const std::string message = error_of([&] { plan_cut_program(pieces_of(layout), profile_named("hpgl-pen-plotter")); });
  EXPECT_NE(message.find("outside the work area"), std::string::npos) << message;
  EXPECT_NE(message.find("piece 1 (item 3 'strap 41.5 left')"), std::string::npos) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << "one line";
  // The same layout fits the larger knife cutter table.
  EXPECT_EQ(error_of([&] { plan_cut_program(pieces_of(layout), profile_named("hpgl-knife-cutter")); }), "");
  Layout below = shoe_layout();
  below.placements[1].y = -5.0;
  EXPECT_NE(error_of([&] { plan_cut_program(pieces_of(below), profile_named("hpgl-knife-cutter")); }).find("outside"),
            std::string::npos);
}

TEST(ToolpathBadLayout, DegeneratePieceIsRefused) {
  std::vector<PlacedPiece> pieces = pieces_of(shoe_layout());
  pieces[2].outline.points = {{10, 10}, {20, 20}, {30, 30}};
  EXPECT_NE(error_of([&] { plan_cut_program(pieces, profile_named("hpgl-pen-plotter")); }).find("no area"), std::string::npos);
}

TEST(ToolpathMachineProfileFile, ShippedProfilesLoadByName) {
  for (const char* name : {"grbl-drag-knife", "grbl-tangential-knife", "hpgl-pen-plotter", "hpgl-knife-cutter"}) {
    const MachineProfile profile = profile_named(name);
    EXPECT_EQ(profile.name, name);
    EXPECT_GT(profile.work_area_x_mm, 500.0);
    EXPECT_TRUE(profile.pen.has_value()) << name;
  }
  EXPECT_EQ(profile_named("grbl-tangential-knife").gcode.rotary_axis, "A");
  EXPECT_EQ(profile_named("grbl-tangential-knife").cut.kind, ToolKind::TangentialKnife);
  EXPECT_EQ(profile_named("grbl-drag-knife").cut.kind, ToolKind::DragKnife);
  EXPECT_EQ(profile_named("hpgl-pen-plotter").native_format, CutFileFormat::Hpgl);
}

TEST(ToolpathMachineProfileFile, MistakesAreErrorsNamingTheKey) {
  const std::string good = read_text(std::filesystem::path(LASTCUT_SOURCE_DIR) / "config/machines/hpgl-knife-cutter.toml");
  auto message_for = [&](const std::string& from, const std::string& to) {
    std::string text = good;
    const size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    return error_of([&] { parse_machine_profile(text, "test.toml"); });
  };
  EXPECT_EQ(error_of([&] { parse_machine_profile(good, "test.toml"); }), "");
  EXPECT_EQ(message_for("speed_mm_s = 30.0", "sped_mm_s = 30.0"), "test.toml: unknown key 'tools.cut.sped_mm_s'");
  EXPECT_EQ(message_for("[label]", "[labels]"), "test.toml: unknown key 'labels'");
  EXPECT_NE(message_for("blade_offset_mm = 0.3", "blade_offset_mm = \"0.3\"").find("'tools.cut.blade_offset_mm' must be a number"), std::string::npos);
  EXPECT_NE(message_for("units_per_mm = 40.0", "units_per_mm = -40.0").find("'hpgl.units_per_mm' must be between"), std::string::npos);
  EXPECT_NE(message_for("kind = \"drag_knife\"", "kind = \"laser\"").find("must be one of"), std::string::npos);
  EXPECT_NE(message_for("work_area_x_mm = 1400.0", "work_area_x_mm = nan").find("must be a number"), std::string::npos);
  EXPECT_NE(message_for("[machine]", "[machine").find("test.toml: line"), std::string::npos);
  // [notch]: the shape and its width, each refused with its key; without the table, today's slit.
  EXPECT_EQ(message_for("shape = \"slit\"", "shape = \"u\""), "test.toml: 'notch.shape' must be one of \"slit\", \"v\"");
  EXPECT_EQ(message_for("v_width_mm = 2.0", "v_width_mm = 0.4"), "test.toml: 'notch.v_width_mm' must be between 0.5 and 10");
  EXPECT_EQ(message_for("v_width_mm = 2.0", "v_width_mm = 10.5"), "test.toml: 'notch.v_width_mm' must be between 0.5 and 10");
  EXPECT_EQ(message_for("v_width_mm = 2.0", "v_width_mm = \"2\""), "test.toml: 'notch.v_width_mm' must be a number");
  EXPECT_EQ(message_for("v_width_mm = 2.0", "v_wdth_mm = 2.0"), "test.toml: unknown key 'notch.v_wdth_mm'");
  EXPECT_EQ(message_for("v_width_mm = 2.0", "depth_mm = 2.0"), "test.toml: unknown key 'notch.depth_mm'");
  const std::string no_notch = good.substr(0, good.find("[notch]"));
  EXPECT_EQ(error_of([&] { parse_machine_profile("notch = 3\n" + no_notch, "test.toml"); }),
            "test.toml: 'notch' must be a table [notch]");
  const MachineProfile slit = parse_machine_profile(no_notch, "test.toml");
  EXPECT_EQ(slit.notch.shape, NotchShape::Slit);
  EXPECT_EQ(slit.notch.v_width_mm, 2.0);
  const std::string missing = error_of([] { load_machine_profile("no-such-machine", {"/nonexistent"}); });
  EXPECT_NE(missing.find("'no-such-machine' not found"), std::string::npos) << missing;
}

// The real command line, on a layout file written by the nester's own JSON writer.
struct CommandResult {
  int exit_code;
  std::string output;
};

CommandResult run_lastcut(const std::string& arguments) {
  const std::string binary = std::string(LASTCUT_BINARY_DIR) + "/bin/lastcut";
  if (!std::filesystem::exists(binary)) throw std::runtime_error("lastcut binary not built: " + binary);
  const std::string command = "'" + binary + "' " + arguments + " 2>&1; echo \"exit=$?\"";
  const std::string output = run_command(command);
  const size_t at = output.rfind("exit=");
  return {std::stoi(output.substr(at + 5)), output.substr(0, at)};
}

TEST(ToolpathCommand, WritesEveryFormatAndRefusesBadLayouts) {
  const auto dir = scratch_dir("command");
  write_layout(dir / "layout.json", shoe_layout(), shoe_instance());
  for (const char* format : {"hpgl", "gcode", "dxf", "svg"}) {
    const auto out = dir / (std::string("job.") + format);
    const CommandResult result = run_lastcut("toolpath '" + (dir / "layout.json").string() +
                                             "' --profile grbl-drag-knife --format " + format + " -o '" + out.string() + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("cut length"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("travel length"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("tool lifts"), std::string::npos) << result.output;
    EXPECT_GT(std::filesystem::file_size(out), 1000u) << format;
  }
  // By path, too.
  const std::string profile_path = std::string(LASTCUT_SOURCE_DIR) + "/config/machines/hpgl-pen-plotter.toml";
  EXPECT_EQ(run_lastcut("toolpath '" + (dir / "layout.json").string() + "' --profile '" + profile_path + "' -o '" +
                        (dir / "job.plt").string() + "'").exit_code, 0);

  Layout outside = shoe_layout();
  outside.placements[0].x = 1250.0;
  write_layout(dir / "outside.json", outside, shoe_instance());
  const CommandResult refused = run_lastcut("toolpath '" + (dir / "outside.json").string() +
                                            "' --profile hpgl-pen-plotter -o '" + (dir / "outside.plt").string() + "'");
  EXPECT_EQ(refused.exit_code, 1);
  EXPECT_NE(refused.output.find("lastcut toolpath: error: piece 1 (item 3 'strap 41.5 left') reaches"), std::string::npos)
      << refused.output;
  EXPECT_FALSE(std::filesystem::exists(dir / "outside.plt")) << "no cut file for a refused layout";

  std::string text = read_text(dir / "layout.json");
  nlohmann::json json = nlohmann::json::parse(text);
  json["placements"][1]["item"] = 77;
  write_text(dir / "unknown.json", json.dump());
  const CommandResult unknown = run_lastcut("toolpath '" + (dir / "unknown.json").string() + "' --profile hpgl-pen-plotter");
  EXPECT_EQ(unknown.exit_code, 1);
  EXPECT_NE(unknown.output.find("item 77"), std::string::npos) << unknown.output;

  const CommandResult no_profile = run_lastcut("toolpath '" + (dir / "layout.json").string() + "' --profile nope");
  EXPECT_EQ(no_profile.exit_code, 1);
  EXPECT_NE(no_profile.output.find("machine profile 'nope' not found"), std::string::npos) << no_profile.output;
}

}  // namespace
}  // namespace lastcut::test
