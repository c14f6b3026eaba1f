#pragma once
// A differential-drive robot for navigation tests: commands applied for dt, integrated exactly
// along the arc, with counts of what a user would see (distance, heading reversals).
#include <cmath>
#include <vector>

#include "tessera/core/angle.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/eval/heading_reversals.hpp"
#include "tessera/nav/velocity_command.hpp"

namespace tessera::nav_test {

/// The pose after driving (v, omega) for dt_s from `pose` (exact unicycle arc).
inline Pose2 integrate(const Pose2& pose, VelocityCommand c, double dt_s) {
  const double dth = c.omega_rad_per_s * dt_s;
  double dx = 0.0, dy = 0.0;
  if (std::abs(dth) < 1e-9) {
    dx = c.v_m_per_s * dt_s * std::cos(pose.theta);
    dy = c.v_m_per_s * dt_s * std::sin(pose.theta);
  } else {
    const double r = c.v_m_per_s / c.omega_rad_per_s;
    dx = r * (std::sin(pose.theta + dth) - std::sin(pose.theta));
    dy = -r * (std::cos(pose.theta + dth) - std::cos(pose.theta));
  }
  return {pose.x + dx, pose.y + dy, normalize_angle(pose.theta + dth)};
}

struct DriveResult {
  std::vector<Pose2> poses;
  double length_m = 0.0;
  int heading_reversals = 0;
  bool arrived = false;
  double time_s = 0.0;
};

/// Runs `controller` (anything with command(Pose2) and arrived()) from `start` until it arrives or
/// max_time_s passes, at dt_s per step.
template <typename Controller>
DriveResult drive(Controller& controller, Pose2 start, double dt_s, double max_time_s,
                  double reversal_threshold_rad = 0.1) {
  DriveResult r;
  HeadingReversalCounter reversals(reversal_threshold_rad);
  Pose2 pose = start;
  r.poses.push_back(pose);
  reversals.add(pose.theta);
  for (double t = 0.0; t < max_time_s; t += dt_s) {
    const VelocityCommand c = controller.command(pose);
    if (controller.arrived()) {
      r.arrived = true;
      r.time_s = t;
      break;
    }
    const Pose2 next = integrate(pose, c, dt_s);
    r.length_m += (next.translation() - pose.translation()).norm();
    pose = next;
    r.poses.push_back(pose);
    reversals.add(pose.theta);
    r.time_s = t + dt_s;
  }
  r.heading_reversals = reversals.reversals();
  return r;
}

}  // namespace tessera::nav_test
