// Odometry from local SLAM alone (scan_matched_odometry.hpp).
#include "tessera/slam/scan_matched_odometry.hpp"

#include <algorithm>
#include <utility>

#include "tessera/core/assert.hpp"
#include "tessera/core/pose_interpolation.hpp"
#include "tessera/sensors/scan_sweep.hpp"

namespace tessera::slam {
namespace {

/// Scans further apart than this say nothing of the velocity during either's sweep.
constexpr double kMaxStepForVelocity_s = 1.0;

/// The pose at t_s on the path through `poses` (one per scan, in file order), from the step
/// between scan i and the next (or, for the last scan, the one before it), extended at constant
/// velocity; scan i's own pose when neither step is usable.
Pose2 pose_near_scan(const std::vector<OdometryReading>& poses, std::size_t i, double t_s) {
  const auto usable = [&](std::size_t a) {
    const double dt_s = poses[a + 1].t_s - poses[a].t_s;
    return dt_s > 0.0 && dt_s <= kMaxStepForVelocity_s;
  };
  std::size_t a = 0;
  if (i + 1 < poses.size() && usable(i)) {
    a = i;
  } else if (i > 0 && usable(i - 1)) {
    a = i - 1;
  } else {
    return poses[i].pose;
  }
  const OdometryReading& from = poses[a];
  const OdometryReading& to = poses[a + 1];
  return interpolate(from.pose, to.pose, (t_s - from.t_s) / (to.t_s - from.t_s));
}

}  // namespace

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
  // A spinning lidar's scans: the robot's velocity over each sweep from that odometry, as a bag's
  // odometry gives it (io/robot_bag.hpp), so that each beam is placed where it was taken.
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    StampedScan& s = log.scans[i];
    s.robot_velocity = sweep_velocity(
        s.scan, [&](double dt_s) { return pose_near_scan(log.odometry, i, s.t_s + dt_s); });
  }
  return log;
}

Result<LaserLog> with_scan_matched_sweep_velocities(LaserLog log, const LaserSlamOptions& options) {
  if (log.has_odometry ||
      std::none_of(log.scans.begin(), log.scans.end(),
                   [](const StampedScan& s) { return has_beam_times(s.scan); })) {
    return log;
  }
  // The log itself goes through with_scan_matched_odometry (no copy of its scans); only its own
  // odometry fields are kept aside and put back.
  std::vector<Pose2> own_poses;
  own_poses.reserve(log.scans.size());
  for (const StampedScan& s : log.scans) own_poses.push_back(s.odometry);
  std::vector<OdometryReading> own_stream = std::move(log.odometry);
  Result<LaserLog> matched = with_scan_matched_odometry(std::move(log), options);
  if (!matched) return matched.error();
  LaserLog out = std::move(matched).value();
  for (std::size_t i = 0; i < out.scans.size(); ++i) out.scans[i].odometry = own_poses[i];
  out.odometry = std::move(own_stream);
  out.has_odometry = false;
  return out;
}

}  // namespace tessera::slam
