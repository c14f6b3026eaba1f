#pragma once
// The steering law shared by the path follower and the thesis-style greedy controller, so that a
// comparison between the two differs only in how the target point is chosen.
#include <algorithm>
#include <cmath>

#include "tessera/core/angle.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/nav/path_follower.hpp"
#include "tessera/nav/velocity_command.hpp"

namespace tessera::nav_internal {

/// Turn towards target_m at gain * heading error (rate-limited); drive at speed_m_per_s *
/// cos(error) unless the error exceeds turn_in_place_rad.
inline VelocityCommand steer_towards(const Pose2& T_map_robot, Vec2 target_m, double speed_m_per_s,
                                     const PathFollowerOptions& o) {
  const Vec2 d = target_m - T_map_robot.translation();
  const double error = normalize_angle(std::atan2(d.y, d.x) - T_map_robot.theta);
  VelocityCommand c;
  c.omega_rad_per_s = std::clamp(o.heading_gain_per_s * error, -o.max_turn_rate_rad_per_s,
                                 o.max_turn_rate_rad_per_s);
  c.v_m_per_s = std::abs(error) > o.turn_in_place_rad ? 0.0 : speed_m_per_s * std::cos(error);
  return c;
}

/// The speed limit near the goal: linear from max at slow_down_m down to min_speed_fraction * max.
inline double approach_speed(double dist_to_goal_m, const PathFollowerOptions& o) {
  const double f = std::clamp(dist_to_goal_m / o.slow_down_m, o.min_speed_fraction, 1.0);
  return o.max_speed_m_per_s * f;
}

}  // namespace tessera::nav_internal
