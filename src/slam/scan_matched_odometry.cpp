// Odometry from local SLAM alone (scan_matched_odometry.hpp).
#include "tessera/slam/scan_matched_odometry.hpp"

#include <utility>

namespace tessera::slam {

Result<LaserLog> with_scan_matched_odometry(LaserLog log, LaserSlamOptions options) {
  options.use_odometry = false;
  options.loop_closure = false;
  options.progress = {};
  Result<LaserSlamResult> local = run_laser_slam(log, options);
  if (!local) return local.error();
  log.odometry.clear();
  log.odometry.reserve(log.scans.size());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const StampedPose2& p = local->local_trajectory[i];
    log.scans[i].odometry = p.pose;
    log.odometry.push_back({p.t_s, p.pose});
  }
  log.has_odometry = true;
  return log;
}

}  // namespace tessera::slam
