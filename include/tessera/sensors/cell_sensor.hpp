#pragma once
#include <array>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// The lecture's cell robot sensor: standing in `center`, the robot tells for each of its 8
/// neighbours (kNeighbors8 order, clockwise from North) whether it holds an obstacle.
struct CellReading {
  Cell center;
  std::array<bool, 8> occupied{};
  std::array<bool, 8> inside_map{};  // false for neighbours beyond the map's edge: not reported
};

/// Probabilities written for a sensed cell (the lecture's figures use 0.1 for open and 0.9 for
/// obstacle cells).
struct CellSensorOptions {
  double p_free = 0.1;
  double p_occupied = 0.9;
};

/// Writes the reading into `map`: the centre cell becomes free (the robot stands in it) and each
/// reported neighbour gets p_free or p_occupied. Changed cells are appended to `touched` if not
/// null.
void insert_cell_reading(OccupancyGrid& map, const CellReading& reading,
                         const CellSensorOptions& options, std::vector<Cell>* touched);

}  // namespace tessera
