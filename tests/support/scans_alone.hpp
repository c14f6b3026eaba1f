#pragma once
// A log as a robot without odometry would send it over ROS 2 topics (decision 0034): no odometry,
// and every scan as it comes off the topic (ranges and angles in float32, stamps in nanoseconds),
// so that an offline run and a live node given the log see the same numbers. Without odometry
// each prediction builds on the last match, so a rounding difference would carry on from scan to
// scan (millimetres). Header-only: a test that includes it links tessera::io and tessera::record.
#include <cstddef>
#include <cstdint>

#include "tessera/io/robot_bag.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera::support {

/// The first `max_scans` scans of `log`, without odometry, as received from topics.
inline LaserLog scans_alone_as_received(LaserLog log, std::size_t max_scans) {
  log.has_odometry = false;
  log.odometry.clear();
  if (log.scans.size() > max_scans) log.scans.resize(max_scans);
  for (StampedScan& s : log.scans) {
    s.odometry = Pose2{};
    s.robot_velocity = {};
    const std::int64_t t_ns = to_ns(s.t_s);
    int no_return = 0;
    s.scan = *range_scan_of(laser_scan_message(s.scan, t_ns, "laser"), no_return);
    s.t_s = 1e-9 * static_cast<double>(t_ns);
  }
  return log;
}

}  // namespace tessera::support
