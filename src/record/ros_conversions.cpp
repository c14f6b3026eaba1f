#include "tessera/record/ros_conversions.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <span>

namespace tessera {

std::int64_t to_ns(double t_s) { return std::llround(t_s * 1e9); }

OccupancyGridMessage occupancy_grid_message(const OccupancyGrid& map, std::int64_t stamp_ns,
                                            const std::string& frame) {
  const GridGeometry& g = map.geometry();
  return occupancy_grid_message(map, {{0, 0}, {g.width() - 1, g.height() - 1}}, stamp_ns, frame);
}

OccupancyGridMessage occupancy_grid_message(const OccupancyGrid& map, const CellBox& box,
                                            std::int64_t stamp_ns, const std::string& frame) {
  const GridGeometry& g = map.geometry();
  const double r = g.resolution_m();
  const int width = std::max(0, box.max.x - box.min.x + 1);
  const int height = std::max(0, box.max.y - box.min.y + 1);
  OccupancyGridMessage m;
  m.header = {stamp_ns, frame};
  m.map_load_time_ns = stamp_ns;
  m.resolution_m = static_cast<float>(r);
  m.width = static_cast<std::uint32_t>(width);
  m.height = static_cast<std::uint32_t>(height);
  m.origin = planar_transform(g.origin().x + box.min.x * r, g.origin().y + box.min.y * r, 0.0);
  m.data.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height));
  // GridGeometry's index is ROS's: row-major from the origin cell, x along a row.
  const std::span<const float> log_odds = map.log_odds_values();
  const std::span<const std::uint8_t> known = map.known_flags();
  std::size_t out = 0;
  for (int y = box.min.y; width > 0 && y <= box.max.y; ++y) {
    std::size_t i = g.index_of({box.min.x, y});
    for (int x = 0; x < width; ++x, ++i, ++out) {
      // Percent rounded half up (p >= 0), as std::lround would, without its libm call per cell.
      m.data[out] = known[i] ? static_cast<std::int8_t>(100.0 * probability(log_odds[i]) + 0.5)
                             : std::int8_t{-1};
    }
  }
  return m;
}

PathMessage path_message(std::span<const Pose2> poses, std::span<const std::int64_t> stamps_ns,
                         std::int64_t stamp_ns, const std::string& frame) {
  PathMessage m;
  m.header = {stamp_ns, frame};
  m.poses.reserve(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const Pose2& p = poses[i];
    m.poses.push_back({{stamps_ns[i], frame}, planar_transform(p.x, p.y, p.theta)});
  }
  return m;
}

PathMessage path_message(std::span<const StampedPose2> trajectory, std::int64_t stamp_ns,
                         const std::string& frame, std::int64_t offset_ns) {
  PathMessage m;
  m.header = {stamp_ns, frame};
  m.poses.reserve(trajectory.size());
  for (const StampedPose2& p : trajectory) {
    m.poses.push_back(
        {{to_ns(p.t_s) + offset_ns, frame}, planar_transform(p.pose.x, p.pose.y, p.pose.theta)});
  }
  return m;
}

LaserScanMessage laser_scan_message(const RangeScan& taken, std::int64_t stamp_ns,
                                    const std::string& frame) {
  // A clockwise sweep (its last beam taken at the stamp) goes out as the driver sent it: beams
  // clockwise, the first at the stamp, as LaserScan's time_increment counts them.
  const std::size_t n = taken.ranges_m.size();
  const bool clockwise = taken.time_increment_s < 0.0 && n > 0 && beam_time_s(taken, n - 1) == 0.0;
  std::optional<RangeScan> flipped;  // only then: a copy of every scan is not needed
  if (clockwise) flipped = reversed(taken);
  const RangeScan& scan = flipped ? *flipped : taken;
  LaserScanMessage m;
  m.header = {stamp_ns, frame};
  m.range_min_m = static_cast<float>(scan.min_range_m);
  m.range_max_m = static_cast<float>(scan.max_range_m);
  m.ranges_m.reserve(n);
  m.angle_min_rad = static_cast<float>(scan.angle_min_rad);
  m.angle_increment_rad = static_cast<float>(scan.angle_increment_rad);
  m.angle_max_rad = static_cast<float>(last_angle_rad(scan));
  m.time_increment_s = static_cast<float>(scan.time_increment_s);
  for (const double r : scan.ranges_m) m.ranges_m.push_back(static_cast<float>(r));
  return m;
}

TransformStampedMessage planar_transform_stamped(const Pose2& T_parent_child, std::int64_t stamp_ns,
                                                 const std::string& parent,
                                                 const std::string& child) {
  return {{stamp_ns, parent},
          child,
          planar_transform(T_parent_child.x, T_parent_child.y, T_parent_child.theta)};
}

MarkerMessage cell_marker(std::span<const Cell> cells, const GridGeometry& geometry,
                          std::int64_t stamp_ns, const std::string& frame, const std::string& ns,
                          RosColor color, double height_m, double z_m) {
  MarkerMessage m;
  m.header = {stamp_ns, frame};
  m.ns = ns;
  m.type = MarkerMessage::kCubeList;
  m.scale = {geometry.resolution_m(), geometry.resolution_m(), height_m};
  m.color = color;
  m.points.reserve(cells.size());
  for (const Cell c : cells) {
    const Vec2 p = geometry.center_of(c);
    m.points.push_back({p.x, p.y, z_m});
  }
  return m;
}

}  // namespace tessera
