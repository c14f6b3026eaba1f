#include "tessera/eval/bob_table.hpp"

#include <vector>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

/// Errors over the sensed cells of the final map, with the band and strictly (BobTableRow).
void count_errors(const BobRunCells& run, const TruthGrid& world, const TruthGrid& truth,
                  double tolerance_m, BobTableRow& row) {
  const GridGeometry& g = truth.geometry();
  const double cell_m = g.resolution_m();
  const Vec2 half{0.5 * cell_m, 0.5 * cell_m};
  const Vec2 band{tolerance_m, tolerance_m};
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (run.sensed[i] == 0) continue;
    ++row.sensed_cells;
    const Cell c = g.cell_of(i);
    const Vec2 centre = g.center_of(c);
    if (run.occupied[i] != 0) {
      if (truth.free(c)) ++row.empty_as_occupied_strict;
      if (!world.any_solid_in(centre - half - band, centre + half + band)) {
        ++row.empty_as_occupied;
      }
    } else {
      if (truth.solid(c)) ++row.occupied_as_empty_strict;
      if (world.any_solid_in(centre - half + band, centre + half - band)) {
        ++row.occupied_as_empty;
      }
    }
  }
}

/// C and E of the SmartDFS bound (Icking et al. 2005) from the start.
void count_reachable(const TruthGrid& truth, Cell start, BobTableRow& row) {
  const GridGeometry& g = truth.geometry();
  const std::vector<std::uint8_t> reachable = truth.reachable_from(start);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (reachable[i] == 0) continue;
    ++row.free_reachable;
    const Cell c = g.cell_of(i);
    for (const Cell d : kNeighbors4) {
      const Cell m = c + d;
      if (!g.contains(m) || reachable[g.index_of(m)] == 0) ++row.boundary_edges;
    }
  }
}

}  // namespace

BobTableRow score_bob_table(const BobRunCells& run, const TruthGrid& world, const TruthGrid& grid_truth,
                            double boundary_tolerance_m) {
  const GridGeometry& g = grid_truth.geometry();
  TESSERA_ASSERT(run.sensed.size() == g.size() && run.occupied.size() == g.size());
  TESSERA_ASSERT(!run.route.empty());
  BobTableRow row;
  row.cells = static_cast<int>(g.size());
  std::vector<std::uint8_t> visited(g.size(), 0);
  for (const Cell c : run.route) visited[g.index_of(c)] = 1;
  for (const std::uint8_t v : visited) row.visited_cells += v;
  count_errors(run, world, grid_truth, boundary_tolerance_m, row);
  row.resensed = run.resensed;
  row.ignored_readings = run.ignored_readings;
  row.path_cells = run.moves;
  row.turns = run.turns;
  row.success_rate =
      static_cast<double>(row.cells - row.empty_as_occupied - row.occupied_as_empty) / row.cells;
  row.success_rate_strict =
      static_cast<double>(row.cells - row.empty_as_occupied_strict - row.occupied_as_empty_strict) /
      row.cells;
  row.path_share = static_cast<double>(row.path_cells) / row.cells;
  row.visited_share = static_cast<double>(row.visited_cells) / row.cells;
  count_reachable(grid_truth, run.route.front(), row);
  const double c_cells = row.free_reachable;
  row.path_per_c = c_cells > 0 ? row.path_cells / c_cells : 0.0;
  const double bound = c_cells + 0.5 * row.boundary_edges - 3.0;
  row.path_per_smartdfs = bound > 0 ? row.path_cells / bound : 0.0;
  return row;
}

}  // namespace tessera
