#pragma once
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <span>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/vec2.hpp"

namespace tessera {

/// A rectangle of a grid's cells, both corners included.
struct CellBox {
  Cell min;
  Cell max;
};

/// Where a grid lies in the map frame (docs/conventions.md): cell (0,0) is the lower-left cell and
/// its lower-left corner is origin(); x is the column, y the row; row-major, index = y*width + x;
/// world->cell uses floor and a cell's centre is at +0.5.
class GridGeometry {
 public:
  GridGeometry() = default;
  /// Precondition: resolution_m > 0, width_cells >= 0, height_cells >= 0.
  GridGeometry(Vec2 origin, double resolution_m, int width_cells, int height_cells)
      : origin_(origin), resolution_m_(resolution_m), width_(width_cells), height_(height_cells) {
    TESSERA_ASSERT(resolution_m > 0.0 && width_cells >= 0 && height_cells >= 0);
  }

  [[nodiscard]] Vec2 origin() const { return origin_; }
  [[nodiscard]] double resolution_m() const { return resolution_m_; }
  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] std::size_t size() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }
  [[nodiscard]] bool operator==(const GridGeometry&) const = default;

  [[nodiscard]] bool contains(Cell c) const {
    return 0 <= c.x && c.x < width_ && 0 <= c.y && c.y < height_;
  }
  /// The cell containing p_map even when it is outside the grid.
  [[nodiscard]] Cell cell_at_unchecked(Vec2 p_map) const {
    return {static_cast<int>(std::floor((p_map.x - origin_.x) / resolution_m_)),
            static_cast<int>(std::floor((p_map.y - origin_.y) / resolution_m_))};
  }
  /// The cell containing p_map, or nullopt if p_map is outside the grid.
  [[nodiscard]] std::optional<Cell> cell_at(Vec2 p_map) const {
    const Cell c = cell_at_unchecked(p_map);
    return contains(c) ? std::optional<Cell>{c} : std::nullopt;
  }
  [[nodiscard]] Vec2 center_of(Cell c) const {
    return {origin_.x + (c.x + 0.5) * resolution_m_, origin_.y + (c.y + 0.5) * resolution_m_};
  }
  /// Precondition: contains(c).
  [[nodiscard]] std::size_t index_of(Cell c) const {
    TESSERA_ASSERT(contains(c));
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(c.x);
  }
  /// Inverse of index_of. Precondition: index < size().
  [[nodiscard]] Cell cell_of(std::size_t index) const {
    TESSERA_ASSERT(index < size());
    return {static_cast<int>(index % static_cast<std::size_t>(width_)),
            static_cast<int>(index / static_cast<std::size_t>(width_))};
  }

 private:
  Vec2 origin_{};
  double resolution_m_ = 1.0;
  int width_ = 0;
  int height_ = 0;
};

/// The smallest box of the cells of `g` whose value in `cells` (one per cell, in index_of order)
/// is not zero: the known cells of a grid that stores "unknown" as 0. Nullopt when there is none.
/// Cost: O(cells), a row at a time.
template <typename T>
[[nodiscard]] std::optional<CellBox> nonzero_box(const GridGeometry& g, std::span<const T> cells) {
  TESSERA_ASSERT(cells.size() == g.size());
  const auto w = static_cast<std::size_t>(g.width());
  int x0 = g.width(), y0 = g.height(), x1 = -1, y1 = -1;
  const auto nonzero = [](T v) { return v != T{}; };
  for (int y = 0; y < g.height(); ++y) {
    const auto row = cells.subspan(static_cast<std::size_t>(y) * w, w);
    const auto first = std::find_if(row.begin(), row.end(), nonzero);
    if (first == row.end()) continue;
    const auto last = std::find_if(row.rbegin(), row.rend(), nonzero);
    x0 = std::min(x0, static_cast<int>(first - row.begin()));
    x1 = std::max(x1, static_cast<int>(row.rend() - last) - 1);
    y0 = std::min(y0, y);
    y1 = y;
  }
  if (x1 < 0) return std::nullopt;
  return CellBox{{x0, y0}, {x1, y1}};
}

}  // namespace tessera
