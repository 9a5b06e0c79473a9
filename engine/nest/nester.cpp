#include "engine/nest/nester.hpp"

#include "engine/core/engine_error.hpp"
#include "engine/nest/hide_nester.hpp"
#include "engine/nest/layout_check.hpp"
#include "engine/nest/pair_clusters.hpp"
#include "engine/nest/strip_nester.hpp"

namespace lastcut {
namespace {

// Strips: complementary pairs are nested as one piece and split again in every layout reported.
Layout nest_strip_with_pairs(const NestInstance& instance, const NestOptions& options) {
  const PairClusters clusters = cluster_pairs(instance, options.gap_mm.value_or(instance.gap_mm),
                                              options.margin_mm.value_or(instance.margin_mm));
  if (clusters.members.empty()) return nest_strip(instance, options);
  NestOptions inner = options;
  if (options.on_improvement)
    inner.on_improvement = [&](const Layout& layout) { options.on_improvement(expand_clusters(layout, clusters, instance)); };
  return expand_clusters(nest_strip(clusters.instance, inner), clusters, instance);
}

}  // namespace

Layout nest(const NestInstance& instance, const NestOptions& options) {
  if (options.time_limit_s < 0) throw EngineError("nest: the time limit must not be negative");
  if (options.threads < 1) throw EngineError("nest: at least one thread is needed");
  if (options.sweep_workers < 1) throw EngineError("nest: at least one sweep worker is needed");
  if (options.gap_mm.value_or(0) < 0 || options.margin_mm.value_or(0) < 0)
    throw EngineError("nest: gap and margin must not be negative");
  if (options.free_rotation_step_deg <= 0 || options.free_rotation_step_deg > 180)
    throw EngineError("nest: the free rotation step must be in (0, 180] deg");
  if (instance.items.empty()) throw EngineError("nest instance " + instance.name + " has no items");
  if (!instance.strip_height && instance.bins.empty())
    throw EngineError("nest instance " + instance.name + " has neither a strip height nor hides");
  Layout layout = instance.strip_height ? nest_strip_with_pairs(instance, options) : nest_hides(instance, options);
  // Leather is cut from whatever leaves here: a layout the independent checker refuses is a bug,
  // and no front door may write or cut it.
  const std::vector<std::string> problems =
      check_layout(layout, instance, options.gap_mm.value_or(-1), options.margin_mm.value_or(-1));
  if (!problems.empty())
    throw EngineError("internal error: the layout of " + instance.name + " failed the independent check: " +
                      problems.front());
  return layout;
}

}  // namespace lastcut
