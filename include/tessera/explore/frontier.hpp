#pragma once
// The frontier of the lecture's frontier algorithm (Ben-Ari & Mondada, lecture Algo 9.1 lines 3-6):
// a frontier cell is a known cell with occupancy probability below `low` that has at least one
// unknown 4-neighbour ("adjacent (left, right, up, down)"; diagonal neighbours are not adjacent).
// Cells outside the map are not unknown: a cell on the map's edge is a frontier cell only because
// of unknown neighbours inside the map.
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// The default "low" occupancy probability below which a known cell counts as open.
inline constexpr double kDefaultFrontierLow = 0.5;

/// Number of 4-neighbours of `c` that lie inside the map and are unknown: the "a" of the lecture's
/// priority p = a / d ("Priority in the frontier algorithm"). Range 0..4.
/// Precondition: map.geometry().contains(c). Cost: O(1).
[[nodiscard]] int unknown_neighbors(const OccupancyGrid& map, Cell c);

/// True when `c` is a frontier cell: known, p < low and at least one unknown 4-neighbour.
/// Precondition: map.geometry().contains(c). Cost: O(1) plus one log() for `low`.
[[nodiscard]] bool is_frontier(const OccupancyGrid& map, Cell c, double low = kDefaultFrontierLow);

/// Full recomputation of the frontier (Algo 9.1 lines 2-6), in row-major order (index = y*w + x).
/// Cost: O(cells). FrontierSet maintains the same set incrementally.
[[nodiscard]] std::vector<Cell> compute_frontier(const OccupancyGrid& map,
                                                 double low = kDefaultFrontierLow);

}  // namespace tessera
