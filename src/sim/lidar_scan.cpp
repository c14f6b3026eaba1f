// The simulated lidar (sim/lidar_scan.hpp).
#include "tessera/sim/lidar_scan.hpp"

#include <algorithm>

namespace tessera {

RangeScan simulate_lidar_scan(const World& world, const Pose2& T_world_laser,
                              const LidarOptions& lidar, Rng& rng) {
  RangeScan scan = empty_scan(lidar);
  const Vec2 from_m = T_world_laser.translation();
  const double bound_m = 3.0 * lidar.range_noise_stddev_m;
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double angle = T_world_laser.theta + scan.angle_min_rad +
                         static_cast<double>(i) * scan.angle_increment_rad;
    const double truth_m = world.cast_ray(from_m, angle, lidar.max_range_m);
    const double noise_m = std::clamp(rng.gaussian(lidar.range_noise_stddev_m), -bound_m, bound_m);
    scan.ranges_m[i] = truth_m >= lidar.max_range_m
                           ? lidar.max_range_m
                           : std::clamp(truth_m + noise_m, 0.0, lidar.max_range_m);
  }
  return scan;
}

}  // namespace tessera
