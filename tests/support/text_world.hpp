#pragma once
// A small World drawn as text for tests: one string per row, top row first; '#' is solid, any
// other character free, and 'R' (when `start` is given) marks the cell returned in *start.
// Header-only: a test that includes it links tessera::sim.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tessera/sim/world.hpp"

namespace tessera::support {

inline World text_world(const std::vector<std::string>& rows, double cell_m,
                        Cell* start = nullptr) {
  const int h = static_cast<int>(rows.size());
  const int w = static_cast<int>(rows.front().size());
  const GridGeometry g({0.0, 0.0}, cell_m, w, h);
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (int r = 0; r < h; ++r) {
    for (int x = 0; x < w; ++x) {
      const char ch = rows[static_cast<std::size_t>(r)][static_cast<std::size_t>(x)];
      const Cell c{x, h - 1 - r};
      solid[g.index_of(c)] = ch == '#' ? 1 : 0;
      if (ch == 'R' && start != nullptr) *start = c;
    }
  }
  return World(g, std::move(solid), "text");
}

}  // namespace tessera::support
