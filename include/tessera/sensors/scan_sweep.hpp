#pragma once
// How the robot moved while a spinning lidar swept one scan: the velocity that lets each beam be
// placed where the robot was when it was taken (slam/scan_points.hpp). The bag reader, the live
// scan input and the simulated laser runs all take it from the odometry around the scan.
#include <algorithm>
#include <cstddef>

#include "tessera/core/pose2.hpp"
#include "tessera/core/twist2.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera {

/// The robot's velocity while `scan` was swept (StampedScan::robot_velocity): its motion from the
/// scan's first beam in time to its last, as a constant velocity in the robot frame.
/// `T_odom_robot_at(dt_s)` is the odometry pose dt_s after the scan's stamp. Zero when the scan's
/// beams have no times.
template <typename PoseAt>
[[nodiscard]] Twist2 sweep_velocity(const RangeScan& scan, PoseAt&& T_odom_robot_at) {
  const std::size_t n = scan.ranges_m.size();
  if (n < 2 || scan.time_increment_s == 0.0) return {};
  const double a_s = beam_time_s(scan, 0), b_s = beam_time_s(scan, n - 1);
  const double first_s = std::min(a_s, b_s), last_s = std::max(a_s, b_s);
  return velocity_between(between(T_odom_robot_at(first_s), T_odom_robot_at(last_s)),
                          last_s - first_s);
}

}  // namespace tessera
