#include "tessera/sensors/wheel_encoders.hpp"

#include <cmath>
#include <numbers>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {

std::optional<std::string> validate(const WheelEncoderOptions& o) {
  if (!(o.wheel_radius_m > 0.0)) return "wheel_radius_m: must be > 0";
  if (!(o.track_width_m > 0.0)) return "track_width_m: must be > 0";
  if (!(o.ticks_per_wheel_rev >= 1.0)) return "ticks_per_wheel_rev: must be >= 1";
  if (!(o.scale_error_stddev >= 0.0)) return "scale_error_stddev: must be >= 0";
  if (!(o.tick_noise_stddev >= 0.0)) return "tick_noise_stddev: must be >= 0";
  return std::nullopt;
}

WheelTravel forward_travel(double distance_m) { return {distance_m, distance_m}; }

WheelTravel turn_travel(double angle_rad, const WheelEncoderOptions& o) {
  const double arc_m = 0.5 * o.track_width_m * angle_rad;
  return {-arc_m, arc_m};
}

Pose2 pose_increment(WheelTravel travel, double track_width_m) {
  const double ds = 0.5 * (travel.left_m + travel.right_m);
  const double dtheta = (travel.right_m - travel.left_m) / track_width_m;
  if (std::abs(dtheta) < 1e-12) return {ds, 0.0, 0.0};
  // Chord of a circular arc of length ds and turn dtheta.
  const double radius = ds / dtheta;
  return {radius * std::sin(dtheta), radius * (1.0 - std::cos(dtheta)), normalize_angle(dtheta)};
}

WheelEncoders::WheelEncoders(const WheelEncoderOptions& o, Rng& rng) : options_(o) {
  TESSERA_ASSERT(!validate(o).has_value());
  left_scale_ = o.scale_error_stddev > 0.0 ? rng.gaussian(o.scale_error_stddev) : 0.0;
  right_scale_ = o.scale_error_stddev > 0.0 ? rng.gaussian(o.scale_error_stddev) : 0.0;
}

EncoderTicks WheelEncoders::count(WheelTravel truth, Rng& rng) const {
  const double m_per_tick =
      2.0 * std::numbers::pi * options_.wheel_radius_m / options_.ticks_per_wheel_rev;
  const auto side = [&](double travel_m, double scale) {
    const double ticks = travel_m / m_per_tick * (1.0 + scale);
    const double sigma = options_.tick_noise_stddev * std::sqrt(std::abs(ticks));
    const double noise = sigma > 0.0 ? rng.gaussian(sigma) : 0.0;
    return static_cast<std::int64_t>(std::llround(ticks + noise));
  };
  const std::int64_t left = side(truth.left_m, left_scale_);
  return {left, side(truth.right_m, right_scale_)};
}

Pose2 WheelEncoders::odometry(EncoderTicks ticks) const {
  const double m_per_tick =
      2.0 * std::numbers::pi * options_.wheel_radius_m / options_.ticks_per_wheel_rev;
  return pose_increment(
      {static_cast<double>(ticks.left) * m_per_tick, static_cast<double>(ticks.right) * m_per_tick},
      options_.track_width_m);
}

}  // namespace tessera
