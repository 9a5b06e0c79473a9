#include "engine/style/forme_lift.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>

#include "engine/core/engine_error.hpp"
#include "engine/style/forme_half_runs.hpp"

namespace lastcut {
namespace {

constexpr double kFormeLiftStep_mm = 1.0;  // a drawn line is lifted at points this far apart at most
constexpr double kEdgeNudge_mm = 1e-4;     // an end on the feather line or top edge is put this far past it:
                                           // off the last (so no rounding reads it as a point inside the
                                           // half), well within the 1e-3 mm the transfer takes as on the edge

EdgeKind edge_kind_of_end(RunEndKind kind) {
  switch (kind) {
    case RunEndKind::Top: return EdgeKind::Top;
    case RunEndKind::FrontSeam: return EdgeKind::FrontSeam;
    case RunEndKind::BackSeam: return EdgeKind::BackSeam;
    default: return EdgeKind::Feather;
  }
}

bool on_seam(RunEndKind kind) { return kind == RunEndKind::FrontSeam || kind == RunEndKind::BackSeam; }

struct EndRef {
  std::size_t run = 0;
  bool last = false;
  auto operator<=>(const EndRef&) const = default;
};

// The runs of every line on both halves, lifted and joined into 3D lines (canonical frame).
class RunJoiner {
 public:
  RunJoiner(const FormeDrawing& drawing, const FormeLayout& layout, const std::array<FormeHalfShape, 2>& shapes,
            std::vector<HalfRun> runs)
      : drawing_(drawing), layout_(layout), shapes_(shapes), runs_(std::move(runs)), used_(runs_.size(), 0) {}

  // The 3D lines of the drawn lines called `name`.
  std::vector<std::vector<Eigen::Vector3d>> lines_named(const std::string& name) {
    std::vector<std::size_t> mine;
    for (std::size_t r = 0; r < runs_.size(); ++r)
      if (drawing_.lines[runs_[r].line].name == name) mine.push_back(r);
    pair_seam_ends(mine);
    std::vector<std::vector<Eigen::Vector3d>> lines;
    for (const std::size_t r : mine)  // open chains first, from an end met by no other run
      if (!used_[r] && !runs_[r].closed && (!partner_.contains({r, false}) || !partner_.contains({r, true})))
        lines.push_back(walk({r, partner_.contains({r, false})}));
    for (const std::size_t r : mine)  // then what is left: closed lines, and chains closing on themselves
      if (!used_[r]) lines.push_back(walk({r, false}));
    return lines;
  }

 private:
  const RunEnd& end_of(const EndRef& end) const { return end.last ? runs_[end.run].last : runs_[end.run].first; }

  // Each lateral end on a seam with the nearest medial end on the same seam, when they are one point of it.
  void pair_seam_ends(const std::vector<std::size_t>& mine) {
    for (const std::size_t lateral : mine) {
      if (runs_[lateral].half != 1 || runs_[lateral].closed) continue;
      for (const bool last : {false, true}) {
        const RunEnd& from = end_of({lateral, last});
        if (!on_seam(from.kind) || partner_.contains({lateral, last})) continue;
        std::optional<EndRef> best;
        for (const std::size_t medial : mine)
          for (const bool medial_last : {false, true}) {
            const RunEnd& to = end_of({medial, medial_last});
            if (runs_[medial].half != 0 || runs_[medial].closed || to.kind != from.kind || partner_.contains({medial, medial_last}))
              continue;
            if (!best || std::abs(to.share - from.share) < std::abs(end_of(*best).share - from.share)) best = EndRef{medial, medial_last};
          }
        const FormeHalfLayout& lateral_half = layout_.halves[1];
        if (!best || std::abs(end_of(*best).share - from.share) * lateral_half.edge_length_mm(edge_kind_of_end(from.kind)) > kFormeJoinGap_mm)
          continue;
        // The seam is one curve of the last, its shares the same from either half: its point halfway is the join.
        const Eigen::Vector3d join = lateral_half.edge_point_3d(edge_kind_of_end(from.kind), 0.5 * (from.share + end_of(*best).share));
        partner_[{lateral, last}] = {*best, join};
        partner_[*best] = {EndRef{lateral, last}, join};
      }
    }
  }

  Eigen::Vector3d end_point(const EndRef& end) const {
    if (const auto joined = partner_.find(end); joined != partner_.end()) return joined->second.second;
    const HalfRun& run = runs_[end.run];
    const RunEnd& settled = end_of(end);
    if (settled.kind == RunEndKind::Line) return shapes_[static_cast<std::size_t>(run.half)].surface_point(end.last ? run.points_mm.back() : run.points_mm.front());
    const FormeHalfLayout& half = layout_.halves[static_cast<std::size_t>(run.half)];
    const FormeEdge& edge = half.boundary.edge(edge_kind_of_end(settled.kind));
    const auto corner = [&](std::size_t k) { return Eigen::Vector3d(half.segment->mesh3d.V.row(edge.vertices[k]).transpose()); };
    return (1 - settled.weight) * corner(settled.segment) + settled.weight * corner(settled.segment + 1);
  }

