#pragma once
// A hide (or sheet) as a container for the nester: the usable region is inside the outline and
// outside the defects (both moved inwards by the margin), and outside every quality zone below a
// piece's min_quality. The exact test runs on the piece's conservative outline: no edge may touch a
// hazard edge, the piece must start in the usable region and no defect or forbidden zone may lie
// inside the piece.
#include <vector>

#include "engine/nest/nest_problem.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

class HideContainer : public Container {
 public:
  // inset_mm: how far outlines must stay inside the hide edge and away from defects (margin - gap/2).
  HideContainer(const Bin& bin, double inset_mm);
  Box offset_range(const OrientedShape& shape) const override;
  // 0 when the piece is usable there; otherwise a positive penalty growing with the offending poles.
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
  bool relevant(const Ring& ring, int min_quality) const {
    return ring.kind != Ring::Zone || ring.quality < min_quality;
  }
  bool usable_point(const Point2& p, int min_quality) const;
  bool collides(const OrientedShape& shape, const Point2& offset, int min_quality) const;

  std::vector<Ring> rings_;
  Box box_;
  double usable_area_mm2_ = 0;
};

}  // namespace lastcut::nest_detail
