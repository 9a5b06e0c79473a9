#pragma once
// The hide search's tuning in one place (engine/nest/hide_search): budgets of one insertion, how hard
// a move tries as attempts keep failing (Effort), when the search gives a trajectory up, and when it
// regroups. Each value was measured on the Baldacci instances (docs/benchmarks-nest.md); the layouts
// depend on every one of them. Which move runs on which attempt is engine/nest/hide_schedule.
namespace lastcut::nest_detail {

struct HideSearchTuning {
  // Separation of one insertion at effort level 0: `strikes` strikes of `stale_sweeps` sweeps without
  // a 2 % improvement. A small budget tried often beat 3 x 40 sweeps on Test1, Test5 and Test6 at 10 s.
  int strikes = 2;
  int stale_sweeps = 15;  // each level of effort adds this many sweeps per strike
  // Levels of effort (failed cycles over the used hides) before a trajectory that is as good as the
  // best one is dropped for a restart; one behind the best gets a single cycle.
  int max_level = 2;
  // Hides an inserted unit tries at level 0, most free area first; each level adds one.
  int destinations = 2;
  // One ejection chain (hide_eject): hides one unit is separated on (each level adds one), and the
  // insertions beyond the target's own units before the chain stops.
  int chain_destinations = 3;
  int max_ejections = 8;
  // Sampled spots of one free placement: enough that a free spot on a half-full hide is found.
  int place_samples = 240;
  // Sweeps compared per separation step inside a hide (capped by NestOptions::sweep_workers): hides
  // hold few pieces, more workers cost more than they find.
  int sweep_workers = 2;
  // Failed shrinks and chains in a row that end the search at the area bound: nothing else is left.
  long shrink_tries = 40;
  // Failed attempts on one hide before the next hide is the target; a cycle is this many per used hide.
  long per_target = 4;
  // Merges tried up to this fill of the hides left (Test1 reached 72 %; fuller ones never emptied).
  double merge_fill = 0.74;
  // Regrouping (hide_regroup): tried only when the fewer hides would be at most this full by area...
  double regroup_fill = 0.74;
  // ...and hold at most this many units each on average (many small units: the moves do well there,
  // and each per-hide search is long: shoe batches).
  long regroup_units_per_hide = 10;
  // Rounds the best layout keeps its number of hides before the regrouping is tried (the moves get
  // the first go: they are cheaper).
  long regroup_after_rounds = 5;
  // The regrouping's share of the time left, and at least this long (unless less is left): one
  // regrouping needs many per-hide searches.
  double regroup_time_share = 0.9;
  double regroup_min_s = 10;
};

// How hard one insertion tries; grows while no attempt succeeds (one level per failed cycle over the
// used hides), back to 0 after a success. A higher level separates longer, tries one more hide and
// drops the inserted piece at a random pose instead of the hide's centre.
struct Effort {
  int level = 0;
  int strikes = 2;
  int stale_sweeps = 15;
  int destinations = 2;
};

inline Effort effort_at(int level, const HideSearchTuning& tuning) {
  return Effort{level, tuning.strikes, tuning.stale_sweeps * (1 + level), tuning.destinations + level};
}

}  // namespace lastcut::nest_detail
