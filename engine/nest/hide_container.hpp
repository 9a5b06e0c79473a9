#pragma once
// A hide (or sheet) as a container for the nester: the usable region is inside the outline and
// outside the defects (both moved inwards by the margin), and outside every quality zone below a
// piece's min_quality (and below each of its stricter quality regions' min_quality, for that region).
// The exact test runs on the piece's conservative outline: no edge may touch a hazard edge, the piece
// must start in the usable region and no defect or forbidden zone may lie inside the piece.
// The penalty of a piece that is not usable where it lies is smooth, like the pieces' pairwise
// overlap: every pole of the piece counts with its smoothed penetration depth into the forbidden side
// of the nearest hazard edge, so the separator can push pieces in from outside or off a hole as
// sparrow pushes them back into the strip (Gardeyn, Vanden Berghe & Wauters, arXiv:2509.13329, 2025).
// The signed distance to the nearest hazard edge is read from a grid (about 160 cells along the hide's
// longer side, bilinear), one per set of forbidden zones in use: it only grades a collision that the
// exact test has found, so its resolution never decides feasibility.
#include <vector>

#include "engine/nest/nest_problem.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

class HideContainer : public Container {
 public:
  // inset_mm: how far outlines must stay inside the hide edge and away from defects (margin - gap/2).
  // min_qualities: the min_quality values of the pieces and quality regions that will be tested
  // (the penalty's distance grids are built for these only; other values fall back to the nearest
  // grid below).
  HideContainer(const Bin& bin, double inset_mm, const std::vector<int>& min_qualities = {0});
  Box offset_range(const OrientedShape& shape) const override;
  // 0 when the piece (and each of its regions) is usable there; otherwise positive, mm^2.
  double exterior_overlap(const OrientedShape& shape, const Point2& offset, int min_quality,
                          double eps_mm) const override;
  double usable_area_mm2() const { return usable_area_mm2_; }

 private:
  struct Ring {
    std::vector<Point2> points;
    Box box;
    enum Kind { Outer, Hole, Zone } kind = Outer;
    int quality = 0;
  };
  // zones_only: a quality region's test, where only the zones below its quality matter.
  bool relevant(const Ring& ring, int min_quality, bool zones_only) const {
    if (zones_only) return ring.kind == Ring::Zone && ring.quality < min_quality;
    return ring.kind != Ring::Zone || ring.quality < min_quality;
  }
  bool usable_point(const Point2& p, int min_quality, bool zones_only) const;
  bool collides(const std::vector<Point2>& outline, const Box& box, const Point2& offset, int min_quality,
                bool zones_only) const;
  // Sum over the poles of smoothed penetration depth x radius into the forbidden side, mm^2.
  double pole_penalty(const std::vector<Pole>& poles, const Point2& offset, int min_quality, bool zones_only,
                      double eps_mm) const;

  // Signed distance (mm, positive where usable) to the nearest relevant hazard edge, on cell centres.
  struct DistanceGrid {
    bool zones_only = false;
    int min_quality = 0;
    double x0 = 0, y0 = 0, step = 1;
    int nx = 0, ny = 0;
    std::vector<float> value;
    double at(const Point2& p) const;
  };
  void build_grid(bool zones_only, int min_quality);
  const DistanceGrid* grid_for(bool zones_only, int min_quality) const;

  std::vector<Ring> rings_;
  std::vector<DistanceGrid> grids_;
  Box box_;
  double usable_area_mm2_ = 0;
};

}  // namespace lastcut::nest_detail
