#pragma once
// A pose between two poses: odometry between two readings (the log and bag readers, the live SLAM
// node) and a trajectory between two stamps (the relation metric).
#include <algorithm>
#include <cstdint>
#include <span>

#include "tessera/core/pose2.hpp"
#include "tessera/core/time_ns.hpp"

namespace tessera {

/// The pose a fraction f in [0, 1] of the way from a to b: linear in x and y, along the shorter
/// arc in theta.
[[nodiscard]] inline Pose2 interpolate(const Pose2& a, const Pose2& b, double f) {
  const double dtheta = normalize_angle(b.theta - a.theta);
  return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), normalize_angle(a.theta + f * dtheta)};
}

/// A pose stamped in nanoseconds (an odometry message).
struct PoseAtNs {
  std::int64_t t_ns = 0;
  Pose2 pose;
};

/// The pose at t_ns in `sorted` (by t_ns; not empty): interpolated between the poses just before
/// and after it, the nearer one outside their span (CARMEN's RAWLASER1 rule, carmen_log.hpp).
[[nodiscard]] inline Pose2 pose_at(std::span<const PoseAtNs> sorted, std::int64_t t_ns) {
  const auto after = std::lower_bound(sorted.begin(), sorted.end(), t_ns,
                                      [](const PoseAtNs& p, std::int64_t v) { return p.t_ns < v; });
  if (after == sorted.begin()) return after->pose;
  if (after == sorted.end()) return sorted.back().pose;
  const PoseAtNs& a = *(after - 1);
  const PoseAtNs& b = *after;
  if (b.t_ns == a.t_ns) return b.pose;
  return interpolate(a.pose, b.pose, ns_difference(t_ns, a.t_ns) / ns_difference(b.t_ns, a.t_ns));
}

}  // namespace tessera
