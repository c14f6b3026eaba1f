#pragma once
#include <cstdint>
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {

/// Differential-drive (tracked) odometry from one quadrature encoder per motor, as BOBMapping
/// 3.3 uses between beacon fixes: pulses times the wheel's arc per pulse gives each side's travel.
/// Defaults: BOBMapping 4.1's robot (GHM-04 motors with a 30:1 gearbox, E4P-100 encoders of 100
/// cycles per revolution read in quadrature on the motor shaft: 100 * 4 * 30 = 12000 ticks per
/// wheel turn), a 2 cm drive sprocket and a 12 cm track width (the body is 15 cm wide).
///
/// Error model, the cause of the cumulative error of 3.3: each side counts (1 + scale) times the
/// true ticks, scale drawn once per robot from N(0, scale_error_stddev) (sprocket and track slip
/// differ per side), plus per-move noise of tick_noise_stddev * sqrt(ticks) ticks (random slip).
struct WheelEncoderOptions {
  double wheel_radius_m = 0.02;
  double track_width_m = 0.12;
  double ticks_per_wheel_rev = 12000.0;
  double scale_error_stddev = 0.0005;  // 0.05 % per side, systematic (after calibration)
  double tick_noise_stddev = 0.3;      // ticks per sqrt(tick), random
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const WheelEncoderOptions& o);

/// Distance each side's track moves, metres; positive forward.
struct WheelTravel {
  double left_m = 0.0;
  double right_m = 0.0;
};

/// Counted encoder pulses of one motion.
struct EncoderTicks {
  std::int64_t left = 0;
  std::int64_t right = 0;
};

/// Both sides forward by distance_m ("move one cell forward" is forward_travel(0.22)).
[[nodiscard]] WheelTravel forward_travel(double distance_m);
/// Turn in place by angle_rad, counter-clockwise positive ("turn 90 degrees" is pi / 2).
[[nodiscard]] WheelTravel turn_travel(double angle_rad, const WheelEncoderOptions& o);

/// The motion T_before_after of a differential drive whose sides travel `travel` at constant
/// speeds (a circular arc; a straight line when both are equal). Exact, O(1).
[[nodiscard]] Pose2 pose_increment(WheelTravel travel, double track_width_m);

/// One robot's pair of encoders, with its systematic scale errors drawn at construction.
/// Deterministic: the same seed gives the same scales and, with the same later draws, the same
/// drift.
class WheelEncoders {
 public:
  /// Draws the two scale errors from rng. Precondition: validate(o) is empty.
  WheelEncoders(const WheelEncoderOptions& o, Rng& rng);

  /// Pulses counted while the sides truly travel `truth`. Draws two Gaussians when noise is on.
  [[nodiscard]] EncoderTicks count(WheelTravel truth, Rng& rng) const;
  /// What the robot believes from the pulses: nominal arc per tick, exact arc integration.
  [[nodiscard]] Pose2 odometry(EncoderTicks ticks) const;
  /// count then odometry: the believed T_before_after of a true motion.
  [[nodiscard]] Pose2 measure(WheelTravel truth, Rng& rng) const {
    return odometry(count(truth, rng));
  }

  [[nodiscard]] double left_scale() const { return left_scale_; }
  [[nodiscard]] double right_scale() const { return right_scale_; }
  [[nodiscard]] const WheelEncoderOptions& options() const { return options_; }

 private:
  WheelEncoderOptions options_;
  double left_scale_ = 0.0;
  double right_scale_ = 0.0;
};

}  // namespace tessera
