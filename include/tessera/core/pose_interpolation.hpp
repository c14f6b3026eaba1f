#pragma once
// A pose between two poses: odometry between two readings (the log and bag readers, the live SLAM
// node) and a trajectory between two stamps (the relation metric).
#include "tessera/core/pose2.hpp"

namespace tessera {

/// The pose a fraction f in [0, 1] of the way from a to b: linear in x and y, along the shorter
/// arc in theta.
[[nodiscard]] inline Pose2 interpolate(const Pose2& a, const Pose2& b, double f) {
  const double dtheta = normalize_angle(b.theta - a.theta);
  return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), normalize_angle(a.theta + f * dtheta)};
}

}  // namespace tessera
