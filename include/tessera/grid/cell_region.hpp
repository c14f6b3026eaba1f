#pragma once
// Cell-level queries every ground truth answers the same way, whoever holds the solid cells (the
// simulator's World, eval's TruthGrid): the cells a metric box overlaps, whether a cell is well
// inside a region, and the cells a robot moving between 4-neighbours reaches from a start (the
// lecture robot's moves; BOBMapping's C).
#include <cmath>
#include <cstdint>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"

namespace tessera {

/// Cells [x0, x1) x [y0, y1) whose squares overlap the box [lo_m, hi_m] by more than a touch
/// (1e-9 cell of tolerance, so that a box edge on a cell edge does not take in the neighbour).
/// May reach outside the grid.
struct CellRange {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

[[nodiscard]] inline CellRange cells_overlapping(const GridGeometry& g, Vec2 lo_m, Vec2 hi_m) {
  constexpr double kTol = 1e-9;
  const double r = g.resolution_m();
  const Vec2 o = g.origin();
  return {static_cast<int>(std::floor((lo_m.x - o.x) / r + kTol)),
          static_cast<int>(std::floor((lo_m.y - o.y) / r + kTol)),
          static_cast<int>(std::ceil((hi_m.x - o.x) / r - kTol)),
          static_cast<int>(std::ceil((hi_m.y - o.y) / r - kTol))};
}

/// True when solid(c) holds for a cell the box [lo_m, hi_m] overlaps.
template <class IsSolid>
[[nodiscard]] bool any_cell_in(const GridGeometry& g, Vec2 lo_m, Vec2 hi_m, const IsSolid& solid) {
  const CellRange c = cells_overlapping(g, lo_m, hi_m);
  for (int y = c.y0; y < c.y1; ++y) {
    for (int x = c.x0; x < c.x1; ++x) {
      if (solid(Cell{x, y})) return true;
    }
  }
  return false;
}

/// True when in(c) holds for c and its 8 neighbours: c lies well inside a region, not on its edge
/// (a one-cell erosion of the region).
template <class In>
[[nodiscard]] bool inside_region_8(Cell c, const In& in) {
  if (!in(c)) return false;
  for (const Cell d : kNeighbors8) {
    if (!in(c + d)) return false;
  }
  return true;
}

/// One byte per cell of g: 1 where a breadth-first flood fill over 4-neighbours from `start`
/// arrives without entering a cell for which solid(c) holds (solid must hold outside the grid).
/// All zero when the start itself is solid. Cost: O(cells).
template <class IsSolid>
[[nodiscard]] std::vector<std::uint8_t> reachable_4(const GridGeometry& g, Cell start,
                                                    const IsSolid& solid) {
  std::vector<std::uint8_t> reached(g.size(), 0);
  if (solid(start)) return reached;
  std::vector<Cell> queue;
  queue.reserve(64);
  reached[g.index_of(start)] = 1;
  queue.push_back(start);
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const Cell c = queue[head];
    for (const Cell d : kNeighbors4) {
      const Cell n = c + d;
      if (solid(n)) continue;
      std::uint8_t& r = reached[g.index_of(n)];
      if (r != 0) continue;
      r = 1;
      queue.push_back(n);
    }
  }
  return reached;
}

}  // namespace tessera
