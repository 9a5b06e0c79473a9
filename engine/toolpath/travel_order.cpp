#include "engine/toolpath/travel_order.hpp"

#include <algorithm>
#include <limits>

namespace lastcut {
namespace {

constexpr double kMinGain_mm = 1e-9;
constexpr int kMaxRounds = 200;

// The path as points: position 0 is home, 1..N the stops in order.
struct Tour {
  std::vector<Point2> point;  // point[k]: position of the k-th visited place, k = 0 is home
  std::vector<int> stop;      // stop[k]: index into stops_mm, -1 for home
  double d(size_t a, size_t b) const { return (point[a] - point[b]).norm(); }
  size_t size() const { return point.size(); }
};

// Cost of the edge from tour position a to b, where b == size() means "no successor".
double edge(const Tour& tour, size_t a, size_t b) { return b >= tour.size() ? 0.0 : tour.d(a, b); }

bool improve_two_opt(Tour& tour) {
  bool improved = false;
  const size_t n = tour.size();
  for (size_t i = 1; i + 1 < n; ++i) {
    for (size_t j = i + 1; j < n; ++j) {
      // Reverse positions i..j: edges (i-1,i) and (j,j+1) become (i-1,j) and (i,j+1).
      const double before = tour.d(i - 1, i) + edge(tour, j, j + 1);
      const double after = tour.d(i - 1, j) + (j + 1 < n ? tour.d(i, j + 1) : 0.0);
      if (after + kMinGain_mm < before) {
        std::reverse(tour.point.begin() + i, tour.point.begin() + j + 1);
        std::reverse(tour.stop.begin() + i, tour.stop.begin() + j + 1);
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
      const size_t last = i + length - 1;  // chain is positions i..last
      const double removal_gain = tour.d(i - 1, i) + edge(tour, last, last + 1) -
                                  (last + 1 < n ? tour.d(i - 1, last + 1) : 0.0);
      // Insert between positions k and k+1 (k outside the chain, k+1 may be the end).
      for (size_t k = 0; k < n; ++k) {
        if (k + 1 >= i && k <= last) continue;
        const bool at_end = k + 1 >= n;
        const double old_edge = at_end ? 0.0 : tour.d(k, k + 1);
        for (int reversed = 0; reversed < 2; ++reversed) {
          const size_t first_in = reversed ? last : i;
          const size_t last_in = reversed ? i : last;
          const double insertion_cost = tour.d(k, first_in) + (at_end ? 0.0 : tour.d(last_in, k + 1)) - old_edge;
          if (insertion_cost + kMinGain_mm < removal_gain) {
            std::vector<Point2> chain_points(tour.point.begin() + i, tour.point.begin() + last + 1);
            std::vector<int> chain_stops(tour.stop.begin() + i, tour.stop.begin() + last + 1);
            if (reversed) {
              std::reverse(chain_points.begin(), chain_points.end());
              std::reverse(chain_stops.begin(), chain_stops.end());
            }
            tour.point.erase(tour.point.begin() + i, tour.point.begin() + last + 1);
            tour.stop.erase(tour.stop.begin() + i, tour.stop.begin() + last + 1);
            const size_t insert_at = k < i ? k + 1 : k + 1 - length;
            tour.point.insert(tour.point.begin() + insert_at, chain_points.begin(), chain_points.end());
            tour.stop.insert(tour.stop.begin() + insert_at, chain_stops.begin(), chain_stops.end());
            return true;
          }
        }
      }
    }
  }
  return false;
}

Tour nearest_neighbour_tour(const std::vector<Point2>& stops_mm, const Point2& home_mm) {
  const size_t n = stops_mm.size();
  Tour tour;
  tour.point.push_back(home_mm);
  tour.stop.push_back(-1);
  std::vector<bool> visited(n, false);
  Point2 here = home_mm;
  for (size_t step = 0; step < n; ++step) {
    int nearest = -1;
    double nearest_mm = std::numeric_limits<double>::infinity();
    for (size_t s = 0; s < n; ++s) {
      const double distance = (stops_mm[s] - here).norm();
      if (!visited[s] && distance < nearest_mm) {
        nearest_mm = distance;
        nearest = static_cast<int>(s);
      }
    }
    visited[nearest] = true;
    here = stops_mm[nearest];
    tour.point.push_back(here);
    tour.stop.push_back(nearest);
  }
  return tour;
}

}  // namespace

std::vector<int> order_by_nearest_neighbour(const std::vector<Point2>& stops_mm, const Point2& home_mm) {
  const Tour tour = nearest_neighbour_tour(stops_mm, home_mm);
  return std::vector<int>(tour.stop.begin() + 1, tour.stop.end());
}

std::vector<int> order_for_short_travel(const std::vector<Point2>& stops_mm, const Point2& home_mm) {
  const size_t n = stops_mm.size();
  Tour tour = nearest_neighbour_tour(stops_mm, home_mm);
  for (int round = 0; round < kMaxRounds; ++round) {
    const bool two_opt = improve_two_opt(tour);
    bool or_opt = false;
    for (int moves = 0; moves < 4 * static_cast<int>(n) && improve_or_opt(tour); ++moves) or_opt = true;
    if (!two_opt && !or_opt) break;
  }
  return std::vector<int>(tour.stop.begin() + 1, tour.stop.end());
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
