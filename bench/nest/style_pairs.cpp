#include "style_pairs.hpp"

#include <stdlib.h>

#include <cmath>
#include <system_error>
#include <utility>

#include "daemon/config/style_folder.hpp"
#include "daemon/config/style_reference.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/lastgen/generate_last.hpp"
#include "engine/mesh/write_mesh.hpp"
#include "engine/style/style_items.hpp"
#include "engine/style/style_pieces.hpp"

namespace lastcut::bench {

namespace fs = std::filesystem;

std::vector<PairOrder> spread_pairs(int pairs, const std::vector<int>& sizes, const std::vector<std::string>& styles) {
  if (pairs < 1) throw EngineError("at least one pair is needed");
  if (styles.empty()) throw EngineError("at least one style is needed");
  constexpr int kSmallest = 36, kLargest = 47;  // issue 35: sizes over EU 36-47
  std::vector<PairOrder> orders;
  for (int k = 0; k < pairs; ++k) {
    PairOrder order;
    order.style = styles[static_cast<std::size_t>(k) % styles.size()];
    if (!sizes.empty())
      order.eu_size = sizes[static_cast<std::size_t>(k) % sizes.size()];
    else
      order.eu_size = pairs == 1 ? kSmallest
                                 : kSmallest + static_cast<int>(std::lround((kLargest - kSmallest) * double(k) / (pairs - 1)));
    order.scanned_foot = (k / 2) % 2 == 0 ? FootSide::Right : FootSide::Left;
    orders.push_back(order);
  }
  return orders;
}

PairMaker::PairMaker(fs::path styles_dir, int last_triangles) : styles_dir_(std::move(styles_dir)), last_triangles_(last_triangles) {
  std::string pattern = (fs::temp_directory_path() / "lastcut-piece-yield-XXXXXX").string();
  if (::mkdtemp(pattern.data()) == nullptr) throw EngineError("cannot make a scratch folder like " + pattern);
  scratch_ = pattern;
}

PairMaker::~PairMaker() {
  std::error_code ignored;  // a leftover scratch file is harmless
  fs::remove_all(scratch_, ignored);
}

const PairMaker::Style& PairMaker::style(const std::string& name) {
  auto found = styles_.find(name);
  if (found != styles_.end()) return *found->second;
  Result<daemon::StyleFolder> folder = daemon::read_style_folder(styles_dir_ / name);
  if (!folder) throw EngineError(folder.error());
  auto made = std::make_unique<Style>(Style{folder->style, daemon::prepare_style_reference(*folder)});
  return *styles_.emplace(name, std::move(made)).first->second;
}

PieceGroup PairMaker::make(const PairOrder& order, int index) {
  const Style& made = style(order.style);
  LastParams params = LastParams::for_eu_size(order.eu_size, order.scanned_foot);
  params.target_triangles = last_triangles_;
  const fs::path scan = scratch_ / "last.stl";
  write_stl_binary(scan, generate_last(params).mesh);
  ScanOptions options;
  options.side = order.scanned_foot;
  const ScanResult target = scan_to_molds(scan, options);
  const StyleResult pieces = make_style_pieces(made.definition, made.reference, target);

  StyleNestSpec spec;
  spec.style = order.style;
  spec.size = std::to_string(order.eu_size);
  spec.foot = std::string(to_string(order.scanned_foot));
  spec.shoes = 1;
  spec.other_foot = true;  // the pair's other shoe, mirrored
  // Every piece of the shipped styles gives its own grain tolerance and grade; a piece that gave
  // none would be free (no material rules here).
  PieceGroup group;
  group.owner = "pair " + std::to_string(index);
  group.order = std::to_string(index);
  group.items = items_from_style(pieces, spec);
  return group;
}

}  // namespace lastcut::bench
