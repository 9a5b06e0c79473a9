#pragma once
// Pairs of shoes of the shipped styles (config/styles) as the cutting room gets them: per pair one
// generated last of the pair's size is scanned (scan_to_molds), the style's pieces are cut from it
// (make_style_pieces) and turned into nest items by the one path the daemon uses (items_from_style),
// the other foot mirrored (other_foot): a generated left last is the mirror image of the right one of
// its size, so the mirrored pieces are the other last's pieces. Each pair is one PieceGroup with an
// order of its own, so hide_batch keeps its pieces on one hide.
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/foot_side.hpp"
#include "engine/nest/hide_batch.hpp"
#include "engine/scan/scan_to_molds.hpp"
#include "engine/style/style_definition.hpp"

namespace lastcut::bench {

struct PairOrder {
  std::string style;  // a folder name under config/styles
  int eu_size = 42;
  FootSide scanned_foot = FootSide::Right;  // the last that is scanned; the other foot is mirrored
};

// `pairs` orders: the styles in turn (pair k has styles[k % n]); the sizes given in turn, or, when
// none are given, spread evenly over EU 36..47 (one pair: 36); the scanned foot right, right, left,
// left, ... so that every style gets both feet.
std::vector<PairOrder> spread_pairs(int pairs, const std::vector<int>& sizes, const std::vector<std::string>& styles);

// Makes the pieces of pairs. The styles are read from styles_dir/<name> and their reference lasts
// prepared once, on first use; every last goes through a scratch folder of its own (mkdtemp).
class PairMaker {
 public:
  PairMaker(std::filesystem::path styles_dir, int last_triangles);
  ~PairMaker();
  PairMaker(const PairMaker&) = delete;
  PairMaker& operator=(const PairMaker&) = delete;

  // The pair's pieces, both feet, as one group (owner "pair K", order "K"). Throws EngineError.
  PieceGroup make(const PairOrder& order, int index);

 private:
  struct Style {
    StyleDefinition definition;
    ScanResult reference;
  };
  const Style& style(const std::string& name);

  std::filesystem::path styles_dir_;
  int last_triangles_;
  std::filesystem::path scratch_;
  std::map<std::string, std::unique_ptr<Style>> styles_;
};

}  // namespace lastcut::bench
