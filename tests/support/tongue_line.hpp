#pragma once
// The lined derby's tongue (config/styles/derby-lined: the line "tongue" of its lines.obj and the
// tongue's label in style.toml), drawn on the reference last from its own geometry so the file can be
// made again and checked (tests/style/tongue_line_test.cpp; LASTCUT_WRITE_TONGUE_LINE=1 rewrites it).
//
// A derby's tongue lies under the lacing: under both quarters' facings, across the front centre, and
// sewn under the vamp at the throat. Seen from above its outline is a U round the instep's ridge (the
// front centre): two sides from behind the top edge, over the top cut, straight forward to a round nose
// kTongueHalfWidth_mm wide either side and kTongueUnderVamp_mm in front of the throat (where the
// derby's vamp line crosses the ridge), so the tongue's front lies under the vamp. The U is laid on the last straight down; its ends run onto the
// top cut and are left out there, so on the upper it runs from the top edge round the nose back to it.
// Frame: the reference scan's (a generated last: heel at x = 0, toe at +x, ground z = 0, +z up).
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

#include "tests/support/loafer_lines.hpp"
#include "tests/support/style_line_geometry.hpp"

namespace lastcut::test {

inline constexpr double kTongueHalfWidth_mm = 20;     // either side of the ridge at the nose (plan view)
inline constexpr double kTongueTopHalfWidth_mm = 13;  // ... where the sides reach the top cut, narrower as the last's top is
inline constexpr double kTongueTop_x_mm = 100;        // the sides run straight from the nose to here, on the top cut
inline constexpr double kTongueUnderVamp_mm = 12;     // the nose this far in front of the throat
inline constexpr double kTongueBack_x_mm = 60;        // and on back over the top cut, past the top edge

// The derby's throat: where its vamp line (tests/support/derby_style.hpp, the shipped derby's) crosses the ridge.
inline Eigen::Vector3d derby_throat(const TriMesh& mesh) {
  const Polyline vamp = plane_section_through(mesh, {1, 0, 0.35}, {170, 0, 40});
  return *std::max_element(vamp.begin(), vamp.end(), [](const auto& a, const auto& b) { return a.z() < b.z(); });
}

struct TongueDrawing {
  StyleLine line;          // "tongue"
  Eigen::Vector3d label;   // a point inside the tongue, on the medial side of the centre
};

// mesh: the reference last as scanned (generator frame, a right last: medial +y). The U is centred on
// the throat's y: the generated last's ridge runs straight from the throat to the top cut.
inline TongueDrawing draw_tongue(const TriMesh& mesh) {
  const Eigen::Vector3d throat = derby_throat(mesh);
  const double round_x = throat.x() + kTongueUnderVamp_mm - kTongueHalfWidth_mm;  // the nose's centre
  const double w = kTongueHalfWidth_mm, y = throat.y();
  const double top = kTongueTopHalfWidth_mm;
  PlanLine plan = {{kTongueBack_x_mm, y + top}, {kTongueTop_x_mm, y + top}};
  for (int k = 0; k <= 36; ++k) {  // the nose, from the medial side round to the lateral
    const double angle = std::numbers::pi / 2 - std::numbers::pi * k / 36;
    plan.emplace_back(round_x + w * std::cos(angle), y + w * std::sin(angle));
  }
  plan.emplace_back(kTongueTop_x_mm, y - top);
  plan.emplace_back(kTongueBack_x_mm, y - top);
  TongueDrawing drawing;
  drawing.line = {"tongue", laid_on_top(mesh, resampled(plan, kPlanStep_mm))};
  drawing.label = laid_on_top(mesh, {Eigen::Vector2d(120, y + 10)}).front();
  return drawing;
}

}  // namespace lastcut::test
