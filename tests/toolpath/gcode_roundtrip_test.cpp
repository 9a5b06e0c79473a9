// G-code written by lastcut, read back by cncjs' gcode-parser and gcode-toolpath under node
// (interpreters nobody on the project wrote).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "engine/toolpath/drag_knife.hpp"
#include "engine/toolpath/gcode_writer.hpp"
#include "engine/toolpath/layout_pieces.hpp"
#include "engine/toolpath/plan_cut_program.hpp"
#include "interpreters.hpp"
#include "test_layouts.hpp"

namespace lastcut::test {
namespace {

constexpr double kTolerance_mm = 0.025;

struct GcodeJob : ShoeJob {
  std::vector<GcodeMove> moves;
};

GcodeJob run_job(const std::string& profile_name, const std::string& test_name) {
  GcodeJob job{write_shoe_job(profile_name, test_name, "job.nc", write_gcode), {}};
  job.moves = gcode_moves_via_node(job.file, job.profile.gcode.rotary_axis);
  return job;
}

// Runs of consecutive moves for which `down` holds, as polylines (arcs sampled).
template <typename Predicate>
std::vector<std::vector<Point2>> tool_down_paths(const std::vector<GcodeMove>& moves, Predicate down) {
  std::vector<std::vector<Point2>> paths;
  std::vector<Point2> current;
  for (const GcodeMove& move : moves) {
    if (!down(move)) {
      if (current.size() >= 2) paths.push_back(current);
      current.clear();
      continue;
    }
    if (current.empty()) current.push_back(move.from_mm);
    for (const Point2& point : sample_move(move)) {
      if ((point - current.back()).norm() > 1e-12) current.push_back(point);
    }
  }
  if (current.size() >= 2) paths.push_back(current);
  return paths;
}

TEST(ToolpathGcodeRoundTrip, TangentialKnifeCutsEveryOutlineAsOneClosedPath) {
  const GcodeJob job = run_job("grbl-tangential-knife", "tangential-outlines");
  const double z_cut = job.profile.cut.z_down_mm;
  // Lift-rotate-plunge splits a contour at sharp corners; the knife is "in the contour" from the
  // first plunge to the last lift, counting only moves at cutting depth.
  std::vector<std::vector<Point2>> knife_paths;
  std::vector<Point2> current;
  for (const GcodeMove& move : job.moves) {
    const bool cutting = move.z_from_mm <= z_cut + 1e-9 && move.z_to_mm <= z_cut + 1e-9;
    const bool travel = move.motion == "G0" && (move.to_mm - move.from_mm).norm() > 1e-9;
    if (travel || move.coolant == "M8") {  // moving somewhere else, or the pen is working
      if (current.size() >= 2) knife_paths.push_back(current);
      current.clear();
    }
    if (!cutting) continue;
    if (current.empty()) current.push_back(move.from_mm);
    if ((move.to_mm - current.back()).norm() > 1e-12) current.push_back(move.to_mm);
  }
  if (current.size() >= 2) knife_paths.push_back(current);
  for (const Placement& placement : job.layout.placements) {
    const Polygon2 outline = expected_outline(find_item(job.instance, placement.item), placement);
    int tracing = 0;
    for (const auto& path : knife_paths) tracing += traces_outline(path, outline, kTolerance_mm);
    EXPECT_EQ(tracing, 1) << "item " << placement.item << " at (" << placement.x << ", " << placement.y << ")";
  }
}

TEST(ToolpathGcodeRoundTrip, RotaryAxisNeverTurnsMoreThanTheThresholdWhileTheKnifeIsDown) {
  const GcodeJob job = run_job("grbl-tangential-knife", "tangential-axis");
  const double z_cut = job.profile.cut.z_down_mm;
  const double threshold_deg = job.profile.corner_threshold_deg;
  int cutting_moves = 0, lifts_at_corners = 0;
  for (const GcodeMove& move : job.moves) {
    const bool knife_down = move.z_from_mm < job.profile.gcode.z_up_mm - 1e-9 && move.z_to_mm < job.profile.gcode.z_up_mm - 1e-9;
    const double turn_deg = std::abs(move.a_to_deg - move.a_from_deg);
    if (knife_down) {
      EXPECT_LE(turn_deg, threshold_deg + 1e-9) << "at (" << move.from_mm.x() << ", " << move.from_mm.y() << ")";
      const Point2 step = move.to_mm - move.from_mm;
      if (move.z_from_mm <= z_cut + 1e-9 && step.norm() > 0.05) {
        ++cutting_moves;
        // The blade points along the cut: A equals the direction of travel (mod 360).
        const double direction_deg = std::atan2(step.y(), step.x()) * 180.0 / M_PI;
        EXPECT_NEAR(std::remainder(move.a_to_deg - direction_deg, 360.0), 0.0, 0.5);
      }
    } else if (turn_deg > threshold_deg && (move.to_mm - move.from_mm).norm() < 1e-9) {
      ++lifts_at_corners;  // turned in the air on the spot: lift-rotate-plunge
    }
    EXPECT_LT(turn_deg, 180.0 + 1e-9) << "the axis always turns the short way";
  }
  EXPECT_GT(cutting_moves, 100);
  EXPECT_GE(lifts_at_corners, 8) << "rectangles and heel corners need lift-rotate-plunge";
}

TEST(ToolpathGcodeRoundTrip, EveryPieceIsAnnouncedOnceInCuttingOrder) {
  // The interpreters above read the file with these comments in it; here: what the operator reads.
  const GcodeJob job = run_job("grbl-tangential-knife", "piece-comments");
  std::ifstream file(job.file);
  std::vector<std::string> comments;
  for (std::string line; std::getline(file, line);)
    if (line.rfind("; piece ", 0) == 0) comments.push_back(line);
  const size_t count = job.program.pieces.size();
  ASSERT_EQ(comments.size(), count);
  for (size_t k = 0; k < count; ++k) {
    const ProgramPiece& piece = job.program.pieces[k];
    const std::string head = "; piece " + std::to_string(k + 1) + "/" + std::to_string(count) + ": ";
    EXPECT_EQ(comments[k].rfind(head, 0), 0u) << comments[k];
    EXPECT_NE(comments[k].find("(item " + std::to_string(piece.item_id) + ")"), std::string::npos) << comments[k];
    if (!piece.label.empty()) {
      EXPECT_NE(comments[k].find(piece.label), std::string::npos) << comments[k];
    }
    EXPECT_LE(comments[k].size(), 72u);
  }
}

TEST(ToolpathGcodeRoundTrip, PenMarksLandWhereTheLayoutPutsThem) {
  const GcodeJob job = run_job("grbl-tangential-knife", "tangential-marks");
  const auto pen_paths = tool_down_paths(job.moves, [](const GcodeMove& move) {
    return move.coolant == "M8" && (move.motion == "G1" || move.motion == "G2" || move.motion == "G3");
  });
  for (const Placement& placement : job.layout.placements) {
    for (const ItemMark& mark : find_item(job.instance, placement.item).marks) {
      const Point2 from = expected_point(mark.from_mm, placement), to = expected_point(mark.to_mm, placement);
      int found = 0;
      for (const auto& path : pen_paths) {
        if (path.size() != 2) continue;
        found += ((path[0] - from).norm() <= kTolerance_mm && (path[1] - to).norm() <= kTolerance_mm) ||
                 ((path[0] - to).norm() <= kTolerance_mm && (path[1] - from).norm() <= kTolerance_mm);
      }
      EXPECT_EQ(found, 1) << "mark " << mark.name << " of item " << placement.item;
    }
  }
}

TEST(ToolpathGcodeRoundTrip, DragKnifeWithArcsBladeTipFollowsEveryOutline) {
  const GcodeJob job = run_job("grbl-drag-knife", "drag-arcs");
  const double z_cut = job.profile.cut.z_down_mm;
  const double blade_offset_mm = job.profile.cut.blade_offset_mm;
  int arcs = 0;
  for (const GcodeMove& move : job.moves) arcs += move.is_arc;
  EXPECT_GT(arcs, 20) << "arc fitting is on in this profile";
  const auto knife_paths = tool_down_paths(job.moves, [z_cut](const GcodeMove& move) {
    return move.z_from_mm <= z_cut + 1e-9 && move.z_to_mm <= z_cut + 1e-9;
  });
  for (const Placement& placement : job.layout.placements) {
    const Polygon2 outline = expected_outline(find_item(job.instance, placement.item), placement);
    int tracing = 0;
    for (const auto& path : knife_paths) {
      for (const Point2& vertex : outline.points) {
        if (std::abs((vertex - path.front()).norm() - blade_offset_mm) > 1e-3) continue;
        std::vector<Point2> tip = simulate_drag_knife_tip(path, vertex, blade_offset_mm, 0.01);
        tip.insert(tip.begin(), vertex);
        if (traces_outline(tip, outline, kTolerance_mm)) {
          ++tracing;
          break;
        }
      }
    }
    EXPECT_EQ(tracing, 1) << "item " << placement.item << " at (" << placement.x << ", " << placement.y << ")";
  }
}

}  // namespace
}  // namespace lastcut::test
