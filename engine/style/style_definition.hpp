#pragma once
// A style as the pattern maker defines it once, on a reference last (issue 34, point 1): the style
// lines drawn on the last, which stretches of the centre seams are cut, a label point inside each
// piece, and the allowance rules. Plain data; read from a style folder by daemon/config/style_folder.hpp.
//
// Allowances by edge (shoemaking's defaults, all configurable): the feather line carries the lasting
// margin (18 mm, folded under the insole), the top edge is folded (5 mm), a style line gives the piece
// that lies under its neighbour the underlay (8 mm) and the other one a butted or raw edge (0), a cut
// seam is butted (0).
//
// Layers: the outer pieces (vamp, quarters, counter) tile the upper and are cut along every style line.
// A second layer over the same upper, the linings, is cut along fewer lines (a StyleLayer names them):
// a derby's linings part where the vamp meets the quarters, while one quarter lining runs round the heel
// under the counter. Each layer tiles the whole upper on its own, with its own seam cuts; its pieces
// are flattened, notched and allowed for exactly as the outer ones. A partial layer cuts only the
// regions that hold a label: a derby's tongue, a U drawn under the lacing from the top edge round below
// the throat and back, lies under the quarters and the vamp and reaches above the top edge by its
// folding allowance.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "engine/mold/edge_allowance.hpp"
#include "engine/style/style_lines_obj.hpp"

namespace lastcut {

struct StyleAllowances {
  double lasting_mm = 18;
  double folding_mm = 5;
  double underlay_mm = 8;
  double butted_mm = 0;
};

struct StyleLineRule {
  std::string line;   // a line's name in the style's lines
  std::string under;  // the piece lying under its neighbour along the line (gets the underlay); empty: none
};

struct StyleSeamCut {
  EdgeKind seam = EdgeKind::BackSeam;  // FrontSeam or BackSeam
  std::string from_line;               // cut from where this line crosses the seam up to the top edge; empty: all of it
  std::string layer;                   // the layer whose pieces it parts; "": the outer pieces
};

// A layer of pieces under the outer ones (the linings, a tongue).
struct StyleLayer {
  std::string name;                // e.g. "lining"; a piece and a seam cut name it in their `layer`
  std::vector<std::string> lines;  // the style lines that part this layer's pieces; the others run over them
  // Only the regions holding a piece's label are cut; the rest of the upper it parts off is not (a
  // tongue under the lacing, a reinforcement). Its lines are the pieces' own edges, sewn to nothing in
  // the layer: no balance notches, no seam lengths. false: the layer tiles the upper (the linings).
  bool partial = false;
};

struct StylePiece {
  std::string name;
  Eigen::Vector3d label_mm = Eigen::Vector3d::Zero();  // a point inside the piece on the reference last (its scan's frame)
  std::string material = "upper leather";
  std::string layer;  // "": the outer pieces; else a StyleLayer's name
  int quantity = 1;  // per shoe
  double grain_deg = 0;  // the grain line, counter-clockwise from the last's heel-to-toe axis (piece_grain.hpp)
  // What the piece asks of the leather when it is cut (engine/nest/pattern_items.hpp); nullopt: the
  // material's default in the cutting room's configuration.
  std::optional<double> grain_tolerance_deg;  // grain line along the hide's backbone within this
  std::optional<int> min_quality;             // lowest leather grade the piece may lie on
  // The material's thickness (mm): the piece is flattened from its mid-surface, half of it off the last
  // (piece_thickness.hpp). nullopt: the style's thickness_mm.
  std::optional<double> thickness_mm;
  // The allowances of this piece's edges, where they differ from the style's (a tongue reaching above
  // the last's top edge: a larger folding); nullopt: the style's.
  std::optional<StyleAllowances> allowances;
};

struct StyleDefinition {
  std::string name;
  std::vector<StyleLine> lines;  // on the reference last, in its scan's frame (mm)
  std::vector<StyleLineRule> line_rules;
  std::vector<StyleSeamCut> seam_cuts;
  std::vector<StyleLayer> layers;  // beside the outer pieces: each tiles the upper again (the linings)
  std::vector<StylePiece> pieces;
  StyleAllowances allowances;
  double balance_notch_spacing_mm = 50;  // along every seam (piece_notches.hpp)
  double thickness_mm = 0;  // of every piece that gives none; 0: flattened from the last's own surface
};

}  // namespace lastcut
