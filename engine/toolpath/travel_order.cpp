#include "engine/toolpath/travel_order.hpp"

#include <algorithm>
#include <limits>

namespace lastcut {
namespace {

constexpr double kMinGain_mm = 1e-9;
constexpr int kMaxRounds = 200;

// The stops as a directed problem: the tool arrives at entry[s] and leaves from exit[s].
// order[0] is home (-1): it has no entry and leaves from home.
struct Tour {
  const std::vector<Point2>& entry;
  const std::vector<Point2>& exit;
  Point2 home;
  std::vector<int> order;  // order[0] == -1 (home), then stop indices

  const Point2& leave(size_t position) const { return order[position] < 0 ? home : exit[order[position]]; }
  // Travel from the stop at position a to the stop at position b.
  double cost(size_t a, size_t b) const { return (entry[order[b]] - leave(a)).norm(); }
  // Travel from stop index s to stop index t (s may be -1 for home).
  double cost_between(int s, int t) const { return (entry[t] - (s < 0 ? home : exit[s])).norm(); }
  size_t size() const { return order.size(); }
};

// Total travel of positions first..last as a chain (internal edges only).
double chain_cost(const Tour& tour, const std::vector<int>& chain) {
  double total = 0.0;
  for (size_t k = 0; k + 1 < chain.size(); ++k) total += tour.cost_between(chain[k], chain[k + 1]);
  return total;
}

bool improve_two_opt(Tour& tour) {
  bool improved = false;
  const size_t n = tour.size();
  for (size_t i = 1; i + 1 < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      std::vector<int> segment(tour.order.begin() + i, tour.order.begin() + j + 1);
      double before = tour.cost(i - 1, i) + chain_cost(tour, segment) + (j + 1 < n ? tour.cost(j, j + 1) : 0.0);
      std::reverse(segment.begin(), segment.end());
      double after = tour.cost_between(tour.order[i - 1], segment.front()) + chain_cost(tour, segment) +
                     (j + 1 < n ? tour.cost_between(segment.back(), tour.order[j + 1]) : 0.0);
      if (after + kMinGain_mm < before) {
        std::reverse(tour.order.begin() + i, tour.order.begin() + j + 1);
        improved = true;
      }
    }
  }
  return improved;
}

bool improve_or_opt(Tour& tour) {
  const size_t n = tour.size();
  for (size_t length = 1; length <= 3; ++length) {
    for (size_t i = 1; i + length <= n; ++i) {
      const size_t last = i + length - 1;
      const std::vector<int> chain(tour.order.begin() + i, tour.order.begin() + last + 1);
      const double chain_forward = chain_cost(tour, chain);
      const double removal_gain = tour.cost(i - 1, i) + chain_forward + (last + 1 < n ? tour.cost(last, last + 1) : 0.0) -
                                  (last + 1 < n ? tour.cost(i - 1, last + 1) : 0.0);
      std::vector<int> rest = tour.order;
      rest.erase(rest.begin() + i, rest.begin() + last + 1);
      for (size_t k = 0; k < rest.size(); ++k) {  // insert after rest[k]
        if (k == i - 1) continue;                 // where it came from
        const bool at_end = k + 1 >= rest.size();
        const double old_edge = at_end ? 0.0 : tour.cost_between(rest[k], rest[k + 1]);
        for (int reversed = 0; reversed < 2; ++reversed) {
          std::vector<int> moved = chain;
          if (reversed) std::reverse(moved.begin(), moved.end());
          const double insertion_cost = tour.cost_between(rest[k], moved.front()) + chain_cost(tour, moved) +
                                        (at_end ? 0.0 : tour.cost_between(moved.back(), rest[k + 1])) - old_edge;
          if (insertion_cost + kMinGain_mm < removal_gain) {
            rest.insert(rest.begin() + k + 1, moved.begin(), moved.end());
            tour.order = rest;
            return true;
          }
        }
      }
    }
  }
  return false;
}

Tour nearest_neighbour_tour(const std::vector<Point2>& entry, const std::vector<Point2>& exit, const Point2& home) {
  const size_t n = entry.size();
  Tour tour{entry, exit, home, {-1}};
  std::vector<bool> visited(n, false);
  int here = -1;
  for (size_t step = 0; step < n; ++step) {
    int nearest = -1;
    double nearest_mm = std::numeric_limits<double>::infinity();
    for (size_t s = 0; s < n; ++s) {
      const double distance = tour.cost_between(here, static_cast<int>(s));
      if (!visited[s] && distance < nearest_mm) {
        nearest_mm = distance;
        nearest = static_cast<int>(s);
      }
    }
    visited[nearest] = true;
    tour.order.push_back(nearest);
    here = nearest;
  }
  return tour;
}

}  // namespace

std::vector<int> order_by_nearest_neighbour(const std::vector<Point2>& entry_mm, const std::vector<Point2>& exit_mm,
                                            const Point2& home_mm) {
  const Tour tour = nearest_neighbour_tour(entry_mm, exit_mm, home_mm);
  return std::vector<int>(tour.order.begin() + 1, tour.order.end());
}

std::vector<int> order_for_short_travel(const std::vector<Point2>& entry_mm, const std::vector<Point2>& exit_mm,
                                        const Point2& home_mm) {
  const size_t n = entry_mm.size();
  Tour tour = nearest_neighbour_tour(entry_mm, exit_mm, home_mm);
  for (int round = 0; round < kMaxRounds; ++round) {
    const bool two_opt = improve_two_opt(tour);
    bool or_opt = false;
    for (int moves = 0; moves < 4 * static_cast<int>(n) && improve_or_opt(tour); ++moves) or_opt = true;
    if (!two_opt && !or_opt) break;
  }
  return std::vector<int>(tour.order.begin() + 1, tour.order.end());
}

std::vector<int> order_for_short_travel(const std::vector<Point2>& stops_mm, const Point2& home_mm) {
  return order_for_short_travel(stops_mm, stops_mm, home_mm);
}

std::vector<int> order_by_nearest_neighbour(const std::vector<Point2>& stops_mm, const Point2& home_mm) {
  return order_by_nearest_neighbour(stops_mm, stops_mm, home_mm);
}

double open_path_length(const std::vector<Point2>& stops_mm, const std::vector<int>& order, const Point2& home_mm) {
  double length_mm = 0.0;
  Point2 here = home_mm;
  for (int stop : order) {
    length_mm += (stops_mm[stop] - here).norm();
    here = stops_mm[stop];
  }
  return length_mm;
}

}  // namespace lastcut
