#pragma once
// A planar velocity and the motion it makes: placing each beam of a scan where the robot was when
// the beam was taken (slam/scan_points.hpp), from the odometry around the scan (io/robot_bag.hpp).
#include <cmath>

#include "tessera/core/pose2.hpp"

namespace tessera {

/// A velocity in a body's own frame: forward, leftward, and the turn rate (counter-clockwise).
struct Twist2 {
  double vx_m_per_s = 0.0;
  double vy_m_per_s = 0.0;
  double omega_rad_per_s = 0.0;

  [[nodiscard]] bool is_zero() const {
    return vx_m_per_s == 0.0 && vy_m_per_s == 0.0 && omega_rad_per_s == 0.0;
  }
};

/// Where a body moving at constant velocity `v` is after dt_s, seen from where it started (an arc:
/// SE(2)'s exponential map).
[[nodiscard]] inline Pose2 displacement(const Twist2& v, double dt_s) {
  const double theta = v.omega_rad_per_s * dt_s;
  const double vx = v.vx_m_per_s * dt_s, vy = v.vy_m_per_s * dt_s;
  if (std::abs(theta) < 1e-9) return {vx, vy, normalize_angle(theta)};
  const double a = std::sin(theta) / theta, b = (1.0 - std::cos(theta)) / theta;
  return {a * vx - b * vy, b * vx + a * vy, normalize_angle(theta)};
}

/// The constant velocity that moves a body by T_a_b in dt_s > 0 (displacement's inverse, for a
/// turn of less than half a turn).
[[nodiscard]] inline Twist2 velocity_between(const Pose2& T_a_b, double dt_s) {
  const double theta = T_a_b.theta;
  double vx = T_a_b.x, vy = T_a_b.y;
  if (std::abs(theta) >= 1e-9) {
    const double a = std::sin(theta) / theta, b = (1.0 - std::cos(theta)) / theta;
    const double det = a * a + b * b;
    vx = (a * T_a_b.x + b * T_a_b.y) / det;
    vy = (-b * T_a_b.x + a * T_a_b.y) / det;
  }
  return {vx / dt_s, vy / dt_s, theta / dt_s};
}

}  // namespace tessera
