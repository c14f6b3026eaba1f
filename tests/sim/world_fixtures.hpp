#pragma once
// Worlds drawn in code for the sim tests.
#include <cstddef>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::support {

/// A world drawn as text, top row first (as it looks on screen): '#' solid, anything else free.
/// Cell (0, 0) is the first character of the LAST line; its lower-left corner is `origin`. The
/// world is named "ascii". Precondition: at least one row, all rows as long as the first.
inline World from_ascii(const std::vector<std::string>& rows_top_first, double resolution_m,
                        Vec2 origin = {0.0, 0.0}) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first.front().size());
  const GridGeometry g(origin, resolution_m, w, h);
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (int y = 0; y < h; ++y) {
    const std::string& row = rows_top_first[static_cast<std::size_t>(h - 1 - y)];
    for (int x = 0; x < w; ++x) solid[g.index_of({x, y})] = row[static_cast<std::size_t>(x)] == '#';
  }
  return World(g, std::move(solid), "ascii");
}

}  // namespace tessera::support
