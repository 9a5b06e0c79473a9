#pragma once
// The strip (roll, sheet) as the separator's container: a rectangle of the current length and the
// fixed height, shrunk on every side by `inset` (margin minus half the gap, since outlines are
// already grown by half the gap). Units: mm.
#include "engine/nest/overlap_proxy.hpp"
#include "engine/nest/separator.hpp"

namespace lastcut::nest_detail {

class StripContainer : public Container {
 public:
  StripContainer(double length, double height, double inset) : length_(length), height_(height), inset_(inset) {}
  void set_length(double length) { length_ = length; }
  Box inside() const { return {inset_, inset_, length_ - inset_, height_ - inset_}; }
  Box offset_range(const OrientedShape& s) const override {
    const Box in = inside();
    return {in.x0 - s.box.x0, in.y0 - s.box.y0, in.x1 - s.box.x1, in.y1 - s.box.y1};
  }
  double exterior_overlap(const OrientedShape& s, const Point2& offset, int, double eps_mm) const override {
    return rectangle_exterior_overlap(s, offset, inside(), eps_mm);
  }

 private:
  double length_, height_, inset_;
};

}  // namespace lastcut::nest_detail
