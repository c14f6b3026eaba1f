#pragma once
// A laser scan as points in the robot frame, the input of every matcher and of submap insertion
// (Hess et al. 2016, "Real-time loop closure in 2D LIDAR SLAM", Sec. IV: range data are points
// plus the sensor origin; readings beyond the useful range become free-space rays).
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/twist2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera::slam {

/// Which readings of a scan become points.
struct ScanPointsOptions {
  /// Readings shorter than this (or than the scan's own min_range_m) are dropped: they hit the
  /// robot or are sensor noise.
  double min_range_m = 0.1;
  /// Returns at or beyond this range are not used as hits; like no-return readings they only clear
  /// free space (missing_ray_length_m). Long returns carry more angular error per metre.
  double max_range_m = 30.0;
  /// A no-return reading (>= the scan's max_range_m) or a return beyond max_range_m clears free
  /// space up to this length; 0 drops such readings (Cartographer's missing_data_ray_length).
  double missing_ray_length_m = 5.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ScanPointsOptions& o);

/// One scan in the robot frame: the sensor origin, the returns (hits), and the endpoints of
/// free-space rays that saw nothing (misses). Metres.
struct ScanPoints {
  Vec2 origin_m;
  std::vector<Vec2> returns_m;
  std::vector<Vec2> misses_m;
  /// The beam index of each return (same length as returns_m), so that neighbouring beams can be
  /// told apart from returns with a dropped beam between them.
  std::vector<int> return_beams;
};

/// Converts `scan`, taken by a sensor at T_robot_laser, into robot-frame points. NaN readings and
/// readings below the range limits are dropped. Each beam is placed where the robot was when it was
/// taken (beam_time_s), moving at `robot_velocity` from the stamp on, and so in the robot frame at
/// the stamp: a lidar spinning at 5 Hz on a robot turning at 1 rad/s sees its last beam from 0.2
/// rad further round than its first, and a wall 3 m away comes out 0.6 m from where the first beams
/// put it (Cartographer unwarps its scans so, Hess et al. 2016, Sec. IV; LOAM with constant
/// velocity). The sensor origin stays the one at the stamp. Cost: O(beams).
[[nodiscard]] ScanPoints scan_to_points(const RangeScan& scan, const Pose2& T_robot_laser,
                                        const ScanPointsOptions& options,
                                        const Twist2& robot_velocity = {});

/// The same for a logged scan: its sensor pose and its robot's velocity.
[[nodiscard]] inline ScanPoints scan_to_points(const StampedScan& scan,
                                               const ScanPointsOptions& options) {
  return scan_to_points(scan.scan, scan.laser_in_robot, options, scan.robot_velocity);
}

/// Keeps the first point (in input order) of every square voxel of side voxel_size_m, so the
/// output order follows the input and does not depend on hashing. voxel_size_m <= 0 keeps all
/// points. Cost: O(n) expected.
[[nodiscard]] std::vector<Vec2> voxel_filter(const std::vector<Vec2>& points_m,
                                             double voxel_size_m);

/// Cartographer's adaptive voxel filter (Hess et al. 2016; adaptive_voxel_filter.cc): points beyond
/// max_range_m are dropped, then the largest voxel size up to max_length_m is chosen (by bisection)
/// that still leaves at least min_num_points points. A scan that already has fewer points than
/// min_num_points is returned unfiltered.
struct AdaptiveVoxelFilterOptions {
  double max_length_m = 0.5;
  int min_num_points = 200;
  double max_range_m = 50.0;
};

[[nodiscard]] std::vector<Vec2> adaptive_voxel_filter(const std::vector<Vec2>& points_m,
                                                      const AdaptiveVoxelFilterOptions& options);

/// Every point transformed by T_a_b (points in frame b -> frame a).
[[nodiscard]] std::vector<Vec2> transform_points(const Pose2& T_a_b,
                                                 const std::vector<Vec2>& points_b);

}  // namespace tessera::slam
