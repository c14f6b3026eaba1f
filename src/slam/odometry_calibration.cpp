#include "tessera/slam/odometry_calibration.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tessera::slam {

std::optional<std::string> validate(const OdometryCalibrationOptions& o) {
  if (!(o.segment_m > 0.0)) return "segment_m must be > 0";
  if (!(o.segment_rad > 0.0)) return "segment_rad must be > 0";
  if (!(o.min_travel_m >= 0.0)) return "min_travel_m must be >= 0";
  if (!(o.min_turn_rad >= 0.0)) return "min_turn_rad must be >= 0";
  if (!(o.memory_m > 0.0)) return "memory_m must be > 0";
  if (!(o.memory_rad > 0.0)) return "memory_rad must be > 0";
  if (!(o.max_scale_error >= 0.0 && o.max_scale_error < 1.0)) {
    return "max_scale_error must be in [0, 1)";
  }
  if (!(o.max_drift_rad_per_m >= 0.0)) return "max_drift_rad_per_m must be >= 0";
  if (!(o.outlier_share > 0.0)) return "outlier_share must be > 0";
  if (!(o.turn_slack_rad >= 0.0)) return "turn_slack_rad must be >= 0";
  return std::nullopt;
}

namespace {
/// The weak prior of the turn model, in the units of its normal equations (as much as a segment
/// turning 0.3 rad at rotation scale 1, one of 0.3 m at drift 0): it keeps the equations solvable
/// before the robot has turned, and is soon outweighed.
constexpr double kTurnPrior = 0.1;
constexpr double kDriftPrior = 0.1;
}  // namespace

double OdometryCalibration::translation_scale() const {
  if (!options_.enabled || travel_m_ < options_.min_travel_m || !(odometry_m_ > 0.0)) return 1.0;
  const double e = options_.max_scale_error;
  return std::clamp(matched_along_m_ / odometry_m_, 1.0 - e, 1.0 + e);
}

double OdometryCalibration::rotation_scale() const {
  if (!options_.enabled || turn_rad_ < options_.min_turn_rad) return 1.0;
  const double e = options_.max_scale_error;
  return std::clamp(rotation_, 1.0 - e, 1.0 + e);
}

double OdometryCalibration::drift_rad_per_m() const {
  if (!options_.enabled || travel_m_ < options_.min_travel_m) return 0.0;
  const double e = options_.max_drift_rad_per_m;
  return std::clamp(drift_, -e, e);
}

Pose2 OdometryCalibration::corrected(const Pose2& odometry_step) const {
  const double k_t = translation_scale();
  // A step that turns nearly half a turn may be scaled past it: wrapped back then (only then, so
  // that every other step is exactly what it was).
  double theta = rotation_scale() * odometry_step.theta + drift_rad_per_m() * odometry_step.x;
  if (std::abs(theta) > std::numbers::pi) theta = normalize_angle(theta);
  return Pose2{k_t * odometry_step.x, k_t * odometry_step.y, theta};
}

void OdometryCalibration::break_segment() {
  segment_odometry_ = segment_matched_ = Pose2{};
  segment_distance_m_ = segment_turn_rad_ = 0.0;
}

void OdometryCalibration::observe(const Pose2& odometry_step, const Pose2& matched_step) {
  if (!options_.enabled) return;
  segment_odometry_ = segment_odometry_ * odometry_step;
  segment_matched_ = segment_matched_ * matched_step;
  segment_distance_m_ += odometry_step.x;
  segment_turn_rad_ += std::abs(odometry_step.theta);
  if (std::hypot(segment_odometry_.x, segment_odometry_.y) >= options_.segment_m ||
      segment_turn_rad_ >= options_.segment_rad) {
    add_segment();
    break_segment();
  }
}

void OdometryCalibration::add_segment() {
  const double length_m = std::hypot(segment_odometry_.x, segment_odometry_.y);
  const double turn_rad = segment_odometry_.theta;  // net, in (-pi, pi]
  const double fade =
      std::exp(-length_m / options_.memory_m - std::abs(turn_rad) / options_.memory_rad);

  if (length_m >= 0.5 * options_.segment_m) {
    const double along_m =
        (segment_matched_.x * segment_odometry_.x + segment_matched_.y * segment_odometry_.y) /
        length_m;
    const double predicted_m = translation_scale() * length_m;
    if (std::abs(along_m - predicted_m) <= options_.outlier_share * predicted_m) {
      matched_along_m_ = fade * matched_along_m_ + along_m;
      odometry_m_ = fade * odometry_m_ + length_m;
      travel_m_ += length_m;
    }
  }

  // The turn: matched = rotation * turn + drift * distance, over every segment (a straight one
  // says what the robot turns per metre when it means to go straight).
  const double d = segment_distance_m_;
  const double predicted_rad = rotation_scale() * turn_rad + drift_rad_per_m() * d;
  const double matched_rad = segment_matched_.theta;
  if (std::abs(matched_rad - predicted_rad) <=
      options_.outlier_share * std::abs(turn_rad) + options_.turn_slack_rad) {
    s_tt_ = fade * s_tt_ + turn_rad * turn_rad;
    s_td_ = fade * s_td_ + turn_rad * d;
    s_dd_ = fade * s_dd_ + d * d;
    s_mt_ = fade * s_mt_ + matched_rad * turn_rad;
    s_md_ = fade * s_md_ + matched_rad * d;
    turn_rad_ += std::abs(turn_rad);
    solve_turn();
  }
}

void OdometryCalibration::solve_turn() {
  // [s_tt + p_t, s_td; s_td, s_dd + p_d] (rotation, drift) = (s_mt + p_t, s_md).
  const double a = s_tt_ + kTurnPrior, b = s_td_, c = s_dd_ + kDriftPrior;
  const double det = a * c - b * b;
  if (!(det > 0.0)) return;
  rotation_ = (c * (s_mt_ + kTurnPrior) - b * s_md_) / det;
  drift_ = (a * s_md_ - b * (s_mt_ + kTurnPrior)) / det;
}

}  // namespace tessera::slam
