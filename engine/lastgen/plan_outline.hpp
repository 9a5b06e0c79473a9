#pragma once
// The plan view (seen from above) of a last at the feather line: a smooth closed outline with a
// rounded heel, a concave medial arch, a fuller and more curved lateral side, the first-metatarsal
// (medial) ball point ahead of the fifth (lateral), and the toe tip shifted medially.
// The outline is a centripetal Catmull-Rom curve through designer control points
// (Yuksel, Schaefer & Keyser, "Parameterization and applications of Catmull-Rom curves",
// Computer-Aided Design 43(7), 2011), scaled so that it spans x in [0, length] exactly and
// its width across Y equals the ball width. Here the medial side is +Y; mirror for a left last.
// A symmetric last (LastParams::symmetric) has the medial side on both sides of y = 0.
#include <Eigen/Core>
#include <vector>

namespace lastcut {

struct LastParams;

class PlanOutline {
 public:
  explicit PlanOutline(const LastParams& params);

  // Signed distance in the XY plane to the outline (mm): negative inside. Sampled on a 0.75 mm
  // grid and interpolated bilinearly; exact within 0.15 x length of the outline, clamped to that
  // beyond; outside the grid the distance to the grid is added.
  double signed_distance_mm(double x_mm, double y_mm) const;
  // Extent of the outline across Y at x: {y_min, y_max} (mm); a small span at the ends.
  Eigen::Vector2d y_span_mm(double x_mm) const;
  // The outline polygon, counter-clockwise, #P x 2 (mm).
  const std::vector<Eigen::Vector2d>& polygon() const { return polygon_; }

 private:
  void fill_distance_grid(double band_mm);

  std::vector<Eigen::Vector2d> polygon_;
  Eigen::Vector2d grid_origin_mm_;
  double grid_step_mm_ = 0.75;
  int grid_nx_ = 0, grid_ny_ = 0;
  std::vector<float> grid_distance_mm_;
  std::vector<Eigen::Vector2d> y_span_by_mm_;  // y span at x = 0, 1, 2 ... mm
};

}  // namespace lastcut
