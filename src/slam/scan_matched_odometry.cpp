// Odometry from local SLAM alone (scan_matched_odometry.hpp).
#include "tessera/slam/scan_matched_odometry.hpp"

#include <utility>

#include "tessera/core/assert.hpp"

namespace tessera::slam {

ScanMatchedOdometry::ScanMatchedOdometry(LaserSlamOptions options, int scans_per_restart)
    : options_(std::move(options)), scans_per_restart_(scans_per_restart) {
  options_.use_odometry = false;
  options_.loop_closure = false;
  options_.progress = {};
  // Unknown cells as Cartographer reads them, not at kSlamUnknownProbability: with no odometry
  // nothing but their pull towards the known cells holds a scan whose view is mostly new, as the
  // first scans after a restart are (a submap of one scan). At 0.3 the office run restarted every
  // 50 scans ended 1.28 m off (decision 0039).
  options_.refiner.unknown_probability = kMinProbability;
  TESSERA_ASSERT(!validate(options_) && scans_per_restart_ >= 2);
}

ScanMatchedOdometry::~ScanMatchedOdometry() = default;

Result<Pose2> ScanMatchedOdometry::add(const StampedScan& scan) {
  if (!slam_ || scans_in_slam_ >= scans_per_restart_) {
    // A new local SLAM whose first scan is the last one taken, at the pose it was given. With no
    // loop closure its graph is never optimised, so its poses are local SLAM's own.
    slam_ = std::make_unique<LaserSlam>(options_);
    scans_in_slam_ = 0;
    T_odom_slam_ = last_T_odom_robot_;
    if (last_) {
      if (Status s = slam_->add_scan(*last_); !s) return s.error();
      ++scans_in_slam_;
    }
  }
  if (Status s = slam_->add_scan(scan); !s) return s.error();
  ++scans_in_slam_;
  last_ = scan;
  last_T_odom_robot_ = T_odom_slam_ * slam_->latest_pose();
  return last_T_odom_robot_;
}

Result<LaserLog> with_scan_matched_odometry(LaserLog log, LaserSlamOptions options) {
  options.use_odometry = false;
  options.loop_closure = false;
  if (auto problem = validate(options)) return usage_error("laser SLAM options: " + *problem);
  if (log.scans.empty()) return input_error("laser SLAM: the log has no scans");
  ScanMatchedOdometry odometry(std::move(options));
  log.odometry.clear();
  log.odometry.reserve(log.scans.size());
  for (StampedScan& scan : log.scans) {
    Result<Pose2> pose = odometry.add(scan);
    if (!pose) return pose.error();
    scan.odometry = *pose;
    log.odometry.push_back({scan.t_s, *pose});
  }
  log.has_odometry = true;
  return log;
}

}  // namespace tessera::slam
