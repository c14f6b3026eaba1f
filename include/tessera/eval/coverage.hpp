#pragma once
// Exploration coverage (DESIGN.md report.json): the share of the ground truth's reachable free
// cells that the map knows as free (known and p < free_below). The reachable cells come from the
// truth's owner (sim/world.hpp: World::reachable_from for a simulated world), so eval needs no
// simulator.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// Coverage of `map` over the cells marked 1 in `reachable` (one byte per cell, row-major, as
/// World::reachable_from returns it). 0 when no cell is reachable.
/// Precondition: reachable.size() == map.geometry().size(). Cost: O(cells).
[[nodiscard]] double coverage(const OccupancyGrid& map, std::span<const std::uint8_t> reachable,
                              double free_below = 0.5);

/// Coverage kept up to date from the cells the sensors touched: O(touched) per update instead of
/// O(cells). Memory: 2 bytes per cell.
class CoverageTracker {
 public:
  CoverageTracker() = default;
  /// `reachable`: one byte per cell of the map's geometry, 1 = reachable free cell of the truth.
  /// Starts as for an all-unknown map (nothing covered); reset() adopts a map that knows cells.
  explicit CoverageTracker(std::vector<std::uint8_t> reachable, double free_below = 0.5);

  /// Recounts from `map`. Cost: O(cells).
  void reset(const OccupancyGrid& map);
  /// Re-examines the touched cells (repeats and cells outside the map allowed). Precondition: every
  /// cell changed since the last reset()/update() is in `touched`.
  void update(const OccupancyGrid& map, std::span<const Cell> touched);

  [[nodiscard]] std::size_t reachable_cells() const { return reachable_count_; }
  [[nodiscard]] std::size_t covered_cells() const { return covered_count_; }
  /// covered / reachable; 0 when nothing is reachable.
  [[nodiscard]] double coverage() const {
    return reachable_count_ == 0
               ? 0.0
               : static_cast<double>(covered_count_) / static_cast<double>(reachable_count_);
  }

 private:
  std::vector<std::uint8_t> reachable_;
  std::vector<std::uint8_t> covered_;
  float free_below_log_odds_ = 0.0f;
  std::size_t reachable_count_ = 0;
  std::size_t covered_count_ = 0;
};

}  // namespace tessera
