#pragma once
// Map accuracy against ground truth, as BOBMapping's Table 1 counts it: of the cells the map knows,
// how many are right, how many empty cells were sensed as occupied and how many occupied cells were
// sensed as empty (the dangerous error: a planner would drive into them).
#include <cstddef>

#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct MapAccuracy {
  std::size_t cells_compared = 0;  // cells the map knows
  std::size_t correct = 0;
  std::size_t empty_as_occupied = 0;  // truth free, map p >= occupied_threshold
  std::size_t occupied_as_empty = 0;  // truth solid, map p < occupied_threshold
  double success_rate = 0.0;          // correct / cells_compared; 0 when nothing was compared
};

/// Compares every known cell of `map` with `truth` cell by cell (threshold view: occupied when
/// p >= occupied_threshold). Unknown cells are not compared.
/// Precondition: map and truth have the same width and height. Cost: O(cells).
[[nodiscard]] MapAccuracy compare_to_truth(const OccupancyGrid& map, const World& truth,
                                           double occupied_threshold = 0.5);

}  // namespace tessera
