#include "tessera/sensors/odometry_model.hpp"

#include <cmath>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

bool non_negative(double v) { return v >= 0.0 && std::isfinite(v); }

/// A scale error above this is no longer an error but a different robot (and 1 + e <= 0 would
/// reverse the motion).
constexpr double kMaxScaleError = 0.5;

/// Zero-mean Gaussian with the given variance; no draw when it is zero.
double sample_with_variance(double variance, Rng& rng) {
  return variance > 0.0 ? rng.gaussian(std::sqrt(variance)) : 0.0;
}

}  // namespace

std::optional<std::string> validate(const OdometryErrorOptions& o) {
  if (!(std::abs(o.distance_scale_error) < kMaxScaleError)) {
    return "distance_scale_error must be in (-0.5, 0.5), got " +
           std::to_string(o.distance_scale_error);
  }
  if (!(std::abs(o.rotation_scale_error) < kMaxScaleError)) {
    return "rotation_scale_error must be in (-0.5, 0.5), got " +
           std::to_string(o.rotation_scale_error);
  }
  if (!std::isfinite(o.heading_drift_rad_per_m)) return "heading_drift_rad_per_m must be finite";
  if (!non_negative(o.rot_var_rad2_per_rad)) {
    return "rot_var_rad2_per_rad must be >= 0, got " + std::to_string(o.rot_var_rad2_per_rad);
  }
  if (!non_negative(o.rot_var_rad2_per_m)) {
    return "rot_var_rad2_per_m must be >= 0, got " + std::to_string(o.rot_var_rad2_per_m);
  }
  if (!non_negative(o.trans_var_m2_per_m)) {
    return "trans_var_m2_per_m must be >= 0, got " + std::to_string(o.trans_var_m2_per_m);
  }
  if (!non_negative(o.trans_var_m2_per_rad)) {
    return "trans_var_m2_per_rad must be >= 0, got " + std::to_string(o.trans_var_m2_per_rad);
  }
  return std::nullopt;
}

OdometryErrorOptions perfect_odometry() {
  OdometryErrorOptions o;
  o.distance_scale_error = 0.0;
  o.rotation_scale_error = 0.0;
  o.heading_drift_rad_per_m = 0.0;
  o.rot_var_rad2_per_rad = 0.0;
  o.rot_var_rad2_per_m = 0.0;
  o.trans_var_m2_per_m = 0.0;
  o.trans_var_m2_per_rad = 0.0;
  return o;
}

Pose2 noisy_odometry_increment(const Pose2& T_prev_cur_true, const OdometryErrorOptions& o,
                               Rng& rng) {
  TESSERA_ASSERT(!validate(o).has_value());
  // Thrun Table 5.6, lines 2-4, with a backward displacement as a negative trans.
  const double dx = T_prev_cur_true.x, dy = T_prev_cur_true.y;
  double trans = std::hypot(dx, dy);
  double rot1 = 0.0;
  // A turn on the spot composed from poses leaves floating-point dust (1e-17 m) of translation,
  // whose direction means nothing: it is no translation, and rot1 is 0 (else the turn's noise
  // would grow with an arbitrary rot1 of up to 90 degrees).
  constexpr double kNoTranslation_m = 1e-9;
  if (trans <= kNoTranslation_m) trans = 0.0;
  if (trans > 0.0) {
    if (dx >= 0.0) {
      rot1 = std::atan2(dy, dx);
    } else {
      rot1 = std::atan2(-dy, -dx);
      trans = -trans;
    }
  }
  const double rot2 = normalize_angle(T_prev_cur_true.theta - rot1);

  // Systematic errors (Borenstein & Feng 1996): scales, and the heading drift of unequal wheels
  // split evenly between the two rotations.
  const double drift = 0.5 * o.heading_drift_rad_per_m * trans;
  double rot1_hat = rot1 * (1.0 + o.rotation_scale_error) + drift;
  double trans_hat = trans * (1.0 + o.distance_scale_error);
  double rot2_hat = rot2 * (1.0 + o.rotation_scale_error) + drift;

  // Random errors (Thrun Table 5.6, lines 5-7), variances linear in the motion.
  const double abs_trans = std::abs(trans);
  rot1_hat += sample_with_variance(
      o.rot_var_rad2_per_rad * std::abs(rot1) + 0.5 * o.rot_var_rad2_per_m * abs_trans, rng);
  trans_hat += sample_with_variance(
      o.trans_var_m2_per_m * abs_trans + o.trans_var_m2_per_rad * (std::abs(rot1) + std::abs(rot2)),
      rng);
  rot2_hat += sample_with_variance(
      o.rot_var_rad2_per_rad * std::abs(rot2) + 0.5 * o.rot_var_rad2_per_m * abs_trans, rng);

  // Lines 8-10: the reported motion.
  return {trans_hat * std::cos(rot1_hat), trans_hat * std::sin(rot1_hat),
          normalize_angle(rot1_hat + rot2_hat)};
}

}  // namespace tessera
