#pragma once
// Shortest drivable routes for a round robot on a grid, given the cells where its centre may be (a
// mask: sim/tour.hpp's room_for_robot, cells at least a clearance from every wall). One planner
// for the simulated laser run's covering tour (sim/tour.hpp) and the teach-and-repeat experiment's
// taught route (mission/teach_and_repeat.hpp):
//  1. Dijkstra over the mask cells, 8-connected (steps of 1 and sqrt(2) cells); a diagonal step
//     needs both cells beside it, so a path never cuts a corner of a cell outside the mask and the
//     straight segment between consecutive cell centres lies in mask cells. Ties settle in order of
//     cell index.
//  2. String pulling with an exact segment check: a vertex is dropped while the straight segment
//     that replaces it passes only through mask cells, every cell it touches found by an exact
//     grid traversal (grid/ray_cast.hpp, Amanatides & Woo 1987), corner touches included. A
//     route's legs therefore keep the mask's clearance everywhere, not only at sampled points.
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <string>
#include <utility>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"

namespace tessera {

/// Step 1: Dijkstra over the cells of a mask. Buffers are reused between searches (stamped with a
/// generation number). Holds references to the geometry and the mask: both must outlive it.
class MaskDijkstra {
 public:
  MaskDijkstra(const GridGeometry& g, const std::vector<std::uint8_t>& mask);

  /// Searches from `start` (a mask cell) until `stop(cell)` is true for a settled cell; returns
  /// that cell, or nullopt when none is reachable (then every reachable cell is settled).
  template <typename Stop>
  std::optional<Cell> search(Cell start, Stop&& stop);

  /// The path of the last search from its start to `goal` (a settled cell), both inclusive.
  [[nodiscard]] std::vector<Cell> path_to(Cell goal) const;
  /// The path length in cells from the last search's start to `c`; infinity when the search did
  /// not reach it (final for settled cells, an upper bound for the others).
  [[nodiscard]] double cost_cells(Cell c) const;

 private:
  [[nodiscard]] bool in_mask(Cell c) const { return g_.contains(c) && mask_[g_.index_of(c)] != 0; }
  void discover(std::size_t i, double cost, std::size_t parent);
  /// Settles the next cell of the open list; nullopt when it is empty.
  std::optional<Cell> settle_next();

  const GridGeometry& g_;
  const std::vector<std::uint8_t>& mask_;
  std::vector<double> cost_;
  std::vector<std::size_t> parent_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t generation_ = 0;
  using Entry = std::pair<double, std::size_t>;  // cost, cell index
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open_;
};

/// True when every cell the segment a -> b passes through (corner touches included) is in the
/// mask. Cost: O(cells crossed).
[[nodiscard]] bool segment_in_mask(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                                   Vec2 a, Vec2 b);

/// Step 2: from each kept vertex, the path goes straight to the furthest following vertex it can
/// reach along a segment inside the mask (extending one vertex at a time); a vertex within 1e-9 m
/// of the last kept one is dropped. Keeps the first and last points. Only for a path that never
/// doubles back (a shortest path): one that goes into a dead end and out again would be pulled
/// past the dead end. Cost: O(points * segment length in cells).
[[nodiscard]] std::vector<Vec2> string_pull(const GridGeometry& g,
                                            const std::vector<std::uint8_t>& mask,
                                            const std::vector<Vec2>& points);

/// Steps 1 and 2 from `from_m` to `to_m`: the shortest mask path between their cells, its ends
/// replaced by the two points, string-pulled. Starts with from_m and ends with to_m. Input error
/// (naming the point, "route: start (x, y) m has no room ...") when either end is outside the map
/// or not in the mask, or when no mask path joins them. Cost: one Dijkstra search.
[[nodiscard]] Result<std::vector<Vec2>> plan_mask_route(const GridGeometry& g,
                                                        const std::vector<std::uint8_t>& mask,
                                                        Vec2 from_m, Vec2 to_m);

// --- implementation of the template --------------------------------------------------------------

template <typename Stop>
std::optional<Cell> MaskDijkstra::search(Cell start, Stop&& stop) {
  ++generation_;
  open_ = {};
  const std::size_t s = g_.index_of(start);
  discover(s, 0.0, s);
  open_.push({0.0, s});
  for (;;) {
    const std::optional<Cell> c = settle_next();
    if (!c.has_value()) return std::nullopt;
    if (stop(*c)) return c;
  }
}

}  // namespace tessera
