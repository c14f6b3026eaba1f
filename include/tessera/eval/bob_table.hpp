#pragma once
// BOBMapping Table 1 for one simulated run (mission/bob_mission.hpp): the final map's errors
// against the floor plan, the path against the SmartDFS bound. The mission produces the map and
// the route; this compares them with the truth.
#include <cstdint>
#include <span>

#include "tessera/core/cell.hpp"
#include "tessera/eval/truth_grid.hpp"

namespace tessera {

/// What Table 1 reads of a run: the robot's grid cells (one byte per cell of the grid truth's
/// geometry, row-major) and the explorer's counters.
struct BobRunCells {
  std::span<const std::uint8_t> sensed;    // 1 = sensed at least once
  std::span<const std::uint8_t> occupied;  // 1 = occupied in the final map (decision 0008)
  std::span<const Cell> route;             // cells stood in, start first
  int moves = 0;                           // one-cell moves
  int turns = 0;                           // heading changes
  int resensed = 0;                        // readings that changed a sensed cell
  int ignored_readings = 0;                // readings ignored with re-sensing off
};

/// BOBMapping Table 1 for one configuration, plus the comparison with the SmartDFS bound.
struct BobTableRow {
  int cells = 0;         // cells in the configuration: every cell of the grid (W x H)
  int sensed_cells = 0;  // cells sensed at least once
  int resensed = 0;      // readings that changed an already sensed cell
  int ignored_readings = 0;  // readings of sensed cells ignored with re-sensing off
  // Errors over sensed cells of the final map (a visited cell with an obstacle detected inside
  // counts as occupied), scored with a don't-care band of boundary_tolerance_m either side of
  // each cell edge (the robot knows its grid only to its localisation error):
  int empty_as_occupied = 0;  // map occupied, but nothing solid even in the cell grown by the band
  int occupied_as_empty = 0;  // map free, but something solid in the cell shrunk by the band
  double success_rate = 0.0;  // (cells - both errors) / cells, as the paper computes it
  // The same against the cell's own edges (any solid overlap makes a cell occupied):
  int empty_as_occupied_strict = 0;
  int occupied_as_empty_strict = 0;
  double success_rate_strict = 0.0;
  int path_cells = 0;              // one-cell moves ("length path")
  int turns = 0;                   // heading changes, each counts one whatever its angle
  int visited_cells = 0;           // distinct cells stood in
  double path_share = 0.0;         // path_cells / cells (the paper's "68% of the cells")
  double visited_share = 0.0;      // visited_cells / cells
  int free_reachable = 0;          // C: free cells 4-connected to the start
  int boundary_edges = 0;          // E: edges between a C cell and a non-C cell (or the outside)
  double path_per_c = 0.0;         // path_cells / C
  double path_per_smartdfs = 0.0;  // path_cells / (C + E/2 - 3), Icking et al. 2005
};

/// Scores `run` on the robot's grid `grid_truth` (mission/bob_mission.hpp bob_grid_truth: a cell
/// is occupied when any solid cell of `world` overlaps it) with the band of boundary_tolerance_m
/// looked up in the fine `world`. Preconditions: the spans have grid_truth's size; the route is
/// not empty and inside the grid. Cost: O(cells) plus the band look-ups in `world`.
[[nodiscard]] BobTableRow score_bob_table(const BobRunCells& run, const TruthGrid& world,
                                          const TruthGrid& grid_truth, double boundary_tolerance_m);

}  // namespace tessera
