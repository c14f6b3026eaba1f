#pragma once
// The incrementally maintained frontier (lecture, after Algo 9.1: "examine cells in the
// neighbourhood of its position; add or remove cells whose status as frontier cells has changed").
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/explore/frontier.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// The frontier of one map, kept equal to compute_frontier(map, low) as the map changes.
///
/// Built once in O(cells); afterwards update() looks only at the cells the sensors changed. The set
/// remembers each cell's (known, p < low) state, so a touched cell whose state did not change (a
/// log-odds refinement) costs one comparison; a cell whose state changed re-examines itself and its
/// 4-neighbours. Membership is a flat per-cell slot array and the members a compact list with
/// swap-remove, so insert, erase and contains are O(1). Memory: 5 bytes per map cell.
class FrontierSet {
 public:
  FrontierSet() = default;
  /// Full computation over `map` (Algo 9.1 lines 2-6). Cost: O(cells).
  explicit FrontierSet(const OccupancyGrid& map, double low = kDefaultFrontierLow);

  /// Recomputes everything from `map`, which may have a different geometry. Cost: O(cells).
  void reset(const OccupancyGrid& map);

  /// Brings the set up to date after the cells in `touched` changed (repeats and cells outside the
  /// map are allowed). Precondition: `map` has the geometry the set was built for, and every cell
  /// changed since the last reset()/update() is in `touched` (as insert_scan and
  /// insert_cell_reading report them). Cost: O(touched) plus O(1) per cell whose state changed.
  void update(const OccupancyGrid& map, std::span<const Cell> touched);

  [[nodiscard]] double low() const { return low_; }
  [[nodiscard]] bool contains(Cell c) const {
    return geometry_.contains(c) && (state_[geometry_.index_of(c)] & kMember) != 0;
  }
  [[nodiscard]] std::size_t size() const { return members_.size(); }
  [[nodiscard]] bool empty() const { return members_.empty(); }
  /// The members in an unspecified order that changes with updates (cheap; for iteration).
  [[nodiscard]] std::span<const Cell> unordered() const { return members_; }
  /// The members sorted row-major, the order of compute_frontier(). Cost: O(n log n).
  [[nodiscard]] std::vector<Cell> cells() const;

  /// Counts the updates that changed the set or which cells are known free (p < low), the two
  /// things frontier planning reads. Planners use it to tell "nothing changed since I last failed".
  [[nodiscard]] std::uint64_t revision() const { return revision_; }

 private:
  static constexpr std::uint32_t kAbsent = 0xFFFFFFFFu;
  static constexpr std::uint8_t kKnown = 1;
  static constexpr std::uint8_t kFree = 2;
  static constexpr std::uint8_t kMember = 4;  // == (slot_ != kAbsent), without reading slot_

  [[nodiscard]] std::uint8_t state_of(const OccupancyGrid& map, Cell c) const;
  /// The frontier test from the remembered states for cell c at index i; true when membership
  /// changed.
  bool recheck(Cell c, std::size_t i);
  void insert(Cell c, std::size_t index);
  void erase(std::size_t index);

  GridGeometry geometry_;
  double low_ = kDefaultFrontierLow;
  float low_log_odds_ = 0.0f;
  std::vector<std::uint8_t> state_;  // per cell: kKnown | kFree as of the last update, kMember
  std::vector<std::uint32_t> slot_;  // per cell: position in members_, or kAbsent
  std::vector<Cell> members_;
  std::uint64_t revision_ = 0;
};

}  // namespace tessera
