#pragma once
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/twist2.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera {

/// One laser scan as a log records it: the stamp, the odometry pose at scan time and the scan in
/// the sensor frame. `laser_in_robot` is where the sensor sits on the robot (identity when the log
/// does not say).
struct StampedScan {
  double t_s = 0.0;
  Pose2 odometry;
  Pose2 laser_in_robot;
  RangeScan scan;
  /// The robot's velocity while the laser swept the scan (robot frame, from the odometry around
  /// it), to place each beam where the robot was when the beam was taken (scan_points.hpp). Zero
  /// when the scan's beams have no times, the robot stood, or nothing says how it moved.
  Twist2 robot_velocity;
};

/// An odometry pose with its stamp (CARMEN ODOM).
struct OdometryReading {
  double t_s = 0.0;
  Pose2 pose;
};

/// A 2D laser log in file order (the order the robot recorded it; stamps need not increase).
struct LaserLog {
  std::vector<StampedScan> scans;
  std::vector<OdometryReading> odometry;
  /// How many scans have a stamp smaller than the scan before them.
  int backward_stamps = 0;
  /// false: the log records no odometry (a bag of scans alone); every scan's `odometry` is the
  /// identity and `odometry` is empty. SLAM then matches the scans alone
  /// (slam::LaserSlamOptions::use_odometry).
  bool has_odometry = true;
};

/// The log as if it recorded no odometry (`--no-odometry`: odometry that cannot be trusted): none,
/// every scan's odometry the identity, and no velocity taken from it for a scan's sweep.
inline void without_odometry(LaserLog& log) {
  log.has_odometry = false;
  log.odometry.clear();
  for (StampedScan& s : log.scans) {
    s.odometry = Pose2{};
    s.robot_velocity = {};
  }
}

}  // namespace tessera
