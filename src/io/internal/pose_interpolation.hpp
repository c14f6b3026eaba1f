#pragma once
// Odometry between two readings, as the log readers interpolate it (CARMEN RAWLASER1, bag scans).
#include "tessera/core/pose2.hpp"

namespace tessera::io_internal {

/// The pose a fraction f in [0, 1] of the way from a to b: linear in x and y, along the shorter
/// arc in theta.
[[nodiscard]] inline Pose2 interpolate_pose(const Pose2& a, const Pose2& b, double f) {
  const double dtheta = normalize_angle(b.theta - a.theta);
  return {a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), normalize_angle(a.theta + f * dtheta)};
}

}  // namespace tessera::io_internal
