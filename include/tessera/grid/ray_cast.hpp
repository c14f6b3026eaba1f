#pragma once
// Exact traversal of the grid cells a line segment passes through (Amanatides & Woo 1987, "A Fast
// Voxel Traversal Algorithm for Ray Tracing"). This is the hot loop of the lidar simulation
// (World::cast_ray) and of the scan update (insert_scan), so it is a header template: the visitor
// is inlined and the loop does one multiply and one compare per cell, no division and no
// std::floor.

#include <cmath>
#include <type_traits>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"

namespace tessera {

/// Calls visit(Cell c, double t_enter_m, double t_exit_m) for every cell the segment from_m -> to_m
/// passes through, in order from from_m. t is the distance along the segment from from_m in metres,
/// so t_enter_m of the first cell is 0 and t_exit_m of the last is |to_m - from_m|.
///
/// Which cells (docs/conventions.md, world->cell uses floor):
///  - The first cell is geometry.cell_at_unchecked(from_m), the last cell_at_unchecked(to_m); every
///    cell containing a point of the segment (by the floor rule) is visited exactly once.
///  - Consecutive cells are 4-neighbours: the sequence never jumps diagonally. When the segment
///    passes exactly through a cell corner, the x step is taken first, so the x-neighbour is
///    visited with t_enter_m == t_exit_m. Likewise a segment that starts or ends exactly on a cell
///    boundary may visit one cell with zero length (the floor rule's cell). Ties are broken the
///    same way on every platform.
///  - Cells outside the grid are NOT clipped: they are visited like any other (the visitor decides;
///    World::cast_ray treats them as solid, insert_scan skips them). Check geometry.contains(c).
///
/// The visitor may return void, or bool: returning false stops the traversal early.
/// Preconditions: finite coordinates, and every cell index on the way fits in +-2^30.
/// Cost: O(number of cells visited) = O(|dx| + |dy|) in cells.
template <typename Visit>
void traverse_ray(const GridGeometry& geometry, Vec2 from_m, Vec2 to_m, Visit&& visit) {
  using VisitResult = std::invoke_result_t<Visit&, Cell, double, double>;
  constexpr bool kCanStop = std::is_same_v<VisitResult, bool>;
  static_assert(kCanStop || std::is_void_v<VisitResult>,
                "traverse_ray: the visitor must return void or bool");
  const auto call = [&visit](Cell c, double t0, double t1) -> bool {
    if constexpr (kCanStop) {
      return visit(c, t0, t1);
    } else {
      visit(c, t0, t1);
      return true;
    }
  };

  // Work in cell units: p = (point - origin) / resolution. Segment parameter s in [0, 1].
  const double inv_res = 1.0 / geometry.resolution_m();
  const Vec2 origin = geometry.origin();
  const double px = (from_m.x - origin.x) * inv_res;
  const double py = (from_m.y - origin.y) * inv_res;
  const double qx = (to_m.x - origin.x) * inv_res;
  const double qy = (to_m.y - origin.y) * inv_res;
  TESSERA_ASSERT(std::isfinite(px) && std::isfinite(py) && std::isfinite(qx) && std::isfinite(qy));
  constexpr double kMaxIndex = 1073741824.0;  // 2^30: cell indices and their differences fit in int
  const double fx0 = std::floor(px), fy0 = std::floor(py);
  const double fx1 = std::floor(qx), fy1 = std::floor(qy);
  TESSERA_ASSERT(std::fabs(fx0) < kMaxIndex && std::fabs(fy0) < kMaxIndex &&
                 std::fabs(fx1) < kMaxIndex && std::fabs(fy1) < kMaxIndex);

  const double length_m = (to_m - from_m).norm();
  Cell c{static_cast<int>(fx0), static_cast<int>(fy0)};
  const Cell end{static_cast<int>(fx1), static_cast<int>(fy1)};
  const double dx = qx - px, dy = qy - py;
  const int step_x = end.x > c.x ? 1 : -1;
  const int step_y = end.y > c.y ? 1 : -1;
  // Steps left on each axis. Counting them (rather than comparing s with 1) guarantees that the
  // walk ends exactly in cell_at(to_m) whatever the rounding of the crossing parameters.
  int left_x = end.x > c.x ? end.x - c.x : c.x - end.x;
  int left_y = end.y > c.y ? end.y - c.y : c.y - end.y;

  // s at which the segment crosses the next vertical (x) / horizontal (y) cell boundary. Computed
  // from the boundary's index each time (no accumulated error), so equal crossings stay equal.
  // If an axis has steps left, its delta is non-zero (else floor(p) == floor(q) on that axis).
  const double inv_dx = left_x > 0 ? 1.0 / dx : 0.0;
  const double inv_dy = left_y > 0 ? 1.0 / dy : 0.0;
  double next_bx = step_x > 0 ? fx0 + 1.0 : fx0;  // x of the next boundary in the step direction
  double next_by = step_y > 0 ? fy0 + 1.0 : fy0;
  double s_x = left_x > 0 ? (next_bx - px) * inv_dx : 2.0;
  double s_y = left_y > 0 ? (next_by - py) * inv_dy : 2.0;

  double t_enter = 0.0;
  while (left_x > 0 || left_y > 0) {
    // x first on a tie: the deterministic corner rule documented above.
    const bool take_x = left_x > 0 && (left_y == 0 || s_x <= s_y);
    double s = take_x ? s_x : s_y;
    // Rounding can put a crossing a hair outside [0, 1]; this form also maps NaN (0 * inf) to 0.
    s = s > 0.0 ? (s < 1.0 ? s : 1.0) : 0.0;
    double t_exit = s * length_m;
    if (t_exit < t_enter) t_exit = t_enter;  // keep t monotone under rounding
    if (!call(c, t_enter, t_exit)) return;
    t_enter = t_exit;
    if (take_x) {
      c.x += step_x;
      --left_x;
      next_bx += step_x;
      s_x = left_x > 0 ? (next_bx - px) * inv_dx : 2.0;
    } else {
      c.y += step_y;
      --left_y;
      next_by += step_y;
      s_y = left_y > 0 ? (next_by - py) * inv_dy : 2.0;
    }
  }
  call(c, t_enter, length_m > t_enter ? length_m : t_enter);
}

}  // namespace tessera
