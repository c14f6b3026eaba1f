#include "tessera/slam/scan_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_set>

namespace tessera::slam {

std::optional<std::string> validate(const ScanPointsOptions& o) {
  if (!(o.min_range_m >= 0.0)) return "min_range_m must be >= 0";
  if (!(o.max_range_m > o.min_range_m)) return "max_range_m must be > min_range_m";
  if (!(o.missing_ray_length_m >= 0.0)) return "missing_ray_length_m must be >= 0";
  return std::nullopt;
}

ScanPoints scan_to_points(const RangeScan& scan, const Pose2& T_robot_laser,
                          const ScanPointsOptions& options, const Twist2& robot_velocity) {
  // Where the robot was when beam i was taken, seen from the stamp; none when it did not move.
  const bool unwarp = !robot_velocity.is_zero() && has_beam_times(scan);
  const auto place = [&](std::size_t i, Vec2 p_laser) {
    const Vec2 p_robot = T_robot_laser * p_laser;
    return unwarp ? displacement(robot_velocity, beam_time_s(scan, i)) * p_robot : p_robot;
  };
  ScanPoints out;
  out.origin_m = T_robot_laser.translation();
  out.returns_m.reserve(scan.ranges_m.size());
  out.return_beams.reserve(scan.ranges_m.size());
  const double min_range_m = std::max(options.min_range_m, scan.min_range_m);
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (std::isnan(r) || r < min_range_m) continue;
    const double angle = scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
    const Vec2 dir{std::cos(angle), std::sin(angle)};
    const bool no_return = scan.max_range_m > 0.0 && r >= scan.max_range_m;
    if (!no_return && r < options.max_range_m) {
      out.returns_m.push_back(place(i, dir * r));
      out.return_beams.push_back(static_cast<int>(i));
    } else if (options.missing_ray_length_m > 0.0) {
      out.misses_m.push_back(place(i, dir * options.missing_ray_length_m));
    }
  }
  return out;
}

std::vector<Vec2> voxel_filter(const std::vector<Vec2>& points_m, double voxel_size_m) {
  if (!(voxel_size_m > 0.0)) return points_m;
  const double inv = 1.0 / voxel_size_m;
  std::unordered_set<std::uint64_t> seen;
  seen.reserve(points_m.size() * 2);
  std::vector<Vec2> out;
  out.reserve(points_m.size());
  for (const Vec2& p : points_m) {
    const auto kx = static_cast<std::int32_t>(std::floor(p.x * inv));
    const auto ky = static_cast<std::int32_t>(std::floor(p.y * inv));
    const std::uint64_t key = (static_cast<std::uint64_t>(static_cast<std::uint32_t>(kx)) << 32) |
                              static_cast<std::uint32_t>(ky);
    if (seen.insert(key).second) out.push_back(p);
  }
  return out;
}

std::vector<Vec2> adaptive_voxel_filter(const std::vector<Vec2>& points_m,
                                        const AdaptiveVoxelFilterOptions& options) {
  std::vector<Vec2> in_range;
  in_range.reserve(points_m.size());
  for (const Vec2& p : points_m) {
    if (p.norm() <= options.max_range_m) in_range.push_back(p);
  }
  const auto min_points = static_cast<std::size_t>(std::max(options.min_num_points, 0));
  if (in_range.size() <= min_points) return in_range;
  std::vector<Vec2> result = voxel_filter(in_range, options.max_length_m);
  if (result.size() >= min_points) return result;  // the coarsest voxels already keep enough
  // Bisection on the voxel size: `low` keeps enough points, `high` keeps too few.
  double high = options.max_length_m;
  double low = high;
  do {
    low /= 2.0;
    result = voxel_filter(in_range, low);
  } while (result.size() < min_points && low > 1e-6);
  while ((high - low) / low > 0.1) {
    const double mid = 0.5 * (low + high);
    std::vector<Vec2> candidate = voxel_filter(in_range, mid);
    if (candidate.size() >= min_points) {
      low = mid;
      result = std::move(candidate);
    } else {
      high = mid;
    }
  }
  return result;
}

std::vector<Vec2> transform_points(const Pose2& T_a_b, const std::vector<Vec2>& points_b) {
  std::vector<Vec2> out;
  out.reserve(points_b.size());
  const double c = std::cos(T_a_b.theta), s = std::sin(T_a_b.theta);
  for (const Vec2& p : points_b) {
    out.push_back({T_a_b.x + c * p.x - s * p.y, T_a_b.y + s * p.x + c * p.y});
  }
  return out;
}

}  // namespace tessera::slam
