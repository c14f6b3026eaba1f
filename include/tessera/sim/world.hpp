#pragma once
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// Ground truth for the simulator: which cells are solid. Unknown space in a source map counts as
/// solid (a robot can neither see into nor drive through it), and so does everything outside the
/// grid. Cells, not a cost map: the robot occupies one cell of the exploration grid
/// (docs/decisions/0002-robot-is-one-cell.md).
class World {
 public:
  World() = default;
  /// Precondition: solid.size() == geometry.size(); 1 = solid, 0 = free.
  World(const GridGeometry& geometry, std::vector<std::uint8_t> solid, std::string name = {});

  /// A world from a map: free where the cell is known and p < free_below, solid elsewhere.
  [[nodiscard]] static World from_map(const OccupancyGrid& map, double free_below = 0.5,
                                      std::string name = {});

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  [[nodiscard]] const std::string& name() const { return name_; }
  /// True for solid cells and for every cell outside the grid.
  [[nodiscard]] bool solid(Cell c) const {
    return !geometry_.contains(c) || solid_[geometry_.index_of(c)] != 0;
  }
  [[nodiscard]] bool free(Cell c) const { return !solid(c); }
  /// One byte per cell, row-major, 1 = solid: the truth a map is scored against
  /// (eval/truth_grid.hpp views it: TruthGrid(world.geometry(), world.solid_cells())).
  [[nodiscard]] std::span<const std::uint8_t> solid_cells() const { return solid_; }
  [[nodiscard]] std::size_t free_count() const;

  /// The same world on a grid of `resolution_m` covering the same extent. A coarse cell is solid
  /// when any fine cell it overlaps is solid, so thin walls never open (errors fall on the safe
  /// side). Precondition: resolution_m > 0.
  [[nodiscard]] World resampled(double resolution_m) const;

  /// True when a solid cell overlaps the rectangle [lo_m, hi_m] with positive area (cells outside
  /// the grid count as solid). Cost: O(cells the rectangle overlaps).
  [[nodiscard]] bool any_solid_in(Vec2 lo_m, Vec2 hi_m) const;

  /// Euclidean distance from p_m to the nearest point of a solid cell (cells outside the grid
  /// count as solid), exact whenever that distance is at most search_m. Only the cells within
  /// ceil(search_m / resolution) + 1 of p_m's cell are examined, so a larger result only says "more
  /// than search_m"; infinity when none of them is solid. 0 inside a solid cell.
  /// Precondition: search_m >= 0. Cost: O((search_m / resolution)^2).
  [[nodiscard]] double distance_to_solid(Vec2 p_m, double search_m) const;

  /// The part of this world inside the rectangle [lo_m, hi_m], at the same resolution: the fine
  /// cells the rectangle overlaps, so the new origin is lo_m snapped down to a cell corner. Cells
  /// of the rectangle outside this grid are solid. Empty world when the rectangle is empty.
  /// Used to cut a room out of a floor plan (tessera --crop). Cost: O(cells of the result).
  [[nodiscard]] World cropped(Vec2 lo_m, Vec2 hi_m) const;

  /// Distance from `from_m` along `angle_rad` to the first solid cell boundary, exact on the grid
  /// (Amanatides & Woo traversal); max_range_m when nothing is hit within it. 0 when from_m lies in
  /// a solid cell or outside the grid. A ray through an exact cell corner takes the x step first
  /// (grid/ray_cast.hpp), so it stops there if the cell beside it in x is solid.
  /// Cost: O(distance / resolution).
  [[nodiscard]] double cast_ray(Vec2 from_m, double angle_rad, double max_range_m) const;

  /// Free cells 4-connected to `start` (the lecture robot's moves): the space a robot can explore.
  /// Returns one byte per cell (1 = reachable). Empty start or solid start: all zero.
  [[nodiscard]] std::vector<std::uint8_t> reachable_from(Cell start) const;

  /// The 4-connected components of the free space. label[index_of(c)] is c's component (-1 for a
  /// solid cell); components are numbered in row-major order of their first cell, and sizes[k]
  /// counts component k's cells. Cost: O(cells).
  struct FreeComponents {
    std::vector<std::int32_t> label;
    std::vector<std::size_t> sizes;
  };
  [[nodiscard]] FreeComponents free_components() const;

 private:
  GridGeometry geometry_;
  std::vector<std::uint8_t> solid_;
  std::string name_;
};

}  // namespace tessera
