#include "tessera/sim/world.hpp"

#include "tessera/grid/cell_region.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "tessera/core/assert.hpp"
#include "tessera/grid/ray_cast.hpp"

namespace tessera {

World::World(const GridGeometry& geometry, std::vector<std::uint8_t> solid, std::string name)
    : geometry_(geometry), solid_(std::move(solid)), name_(std::move(name)) {
  TESSERA_ASSERT(solid_.size() == geometry_.size());
}

World World::from_map(const OccupancyGrid& map, double free_below, std::string name) {
  const GridGeometry& geometry = map.geometry();
  std::vector<std::uint8_t> solid(geometry.size(), 1);
  for (std::size_t i = 0; i < solid.size(); ++i) {
    const std::optional<double> p = map.probability_at(geometry.cell_of(i));
    if (p.has_value() && *p < free_below) solid[i] = 0;
  }
  return World(geometry, std::move(solid), std::move(name));
}

std::size_t World::free_count() const {
  return static_cast<std::size_t>(std::count(solid_.begin(), solid_.end(), std::uint8_t{0}));
}

World World::resampled(double resolution_m) const {
  TESSERA_ASSERT(resolution_m > 0.0);
  // ratio = coarse cell size in fine cells. A tolerance keeps exact multiples (0.05 -> 0.1) from
  // picking up a neighbour through rounding.
  constexpr double kTol = 1e-9;
  const double ratio = resolution_m / geometry_.resolution_m();
  const auto cells_covering = [&](int fine_cells) {
    return static_cast<int>(std::ceil(static_cast<double>(fine_cells) / ratio - kTol));
  };
  const GridGeometry coarse(geometry_.origin(), resolution_m, cells_covering(geometry_.width()),
                            cells_covering(geometry_.height()));
  // Fine cells overlapping coarse cell i with positive length along one axis: [lo, hi].
  const auto fine_range = [&](int i) {
    const int lo = static_cast<int>(std::floor(i * ratio + kTol));
    const int hi = static_cast<int>(std::ceil((i + 1) * ratio - kTol)) - 1;
    return std::pair<int, int>{lo, std::max(lo, hi)};
  };
  std::vector<std::uint8_t> solid(coarse.size(), 0);
  for (int cy = 0; cy < coarse.height(); ++cy) {
    const auto [y_lo, y_hi] = fine_range(cy);
    for (int cx = 0; cx < coarse.width(); ++cx) {
      const auto [x_lo, x_hi] = fine_range(cx);
      // Any-solid pooling; fine cells beyond the source grid count as solid (World::solid).
      bool any = false;
      for (int y = y_lo; y <= y_hi && !any; ++y) {
        for (int x = x_lo; x <= x_hi && !any; ++x) any = this->solid({x, y});
      }
      solid[coarse.index_of({cx, cy})] = any ? 1 : 0;
    }
  }
  return World(coarse, std::move(solid), name_);
}

bool World::any_solid_in(Vec2 lo_m, Vec2 hi_m) const {
  return any_cell_in(geometry_, lo_m, hi_m, [this](Cell c) { return solid(c); });
}

double World::distance_to_solid(Vec2 p_m, double search_m) const {
  TESSERA_ASSERT(search_m >= 0.0);
  const double r = geometry_.resolution_m();
  const Cell c = geometry_.cell_at_unchecked(p_m);
  const int k = static_cast<int>(std::ceil(search_m / r)) + 1;
  double best = std::numeric_limits<double>::infinity();
  for (int dy = -k; dy <= k; ++dy) {
    for (int dx = -k; dx <= k; ++dx) {
      const Cell s{c.x + dx, c.y + dy};
      if (!solid(s)) continue;
      // Gap between p_m and the cell's square along each axis, 0 where p_m is within its span.
      const double x0 = geometry_.origin().x + s.x * r, y0 = geometry_.origin().y + s.y * r;
      const double gx = std::max({x0 - p_m.x, 0.0, p_m.x - (x0 + r)});
      const double gy = std::max({y0 - p_m.y, 0.0, p_m.y - (y0 + r)});
      best = std::min(best, std::hypot(gx, gy));
    }
  }
  return best;
}

World World::cropped(Vec2 lo_m, Vec2 hi_m) const {
  const CellRange c = cells_overlapping(geometry_, lo_m, hi_m);
  const double r = geometry_.resolution_m();
  const int w = std::max(0, c.x1 - c.x0);
  const int h = std::max(0, c.y1 - c.y0);
  const GridGeometry g(geometry_.origin() + Vec2{c.x0 * r, c.y0 * r}, r, w, h);
  std::vector<std::uint8_t> solid(g.size(), 1);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      solid[g.index_of({x, y})] = this->solid({c.x0 + x, c.y0 + y}) ? 1 : 0;
    }
  }
  return World(g, std::move(solid), name_);
}

double World::cast_ray(Vec2 from_m, double angle_rad, double max_range_m) const {
  TESSERA_ASSERT(max_range_m >= 0.0);
  const Vec2 to_m = from_m + Vec2{std::cos(angle_rad), std::sin(angle_rad)} * max_range_m;
  double hit_m = max_range_m;
  traverse_ray(geometry_, from_m, to_m, [&](Cell c, double t_enter_m, double) {
    if (!solid(c)) return true;
    hit_m = t_enter_m;  // the ray enters the first solid cell here (0 when it starts in one)
    return false;
  });
  return std::min(hit_m, max_range_m);
}

std::vector<std::uint8_t> World::reachable_from(Cell start) const {
  // solid() holds outside the grid, so a start outside reaches nothing.
  return reachable_4(geometry_, start, [this](Cell c) { return solid(c); });
}

World::FreeComponents World::free_components() const {
  FreeComponents out;
  out.label.assign(geometry_.size(), -1);
  std::vector<Cell> queue;
  for (std::size_t i = 0; i < geometry_.size(); ++i) {
    if (out.label[i] >= 0 || solid_[i] != 0) continue;
    const auto k = static_cast<std::int32_t>(out.sizes.size());
    out.label[i] = k;
    queue.assign(1, geometry_.cell_of(i));
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for (const Cell d : kNeighbors4) {
        const Cell n = queue[head] + d;
        if (solid(n)) continue;  // also outside the grid
        std::int32_t& l = out.label[geometry_.index_of(n)];
        if (l >= 0) continue;
        l = k;
        queue.push_back(n);
      }
    }
    out.sizes.push_back(queue.size());
  }
  return out;
}

}  // namespace tessera
