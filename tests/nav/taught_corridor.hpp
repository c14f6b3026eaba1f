#pragma once
// The teach run of the thesis' two-stage experiment (Table 5.1) on a straight corridor: driven from
// the start to the goal and back "in reverse order" on a slightly different line, as a human driver
// does. Out along y = +offset, back along y = -offset: the two runs share the cells centred on
// y = 0 and each adds its own cells in between, so between two shared cells there are two cells of
// EQUAL wavefront value (one per run) whose common border lies on the straight line y = 0: the
// tie the thesis' navigation ping-pongs on (section 6.1).
#include <algorithm>
#include <cmath>

#include "tessera/fusion/hex_cell_map.hpp"

namespace tessera::nav_test {

inline void teach_line(fusion::HexCellMap& map, Vec2 a, Vec2 b, double step_m = 0.01) {
  const Vec2 d = b - a;
  const double theta = std::atan2(d.y, d.x);
  const int n = std::max(1, static_cast<int>(std::ceil(d.norm() / step_m)));
  for (int i = 0; i <= n; ++i) {
    const Vec2 p = a + d * (static_cast<double>(i) / n);
    (void)map.update({p.x, p.y, theta});
  }
}

/// A corridor 12 lattice columns long (3.12 m at d = 0.3 m), so that its far end is a cell centred
/// on y = 0 like the start.
inline double corridor_length_m(double cell_radius_m = 0.3) {
  return 12.0 * kHexColumnStep * cell_radius_m;
}

/// Cells along x in [0, length_m], taught out at y = +offset_m and back at y = -offset_m.
inline fusion::HexCellMap taught_corridor(double length_m, double offset_m = 0.03) {
  fusion::HexCellMap map;
  (void)map.update({0.0, 0.0, 0.0});  // the map starts here: cell 0 centred on y = 0
  teach_line(map, {0.0, offset_m}, {length_m, offset_m});
  teach_line(map, {length_m, offset_m}, {length_m, -offset_m});
  teach_line(map, {length_m, -offset_m}, {0.0, -offset_m});
  return map;
}

}  // namespace tessera::nav_test
