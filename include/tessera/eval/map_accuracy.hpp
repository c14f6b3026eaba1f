#pragma once
// Map accuracy against ground truth, as BOBMapping's Table 1 counts it: of the cells the map knows,
// how many are right, how many empty cells were sensed as occupied and how many occupied cells were
// sensed as empty (the dangerous error: a planner would drive into them).
#include <cstddef>

#include "tessera/core/pose2.hpp"
#include "tessera/eval/truth_grid.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

struct MapAccuracy {
  std::size_t cells_compared = 0;  // cells the map knows
  std::size_t correct = 0;
  std::size_t empty_as_occupied = 0;  // truth free, map p >= occupied_threshold
  std::size_t occupied_as_empty = 0;  // truth solid, map p < occupied_threshold
  std::size_t occupied_compared = 0;  // known cells whose truth is solid
  double success_rate = 0.0;          // correct / cells_compared; 0 when nothing was compared

  /// occupied_as_empty / occupied_compared; 0 when no solid cell was compared.
  [[nodiscard]] double occupied_as_empty_share() const {
    return occupied_compared == 0
               ? 0.0
               : static_cast<double>(occupied_as_empty) / static_cast<double>(occupied_compared);
  }
};

/// Compares every known cell of `map` with `truth` cell by cell (threshold view: occupied when
/// p >= occupied_threshold). Unknown cells are not compared.
/// Precondition: map and truth have the same width and height. Cost: O(cells).
[[nodiscard]] MapAccuracy compare_to_truth(const OccupancyGrid& map, const TruthGrid& truth,
                                           double occupied_threshold = 0.5);

/// The map as its picture shows it (a ROS map_saver image, io/map_yaml.hpp): free where
/// p <= free_at_most, occupied where p >= occupied_from, and cells in between, shown as unknown,
/// not compared. What a user or a planner loading the saved map sees: a wall cell the map is
/// unsure of (seen only at grazing angles) is shown grey, not free. Precondition: same width and
/// height, free_at_most < occupied_from. Cost: O(cells).
[[nodiscard]] MapAccuracy compare_to_truth_as_shown(const OccupancyGrid& map,
                                                    const TruthGrid& truth, double free_at_most,
                                                    double occupied_from);

/// The same for a map on its own grid (a SLAM map: another origin and cell size, its own frame):
/// a known map cell's truth is the world cell holding T_truth_map * (the map cell's centre), solid
/// outside the world. T_truth_map aligns the map to the truth, e.g. the rigid alignment of the
/// trajectory that built it (a SLAM map is anchored at its first pose, so a small heading error
/// turns far walls away from where they are; ATE removes it, so must the map comparison). Map cells
/// close to the world's resolution suit it best; a wall face inside a map cell counts as the side
/// the centre falls on. Cost: O(map cells).
[[nodiscard]] MapAccuracy compare_to_truth_at_centres(const OccupancyGrid& map,
                                                      const TruthGrid& truth,
                                                      const Pose2& T_truth_map = {},
                                                      double occupied_threshold = 0.5);

}  // namespace tessera
