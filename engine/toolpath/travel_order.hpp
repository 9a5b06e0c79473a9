#pragma once
// The order in which the pieces are cut, chosen to keep tool-up travel short: an open path that
// starts at the machine origin and visits every piece's entry point once (a travelling-salesman
// path). Built by nearest neighbour, then improved until neither move helps:
//   2-opt (Croes 1958, "A method for solving traveling-salesman problems", Operations Research 6)
//     reverses a stretch of the tour;
//   Or-opt (Or 1976, PhD thesis, Northwestern University) moves a chain of 1 to 3 consecutive
//     stops, forwards or reversed, to another place in the tour.
// Stops may be directed: the tool arrives at a piece's entry (its label or first mark) and leaves
// from its exit (the contour's start corner, where the overcut ends), so the cost of going from
// piece a to piece b is |entry_b - exit_a| and the moves evaluate reversed stretches in full.
// Deterministic: ties are broken by index.
#include <vector>

#include "engine/core/polygon.hpp"

namespace lastcut {

// stops_mm #N points; returns a permutation of 0..N-1 (the visiting order).
std::vector<int> order_for_short_travel(const std::vector<Point2>& stops_mm, const Point2& home_mm);
// Directed version: entry_mm and exit_mm #N each.
std::vector<int> order_for_short_travel(const std::vector<Point2>& entry_mm, const std::vector<Point2>& exit_mm,
                                        const Point2& home_mm);
std::vector<int> order_by_nearest_neighbour(const std::vector<Point2>& entry_mm, const std::vector<Point2>& exit_mm,
                                            const Point2& home_mm);
// Nearest neighbour alone, without the improvement moves (for comparison in benchmarks).
std::vector<int> order_by_nearest_neighbour(const std::vector<Point2>& stops_mm, const Point2& home_mm);

// Length (mm) of the open path home -> stops_mm[order[0]] -> ... -> stops_mm[order[N-1]].
double open_path_length(const std::vector<Point2>& stops_mm, const std::vector<int>& order, const Point2& home_mm);

}  // namespace lastcut
