#pragma once
// The ground truth a map is scored against (map_accuracy.hpp, BOBMapping Table 1): which cells of a
// grid are solid. A view over one byte per cell, so that a simulator's world
// (sim/world.hpp: World::solid_cells), a floor plan read from a file or a surveyed map of a real
// robot's floor can each be the truth without eval depending on where it came from.
#include <cstdint>
#include <span>
#include <vector>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/cell_region.hpp"
#include "tessera/grid/grid_geometry.hpp"

namespace tessera {

class TruthGrid {
 public:
  /// `solid`: one byte per cell of `geometry`, row-major, 1 = solid, 0 = free. The bytes are not
  /// copied: they must outlive the view. Precondition: solid.size() == geometry.size().
  TruthGrid(const GridGeometry& geometry, std::span<const std::uint8_t> solid)
      : geometry_(geometry), solid_(solid) {
    TESSERA_ASSERT(solid_.size() == geometry_.size());
  }

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }

  /// True for solid cells and for every cell outside the grid (a robot can neither see nor drive
  /// there), as the simulator's World counts them.
  [[nodiscard]] bool solid(Cell c) const {
    return !geometry_.contains(c) || solid_[geometry_.index_of(c)] != 0;
  }
  [[nodiscard]] bool free(Cell c) const { return !solid(c); }

  /// True when a solid cell overlaps the box [lo_m, hi_m] (World::any_solid_in's rule).
  [[nodiscard]] bool any_solid_in(Vec2 lo_m, Vec2 hi_m) const {
    return any_cell_in(geometry_, lo_m, hi_m, [this](Cell c) { return solid(c); });
  }

  /// The free cells 4-connected to `start` (World::reachable_from's rule), one byte per cell.
  [[nodiscard]] std::vector<std::uint8_t> reachable_from(Cell start) const {
    return reachable_4(geometry_, start, [this](Cell c) { return solid(c); });
  }

 private:
  GridGeometry geometry_;
  std::span<const std::uint8_t> solid_;
};

}  // namespace tessera
