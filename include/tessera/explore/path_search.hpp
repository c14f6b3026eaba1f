#pragma once
// Breadth-first search over the known free cells of a map: the frontier algorithm's "move to the
// closest frontier cell" (lecture Algo 9.1 line 8) measured as path length around known obstacles,
// not as straight-line distance. Moves are the lecture robot's: one cell N, E, S or W.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/explore/frontier.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

class FrontierSet;

/// A reusable breadth-first search over known free cells (known and p < low), 4-connected.
///
/// Cells come out of next() in BFS order: by distance, and within one distance in discovery order,
/// where each cell's neighbours are discovered in kNeighbors4 order (N, E, S, W). That order is the
/// tie-break of every "nearest" query, so results are deterministic. The start cell is always
/// expanded whatever the map says about it (the robot stands in it); every other cell on a path is
/// known free. Buffers are stamped with a generation number and reused, so starting a search costs
/// O(1) (O(cells) only when the geometry changes); a search costs O(cells it visits).
class FreeSpaceBfs {
 public:
  FreeSpaceBfs() = default;

  /// Starts a new search. `map` must outlive the search and must not change during it.
  /// Precondition: map.geometry().contains(start), 0 < low < 1.
  void start(const OccupancyGrid& map, Cell start, double low = kDefaultFrontierLow);
  /// The next cell in BFS order (the start first), or nullopt when the search is exhausted.
  [[nodiscard]] std::optional<Cell> next();
  /// Runs the search to exhaustion. Returns the number of cells reached (start included).
  std::size_t run_to_completion();

  [[nodiscard]] Cell start_cell() const { return start_; }
  /// True when the current search has discovered `c` (any cell; false outside the map).
  [[nodiscard]] bool discovered(Cell c) const;
  /// Path length in cells from the start to a discovered cell, or -1.
  [[nodiscard]] int distance(Cell c) const;
  /// The BFS path from the start to a discovered cell, both inclusive; empty if not discovered.
  /// Cost: O(path length).
  [[nodiscard]] std::vector<Cell> path_to(Cell c) const;

 private:
  void expand(std::uint32_t index);

  const OccupancyGrid* map_ = nullptr;
  float low_log_odds_ = 0.0f;
  Cell start_{};
  std::uint32_t generation_ = 0;
  std::vector<std::uint32_t> stamp_;    // == generation_ when discovered in this search
  std::vector<std::int32_t> distance_;  // valid where stamped
  std::vector<std::uint8_t> from_dir_;  // kNeighbors4 index of the step that reached the cell
  std::vector<std::uint32_t> queue_;
  std::size_t head_ = 0;
};

/// Path length in cells from `start` to every cell, -1 where unreachable through known free cells.
/// Row-major, one int per cell. Cost: O(cells).
[[nodiscard]] std::vector<int> free_space_distances(const OccupancyGrid& map, Cell start,
                                                    double low = kDefaultFrontierLow);

/// A shortest 4-connected path from `start` to `goal` through known free cells, both inclusive
/// (BFS tie-break N, E, S, W); empty when `goal` cannot be reached.
[[nodiscard]] std::vector<Cell> shortest_free_path(const OccupancyGrid& map, Cell start, Cell goal,
                                                   double low = kDefaultFrontierLow);

/// The frontier cell closest to the robot and the path to it.
struct FrontierPath {
  Cell target;
  int distance_cells = 0;
  std::vector<Cell> path;  // robot cell first, target last
};

/// The frontier cell with the shortest path from `start` (lecture Algo 9.1 line 8, "cell in
/// frontier nearest robot", with distance measured along known free cells), stopping the search at
/// the first one. Ties: the first found in BFS order (N, E, S, W). nullopt when no frontier cell is
/// reachable. `bfs` is a reused workspace. Cost: O(cells within the target's distance).
[[nodiscard]] std::optional<FrontierPath> nearest_frontier(FreeSpaceBfs& bfs,
                                                           const OccupancyGrid& map,
                                                           const FrontierSet& frontier, Cell start);

}  // namespace tessera
