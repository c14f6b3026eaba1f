#pragma once
// Odometry made from the scans themselves, for a log that records none (LaserLog::has_odometry
// false: a bag of scans alone, or odometry set aside with --no-odometry): every scan's pose from
// local SLAM alone (scan-to-submap matching with LaserSlamOptions::use_odometry off, no loop
// closure), as laser_scan_matcher or Hector SLAM's scan matcher would give a robot that has no
// wheel odometry. What needs odometry between scans (the localizer's tracking and relocalization
// view, a resumed session's new trajectory) can then run on such a log. Decision 0034.
#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::slam {

/// The log with every scan's odometry (and LaserLog::odometry) replaced by its local SLAM pose,
/// in the frame of the first scan, and has_odometry true. The log's own odometry fields are not
/// read. `options` are the local SLAM's (use_odometry and loop_closure are set off here).
/// Errors as run_laser_slam's.
[[nodiscard]] Result<LaserLog> with_scan_matched_odometry(LaserLog log,
                                                          LaserSlamOptions options = {});

}  // namespace tessera::slam
