#include "tessera/slam/perception_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/core/assert.hpp"

namespace tessera::slam {

std::size_t TernaryGrid::known_count() const {
  return static_cast<std::size_t>(
      std::count_if(values_.begin(), values_.end(), [](std::int8_t v) { return v != 0; }));
}

std::int8_t ternary_value(const OccupancyGrid& map, Cell c, double occupied_threshold) {
  switch (map.state(c, occupied_threshold)) {
    case CellState::kUnknown:
      return kTernaryUnknown;
    case CellState::kFree:
      return kTernaryFree;
    case CellState::kOccupied:
      return kTernaryOccupied;
  }
  return kTernaryUnknown;
}

GridGeometry robot_window(double cell_m, int behind_cells, int ahead_cells, int side_cells) {
  TESSERA_ASSERT(cell_m > 0.0 && behind_cells >= 0 && ahead_cells >= 0 && side_cells >= 0);
  // The robot (the frame's origin) sits at the centre of cell (behind_cells, side_cells).
  const Vec2 origin{-(behind_cells + 0.5) * cell_m, -(side_cells + 0.5) * cell_m};
  return GridGeometry(origin, cell_m, behind_cells + 1 + ahead_cells, 2 * side_cells + 1);
}

GridGeometry robot_window(double cell_m, double max_range_m) {
  TESSERA_ASSERT(cell_m > 0.0 && max_range_m >= 0.0);
  // A return at max range from the centre of the robot's cell lies at most ceil(range / cell)
  // cells away (the centre is half a cell from every border, so this holds with half a cell
  // to spare).
  const int radius = static_cast<int>(std::ceil(max_range_m / cell_m));
  return robot_window(cell_m, radius, radius, radius);
}

std::optional<std::string> validate(const PerceptionOptions& o) {
  if (!(o.wall_depth_cells > 0.0) || !std::isfinite(o.wall_depth_cells)) {
    return "wall_depth_cells must be > 0, got " + std::to_string(o.wall_depth_cells);
  }
  return std::nullopt;
}

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

/// The index of the beam of `scan` nearest the bearing phi_rad (sensor frame), or -1 when phi_rad
/// is more than half a beam spacing outside a partial field of view.
[[nodiscard]] long nearest_beam(const RangeScan& scan, double phi_rad) {
  const auto n = static_cast<long>(scan.ranges_m.size());
  if (n == 0 || !(scan.angle_increment_rad > 0.0)) return -1;
  // Bearing past the first beam, in [0, 2 pi).
  double rel = std::fmod(phi_rad - scan.angle_min_rad, kTwoPi);
  if (rel < 0.0) rel += kTwoPi;
  const double k = rel / scan.angle_increment_rad;
  const bool full_circle = static_cast<double>(n) * scan.angle_increment_rad >= kTwoPi - 1e-9;
  if (full_circle) return static_cast<long>(std::lround(k)) % n;
  if (k <= static_cast<double>(n - 1) + 0.5) return static_cast<long>(std::lround(k));
  // Just before the first beam (rel wrapped round to nearly 2 pi).
  if ((kTwoPi - rel) / scan.angle_increment_rad <= 0.5) return 0;
  return -1;
}

}  // namespace

TernaryGrid perception_from_scan(const RangeScan& scan, const GridGeometry& window,
                                 const Pose2& T_robot_sensor, const PerceptionOptions& o) {
  TESSERA_ASSERT(!validate(o).has_value());
  const double depth_m = o.wall_depth_cells * window.resolution_m();
  const Pose2 T_sensor_robot = T_robot_sensor.inverse();
  TernaryGrid perception(window);
  for (int y = 0; y < window.height(); ++y) {
    for (int x = 0; x < window.width(); ++x) {
      // "Majority of the area" judged by the cell's centre, in the sensor frame.
      const Vec2 q = T_sensor_robot * window.center_of({x, y});
      const double d = q.norm();
      if (d < 1e-9) {
        perception.set({x, y}, kTernaryFree);  // the sensor stands in it
        continue;
      }
      const long k = nearest_beam(scan, std::atan2(q.y, q.x));
      if (k < 0) continue;
      const double r = scan.ranges_m[static_cast<std::size_t>(k)];
      if (std::isnan(r) || r < scan.min_range_m) continue;  // invalid reading: nothing known
      if (r >= scan.max_range_m) {
        if (d < scan.max_range_m) perception.set({x, y}, kTernaryFree);  // no return: all free
        continue;
      }
      if (d < r) {
        perception.set({x, y}, kTernaryFree);
      } else if (d < r + depth_m) {
        perception.set({x, y}, kTernaryOccupied);
      }
    }
  }
  return perception;
}

TernaryGrid perception_from_cells(const CellReading& reading, double cell_m) {
  TernaryGrid perception(robot_window(cell_m, 1, 1, 1));
  const Cell robot{1, 1};
  perception.set(robot, kTernaryFree);  // the robot stands in it
  for (std::size_t k = 0; k < kNeighbors8.size(); ++k) {
    if (!reading.inside_map[k]) continue;
    perception.set(robot + kNeighbors8[k], reading.occupied[k] ? kTernaryOccupied : kTernaryFree);
  }
  return perception;
}

TernaryGrid expected_map(const OccupancyGrid& map, const GridGeometry& window,
                         const Pose2& T_map_robot, double occupied_threshold) {
  const GridGeometry& map_geometry = map.geometry();
  TernaryGrid expected(window);
  for (int y = 0; y < window.height(); ++y) {
    for (int x = 0; x < window.width(); ++x) {
      const Vec2 p_map = T_map_robot * window.center_of({x, y});
      const std::optional<Cell> c = map_geometry.cell_at(p_map);
      if (c) expected.set({x, y}, ternary_value(map, *c, occupied_threshold));
    }
  }
  return expected;
}

}  // namespace tessera::slam
