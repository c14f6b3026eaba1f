#include "tessera/sim/differential_drive.hpp"

#include <cmath>

#include "tessera/core/assert.hpp"

namespace tessera {

Pose2 arc_motion(double v_m_per_s, double w_rad_per_s, double dt_s) {
  const double angle = w_rad_per_s * dt_s;
  const double distance = v_m_per_s * dt_s;
  // Below this turn the series form avoids dividing by a tiny w (relative error < 1e-16).
  if (std::abs(angle) < 1e-6) {
    return {distance * (1.0 - angle * angle / 6.0), distance * angle / 2.0, normalize_angle(angle)};
  }
  const double radius = v_m_per_s / w_rad_per_s;
  const double half_sin = std::sin(0.5 * angle);  // 1 - cos(a) = 2 sin^2(a / 2), no cancellation
  return {radius * std::sin(angle), radius * 2.0 * half_sin * half_sin, normalize_angle(angle)};
}

DifferentialDriveRobot::DifferentialDriveRobot(const Pose2& T_world_robot,
                                               const OdometryErrorOptions& odometry, Rng rng)
    : truth_(T_world_robot), odometry_(T_world_robot), odometry_options_(odometry), rng_(rng) {
  TESSERA_ASSERT(!validate(odometry).has_value());
  truth_.theta = normalize_angle(truth_.theta);
  odometry_.theta = truth_.theta;
}

DriveStep DifferentialDriveRobot::step(double v_m_per_s, double w_rad_per_s, double dt_s) {
  TESSERA_ASSERT(dt_s >= 0.0 && std::isfinite(dt_s) && std::isfinite(v_m_per_s) &&
                 std::isfinite(w_rad_per_s));
  DriveStep s;
  s.true_increment = arc_motion(v_m_per_s, w_rad_per_s, dt_s);
  s.odometry_increment = noisy_odometry_increment(s.true_increment, odometry_options_, rng_);
  truth_ = truth_ * s.true_increment;
  odometry_ = odometry_ * s.odometry_increment;
  path_length_m_ += std::abs(v_m_per_s) * dt_s;
  turned_rad_ += std::abs(w_rad_per_s) * dt_s;
  return s;
}

}  // namespace tessera