  // The 3D line from `start` (an end of a run) through the runs joined to it.
  std::vector<Eigen::Vector3d> walk(EndRef start) {
    std::vector<Eigen::Vector3d> line;
    const HalfRun& first_run = runs_[start.run];
    if (first_run.closed) {
      used_[start.run] = 1;
      for (const Point2& p : first_run.points_mm) line.push_back(shapes_[static_cast<std::size_t>(first_run.half)].surface_point(p));
      line.back() = line.front();
      return line;
    }
    EndRef at = start;
    line.push_back(end_point(at));
    for (;;) {
      used_[at.run] = 1;
      const HalfRun& run = runs_[at.run];
      const std::size_t n = run.points_mm.size();
      for (std::size_t k = 1; k + 1 < n; ++k)
        line.push_back(shapes_[static_cast<std::size_t>(run.half)].surface_point(run.points_mm[at.last ? n - 1 - k : k]));
      const EndRef leaving{at.run, !at.last};
      line.push_back(end_point(leaving));
      const auto joined = partner_.find(leaving);
      if (joined == partner_.end() || used_[joined->second.first.run]) break;  // an open end, or back at the start
      at = joined->second.first;
    }
    nudge_past_edge(line, start, true);
    nudge_past_edge(line, {at.run, !at.last}, false);
    return line;
  }

  void nudge_past_edge(std::vector<Eigen::Vector3d>& line, const EndRef& end, bool front) const {
    const RunEndKind kind = end_of(end).kind;
    if (partner_.contains(end) || (kind != RunEndKind::Feather && kind != RunEndKind::Top) || line.size() < 2) return;
    Eigen::Vector3d& tip = front ? line.front() : line.back();
    const Eigen::Vector3d along = tip - (front ? line[1] : line[line.size() - 2]);
    if (along.norm() > 0) tip += kEdgeNudge_mm * along.normalized();
  }

  const FormeDrawing& drawing_;
  const FormeLayout& layout_;
  const std::array<FormeHalfShape, 2>& shapes_;
  std::vector<HalfRun> runs_;
  std::vector<char> used_;
  std::map<EndRef, std::pair<EndRef, Eigen::Vector3d>> partner_;  // joined ends: the other end and the join (3D)
};

}  // namespace

LiftedForme lift_forme_drawing(const FormeDrawing& drawing, const FormeLayout& layout, const Eigen::Affine3d& scan_to_canonical) {
  const std::array<FormeHalfShape, 2> shapes = {FormeHalfShape(layout.halves[0]), FormeHalfShape(layout.halves[1])};
  std::array<std::vector<HalfRun>, 2> runs;
  for (std::size_t line = 0; line < drawing.lines.size(); ++line) {
    const FormeLineDrawing& drawn = drawing.lines[line];
    const std::vector<Point2> points = densified(drawn.points_mm, kFormeLiftStep_mm);
    std::vector<int> halves;
    if (drawn.halves != FormeHalves::Lateral) halves.push_back(0);
    if (drawn.halves != FormeHalves::Medial) halves.push_back(1);
    std::size_t found = 0;
    for (const int h : halves) {
      std::vector<double> outside_elsewhere(points.size(), INFINITY);
      if (halves.size() == 2)
        for (std::size_t i = 0; i < points.size(); ++i) outside_elsewhere[i] = shapes[static_cast<std::size_t>(1 - h)].outside_mm(points[i]);
      std::vector<HalfRun> on_half = runs_on_half(drawing, line, points, shapes[static_cast<std::size_t>(h)], h, outside_elsewhere);
      found += on_half.size();
      runs[static_cast<std::size_t>(h)].insert(runs[static_cast<std::size_t>(h)].end(), on_half.begin(), on_half.end());
    }
    if (found == 0)
      throw EngineError(drawing.source + ": line " + drawn.name + " (layer " + drawn.layer + ") does not enter the forme, near " +
                        forme_point_text(drawn.points_mm.front()));
  }
  for (std::size_t h = 0; h < 2; ++h) settle_run_ends(drawing, shapes[h], runs[h]);

  LiftedForme lifted;
  const Eigen::Affine3d canonical_to_scan = scan_to_canonical.inverse();
  std::vector<HalfRun> all = runs[0];
  all.insert(all.end(), runs[1].begin(), runs[1].end());
  RunJoiner joiner(drawing, layout, shapes, std::move(all));
  std::vector<std::string> names;
  for (const FormeLineDrawing& drawn : drawing.lines)
    if (std::find(names.begin(), names.end(), drawn.name) == names.end()) names.push_back(drawn.name);
  for (const std::string& name : names)
    for (std::vector<Eigen::Vector3d>& line : joiner.lines_named(name)) {
      for (Eigen::Vector3d& p : line) p = canonical_to_scan * p;
      lifted.lines.push_back({name, std::move(line)});
    }

  for (const FormePieceText& text : drawing.pieces) {
    const int h = text.half == FormeHalves::Medial ? 0 : 1;
    const FormeHalfShape& shape = shapes[static_cast<std::size_t>(h)];
    if (const double outside_mm = shape.outside_mm(text.at_mm); outside_mm > 0) {
      char distance[32];
      std::snprintf(distance, sizeof distance, "%.1f", outside_mm);
      throw EngineError(drawing.source + ": piece text \"" + text.name + "\" at " + forme_point_text(text.at_mm) + " lies " + distance +
                        " mm outside the " + (h == 0 ? "medial" : "lateral") +
                        " half: put it inside its piece (a text beginning \"medial \" labels the medial half)");
    }
    StylePiece piece;
    piece.name = text.name;
    piece.label_mm = canonical_to_scan * shape.surface_point(text.at_mm);
    lifted.pieces.push_back(piece);
  }
  return lifted;
}

}  // namespace lastcut
