// The simulated lidar (sim/lidar_scan.hpp).
#include "tessera/sim/lidar_scan.hpp"

#include <algorithm>

#include "tessera/core/assert.hpp"

namespace tessera {

namespace {

/// Casts beam i from laser_pose(i).
template <typename LaserPose>
RangeScan cast_scan(const World& world, LaserPose&& laser_pose, const LidarOptions& lidar,
                    Rng& rng) {
  RangeScan scan = empty_scan(lidar);
  const double bound_m = 3.0 * lidar.range_noise_stddev_m;
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const Pose2& T_world_laser = laser_pose(i);
    const double angle = T_world_laser.theta + scan.angle_min_rad +
                         static_cast<double>(i) * scan.angle_increment_rad;
    const double truth_m = world.cast_ray(T_world_laser.translation(), angle, lidar.max_range_m);
    const double noise_m = std::clamp(rng.gaussian(lidar.range_noise_stddev_m), -bound_m, bound_m);
    scan.ranges_m[i] = truth_m >= lidar.max_range_m
                           ? lidar.max_range_m
                           : std::clamp(truth_m + noise_m, 0.0, lidar.max_range_m);
  }
  return scan;
}

}  // namespace

RangeScan simulate_lidar_scan(const World& world, const Pose2& T_world_laser,
                              const LidarOptions& lidar, Rng& rng) {
  return cast_scan(
      world, [&](std::size_t) -> const Pose2& { return T_world_laser; }, lidar, rng);
}

RangeScan simulate_lidar_scan(const World& world, std::span<const Pose2> T_world_laser_per_beam,
                              const LidarOptions& lidar, Rng& rng) {
  TESSERA_ASSERT(T_world_laser_per_beam.size() == static_cast<std::size_t>(lidar.beams));
  return cast_scan(
      world, [&](std::size_t i) -> const Pose2& { return T_world_laser_per_beam[i]; }, lidar, rng);
}

}  // namespace tessera
