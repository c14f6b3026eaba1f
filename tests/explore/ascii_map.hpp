#pragma once
// Test helper: occupancy grids drawn as text. Rows are listed top first, so the last string is row
// y = 0 (cell (0,0) is lower-left). '?' unknown, '.' open (p = 0.1), '#' obstacle (p = 0.9), the
// lecture's figure values; any other letter is an open cell the test can find with find_char().
#include <string>
#include <vector>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera::test {

inline OccupancyGrid ascii_map(const std::vector<std::string>& rows_top_first) {
  const int h = static_cast<int>(rows_top_first.size());
  TESSERA_ASSERT(h > 0);
  const int w = static_cast<int>(rows_top_first[0].size());
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, w, h));
  for (int row = 0; row < h; ++row) {
    const std::string& s = rows_top_first[static_cast<std::size_t>(row)];
    TESSERA_ASSERT(static_cast<int>(s.size()) == w);
    for (int x = 0; x < w; ++x) {
      const Cell c{x, h - 1 - row};
      const char ch = s[static_cast<std::size_t>(x)];
      if (ch == '?') continue;
      map.set_probability(c, ch == '#' ? 0.9 : 0.1);
    }
  }
  return map;
}

/// The cell drawn as `ch` (the first in row-major order from the bottom row).
inline Cell find_char(const std::vector<std::string>& rows_top_first, char ch) {
  const int h = static_cast<int>(rows_top_first.size());
  for (int y = 0; y < h; ++y) {
    const std::string& s = rows_top_first[static_cast<std::size_t>(h - 1 - y)];
    for (int x = 0; x < static_cast<int>(s.size()); ++x) {
      if (s[static_cast<std::size_t>(x)] == ch) return {x, y};
    }
  }
  TESSERA_ASSERT(false && "character not in map");
  return {};
}

/// The lecture's labyrinth ("Priority in the frontier algorithm"; the figure is missing from the
/// notes, so this is a map consistent with its text). Robot at (3,3); 5 open cells (3,3), (2,3),
/// (1,3), (2,2), (3,2), of which (1,3), (2,2), (3,2) are frontier cells; 6 obstacle cells. With
/// diagonals not adjacent:
///   (3,2): neighbours (3,3) open, (2,2) open, (4,2) obstacle, (3,1) unknown -> a = 1, d = 1
///   (2,2): neighbours (2,3) open, (3,2) open, (1,2) unknown, (2,1) unknown  -> a = 2, d = 2
///   (1,3): neighbours (2,3) open, (1,4) unknown, (0,3) unknown, (1,2) unknown -> a = 3, d = 2
///   (3,3) and (2,3) have no unknown neighbour: (3,4), (4,3), (2,4) are obstacles.
/// The other two obstacles, (4,4) and (4,1), close the corner. Priorities 1, 1, 1.5 as in the
/// notes.
///   y=4  ? ? # # #
///   y=3  ? . . R #
///   y=2  ? ? . . #
///   y=1  ? ? ? ? #
///   y=0  ? ? ? ? ?
inline const std::vector<std::string>& labyrinth_rows() {
  static const std::vector<std::string> rows{
      "??###", "?..R#", "??..#", "????#", "?????",
  };
  return rows;
}

}  // namespace tessera::test
