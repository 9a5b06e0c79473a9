// Fuzz target: the comparison of a mold with a reference pattern (engine/compare/compare_outlines.hpp)
// and its record (comparison_json, comparison_svg), what `lastcut compare` and lastcutd do after the
// readers, whose own targets are reference_svg and reference_dxf. The readers hand over any closed
// ring with area, self-intersecting or not, so this target builds the two outlines from the bytes
// directly and keeps them small: under the sanitizers a comparison of real molds takes 1-6 s (the
// alignment clips at every trial motion); outlines of at most 24 points take a fraction of that.
//
// Input bytes: [mold points - 3] [reference points - 3] [flags] then 4 bytes a point, x and y as
// 16-bit fractions of a 320 x 160 mm box (mold points first), then one byte a notch mark (the index
// of the mold point it sits on). flags: bit 0 allows the mirror, bits 1-3 the number of marks
// (heel, toe, top_front, top_back, a fifth named "extra"), bit 4 gives the reference the same marks.
//
// What counts as fine: check_pattern_outline and compare_mold document EngineError (one line) for what
// is no pattern; anything else that is thrown, a sanitizer report, an overlap outside [0, 1] or a
// distance that is not finite is a crash.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "engine/compare/compare_report.hpp"
#include "engine/compare/reference_outline.hpp"
#include "engine/core/engine_error.hpp"
#include "engine/core/polygon.hpp"

namespace {

constexpr int kMaxPoints = 24;
constexpr double kBoxWidth_mm = 320.0, kBoxHeight_mm = 160.0;

struct ByteReader {
  const uint8_t* data;
  size_t size, at = 0;
  int byte() { return at < size ? data[at++] : 0; }
  double fraction() {
    const int high = byte();
    return (high * 256 + byte()) / 65535.0;
  }
};

lastcut::Polygon2 outline_from(ByteReader& bytes, int count) {
  lastcut::Polygon2 outline;
  for (int i = 0; i < count; ++i) {
    const double x = kBoxWidth_mm * bytes.fraction();
    outline.points.emplace_back(x, kBoxHeight_mm * bytes.fraction());
  }
  // As every reader hands it on (read_mold_dxf, largest_closed_outline).
  if (lastcut::signed_area(outline) < 0.0) lastcut::make_counter_clockwise(outline);
  return outline;
}

void require(bool holds) {
  if (!holds) __builtin_trap();
}

bool finite_point(const lastcut::Point2& p) { return std::isfinite(p.x()) && std::isfinite(p.y()); }

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ByteReader bytes{data, size};
  const int mold_count = 3 + bytes.byte() % (kMaxPoints - 2);
  const int reference_count = 3 + bytes.byte() % (kMaxPoints - 2);
  const int flags = bytes.byte();
  lastcut::Mold mold{"mold", outline_from(bytes, mold_count), {}, {}};
  lastcut::Mold reference{"reference", outline_from(bytes, reference_count), {}, {}};
  static const char* const kMarkNames[] = {"heel", "toe", "top_front", "top_back", "extra"};
  const int mark_count = std::min((flags >> 1) & 7, 5);
  for (int m = 0; m < mark_count; ++m) {
    const int at = bytes.byte() % mold_count;
    mold.marks.push_back({kMarkNames[m], mold.outline.points[static_cast<size_t>(at)], lastcut::Point2::Zero()});
    if (flags & 16) {
      const int at_reference = at % reference_count;
      reference.marks.push_back(
          {kMarkNames[m], reference.outline.points[static_cast<size_t>(at_reference)], lastcut::Point2::Zero()});
    }
  }
  try {
    lastcut::check_pattern_outline("mold.dxf", mold.outline);
    lastcut::check_pattern_outline("reference.svg", reference.outline);
    lastcut::CompareOptions options;
    options.overlap.allow_mirror = (flags & 1) != 0;
    const lastcut::Comparison comparison = lastcut::compare_mold(mold, reference, options);
    const double overlap = comparison.alignment.overlap_fraction();
    require(overlap >= 0.0 && overlap <= 1.0 + 1e-9);
    require(std::isfinite(comparison.deviation.hausdorff_mm) && std::isfinite(comparison.deviation.mean_mm));
    for (const lastcut::CornerMatch& corner : comparison.corners)
      require(std::isfinite(corner.margin_mm) && finite_point(corner.mold_mm) && finite_point(corner.reference_mm));
    const nlohmann::json record = lastcut::comparison_json(comparison, {"mold.dxf", "reference.svg"}, 2.0);
    require(!record.dump().empty());
    require(!lastcut::comparison_svg(comparison, 2.0).empty());
  } catch (const lastcut::EngineError&) {
    // A refusal, as documented.
  }
  return 0;
}
