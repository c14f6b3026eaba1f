#pragma once
// Private helpers shared by the frontier sources: the frontier test with `low` already converted to
// log-odds, so hot loops pay no log() per cell.
#include "tessera/core/cell.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera::explore_internal {

[[nodiscard]] inline bool has_unknown_neighbor(const OccupancyGrid& map, Cell c) {
  const GridGeometry& g = map.geometry();
  for (const Cell d : kNeighbors4) {
    const Cell n = c + d;
    if (g.contains(n) && !map.known(n)) return true;
  }
  return false;
}

/// lecture Algo 9.1 lines 3-6 for one cell. Precondition: map.geometry().contains(c).
[[nodiscard]] inline bool is_frontier_log_odds(const OccupancyGrid& map, Cell c, float low_lo) {
  return map.is_free_below(c, low_lo) && has_unknown_neighbor(map, c);
}

}  // namespace tessera::explore_internal
