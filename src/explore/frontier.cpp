#include "tessera/explore/frontier.hpp"

#include "internal/frontier_check.hpp"

namespace tessera {

int unknown_neighbors(const OccupancyGrid& map, Cell c) {
  TESSERA_ASSERT(map.geometry().contains(c));
  int a = 0;
  for (const Cell d : kNeighbors4) {
    const Cell n = c + d;
    if (map.geometry().contains(n) && !map.known(n)) ++a;
  }
  return a;
}

bool is_frontier(const OccupancyGrid& map, Cell c, double low) {
  TESSERA_ASSERT(map.geometry().contains(c));
  return explore_internal::is_frontier_log_odds(map, c, log_odds(low));
}

std::vector<Cell> compute_frontier(const OccupancyGrid& map, double low) {
  const float low_lo = log_odds(low);
  const GridGeometry& g = map.geometry();
  std::vector<Cell> frontier;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Cell c{x, y};
      if (explore_internal::is_frontier_log_odds(map, c, low_lo)) frontier.push_back(c);
    }
  }
  return frontier;
}

}  // namespace tessera
