#pragma once
// Odometry made from the scans themselves, for a log that records none (LaserLog::has_odometry
// false: a bag of scans alone, or odometry set aside with --no-odometry): every scan's pose from
// local SLAM alone (scan-to-submap matching with LaserSlamOptions::use_odometry off, no loop
// closure), as laser_scan_matcher or Hector SLAM's scan matcher would give a robot that has no
// wheel odometry. What needs odometry between scans (the localizer's tracking and relocalization
// view, a resumed session's new trajectory) can then run on such a log. Decision 0034.
#include <memory>
#include <optional>

#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::slam {

/// Odometry from the scans, one scan at a time, for a live input (the localization node of a
/// robot without odometry): local SLAM alone over the scans so far. So that a run of hours keeps
/// a bounded memory, the local SLAM starts again every `scans_per_restart` scans from the last
/// scan it took (that scan begins the new one, at the pose the old one gave it), so the poses go
/// on without a jump; only the first scans after a restart match against a submap of few scans,
/// as at the start of any run.
class ScanMatchedOdometry {
 public:
  /// `options` are the local SLAM's (use_odometry and loop_closure are set off here).
  /// Preconditions: validate(options) is empty; scans_per_restart >= 2.
  explicit ScanMatchedOdometry(LaserSlamOptions options = {}, int scans_per_restart = 3000);
  ~ScanMatchedOdometry();
  ScanMatchedOdometry(const ScanMatchedOdometry&) = delete;
  ScanMatchedOdometry& operator=(const ScanMatchedOdometry&) = delete;

  /// T_odom_robot of `scan` (its own odometry field is not read); the first scan is the origin.
  /// Errors as LaserSlam::add_scan's.
  [[nodiscard]] Result<Pose2> add(const StampedScan& scan);

 private:
  LaserSlamOptions options_;
  int scans_per_restart_;
  std::unique_ptr<LaserSlam> slam_;
  int scans_in_slam_ = 0;
  Pose2 T_odom_slam_;  // where the current local SLAM's origin lies in the odometry frame
  std::optional<StampedScan> last_;
  Pose2 last_T_odom_robot_;
};

/// The log with every scan's odometry (and LaserLog::odometry) replaced by its local SLAM pose,
/// in the frame of the first scan (ScanMatchedOdometry over the whole log, so a live node given the
/// same scans gets the same odometry), and has_odometry true; a spinning lidar's scans (beams with
/// times) get their robot_velocity over the sweep from that odometry, as a bag's odometry gives
/// it (a live node, which cannot wait for the next scan's pose, places them from the stamp). The
/// log's own odometry fields are not read. `options` are the local SLAM's (use_odometry and
/// loop_closure are set off here). Usage error for invalid options, input error for a log without
/// scans, and LaserSlam::add_scan's errors.
[[nodiscard]] Result<LaserLog> with_scan_matched_odometry(LaserLog log,
                                                          LaserSlamOptions options = {});

/// For SLAM from scans alone: a log without odometry (has_odometry false) whose scans are a
/// spinning lidar's (beams with times) gets every scan's robot_velocity over its sweep from the
/// odometry with_scan_matched_odometry makes (its scans placed from their stamps), and keeps
/// has_odometry false and its odometry fields as they were: SLAM then places each beam where it
/// was taken (scan_points.hpp; decision 0048). Any other log is returned unchanged. Errors as
/// with_scan_matched_odometry's.
[[nodiscard]] Result<LaserLog> with_scan_matched_sweep_velocities(LaserLog log,
                                                                  const LaserSlamOptions& options);

}  // namespace tessera::slam
