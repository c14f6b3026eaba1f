#pragma once
// The error of a wheeled robot's odometry, for simulated runs: what dead reckoning reports for a
// true motion. Systematic errors after Borenstein & Feng 1996 ("Measurement and correction of
// systematic odometry errors in mobile robots", UMBmark): a distance scale (wheel diameter
// average), a rotation scale (effective wheelbase, their type A) and a heading drift per metre
// (unequal wheel diameters, their type B). Random errors after Thrun, Burgard & Fox, Probabilistic
// Robotics, Table 5.6 (sample_motion_model_odometry): the motion is split into rot1, trans, rot2
// and each part is perturbed by a zero-mean Gaussian whose variance grows with the motion
// (alpha1..alpha4). Unlike the book, the variances grow linearly, not quadratically, with the
// motion: the error is a random walk in distance and angle, so a run's accumulated drift does not
// depend on how often odometry is sampled (with squared terms it would vanish as the rate rises).
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {

/// Defaults: a robot whose odometry was calibrated roughly (1 % distance, 0.5 % rotation, 0.06
/// degrees of heading per metre) and whose wheels slip a little. Measured over 5-7 minute tours
/// of 114-168 m on three floor plans (sim/laser_run.hpp, docs/slam-results.md): dead reckoning
/// ends 0.2-1.2 m off with heading errors up to 12 degrees, an ATE of 0.13-0.51 m (decision
/// 0047). SLAM is expected to beat it by far. perfect_odometry() turns every error off.
struct OdometryErrorOptions {
  /// Odometry reports (1 + distance_scale_error) times the distance driven.
  double distance_scale_error = 0.01;
  /// Odometry reports (1 + rotation_scale_error) times the angle turned (wheelbase error).
  double rotation_scale_error = 0.005;
  /// Heading odometry gains per metre driven forward (counter-clockwise positive), although the
  /// robot drove straight (unequal wheel diameters). Borenstein & Feng's uncalibrated robots:
  /// a few thousandths of a radian per metre.
  double heading_drift_rad_per_m = 0.001;
  /// Thrun's alpha1: rotation variance per radian turned, rad^2 per rad (0.005 rad per sqrt(rad)).
  double rot_var_rad2_per_rad = 2.5e-5;
  /// Thrun's alpha2: rotation variance per metre driven, rad^2 per m (0.003 rad per sqrt(m)).
  double rot_var_rad2_per_m = 1e-5;
  /// Thrun's alpha3: distance variance per metre driven, m^2 per m (0.01 m per sqrt(m)).
  double trans_var_m2_per_m = 1e-4;
  /// Thrun's alpha4: distance variance per radian turned, m^2 per rad (0.003 m per sqrt(rad)).
  double trans_var_m2_per_rad = 1e-5;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const OdometryErrorOptions& o);

/// Odometry with every error switched off: reports the true motion exactly.
[[nodiscard]] OdometryErrorOptions perfect_odometry();

/// The increment T_prev_cur that odometry reports when the robot truly moves by T_prev_cur_true.
/// The motion is split as in Thrun Table 5.6: rot1 = heading of the displacement, trans = its
/// length, rot2 = the rest of the turn; a displacement pointing backwards counts as a negative
/// trans (rot1 is then the heading of the reversed displacement), so reversing does not read as a
/// half turn. Reported: trans * (1 + distance_scale_error) + noise, and each rot_i * (1 +
/// rotation_scale_error) + heading_drift_rad_per_m * trans / 2 + noise, with noise variances
/// alpha1 |rot_i| + alpha2 |trans| / 2 (rotations) and alpha3 |trans| + alpha4 (|rot1| + |rot2|)
/// (distance). Draws three Gaussians from rng (none for a part whose variance is zero).
/// Meant for small increments (a simulation step): rot1 and rot2 are taken in (-pi, pi]. A
/// translation of at most 1e-9 m (the floating-point dust a turn on the spot leaves when it is
/// computed as the motion between two poses) is none, and rot1 is 0 (decision 0047).
/// Precondition: validate(o) is empty. O(1).
[[nodiscard]] Pose2 noisy_odometry_increment(const Pose2& T_prev_cur_true,
                                             const OdometryErrorOptions& o, Rng& rng);

}  // namespace tessera
