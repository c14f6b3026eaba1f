#include "tessera/slam/odometry_calibration.hpp"

#include <algorithm>
#include <cmath>

namespace tessera::slam {

std::optional<std::string> validate(const OdometryCalibrationOptions& o) {
  if (!(o.min_travel_m >= 0.0)) return "min_travel_m must be >= 0";
  if (!(o.min_turn_rad >= 0.0)) return "min_turn_rad must be >= 0";
  if (!(o.segment_m > 0.0)) return "segment_m must be > 0";
  if (!(o.segment_rad > 0.0)) return "segment_rad must be > 0";
  if (!(o.memory_m > 0.0)) return "memory_m must be > 0";
  if (!(o.memory_rad > 0.0)) return "memory_rad must be > 0";
  if (!(o.max_scale_error >= 0.0 && o.max_scale_error < 1.0)) {
    return "max_scale_error must be in [0, 1)";
  }
  if (!(o.outlier_share > 0.0)) return "outlier_share must be > 0";
  return std::nullopt;
}

namespace {
double clamped(double scale, double max_error) {
  return std::clamp(scale, 1.0 - max_error, 1.0 + max_error);
}
}  // namespace

double OdometryCalibration::translation_scale() const {
  if (!options_.enabled || travel_m_ < options_.min_travel_m || !(odometry_m_ > 0.0)) return 1.0;
  return clamped(matched_along_m_ / odometry_m_, options_.max_scale_error);
}

double OdometryCalibration::rotation_scale() const {
  if (!options_.enabled || turn_rad_ < options_.min_turn_rad || !(odometry_turn_rad_ > 0.0)) {
    return 1.0;
  }
  return clamped(matched_turn_rad_ / odometry_turn_rad_, options_.max_scale_error);
}

Pose2 OdometryCalibration::corrected(const Pose2& odometry_step) const {
  const double k_t = translation_scale();
  return Pose2{k_t * odometry_step.x, k_t * odometry_step.y,
               rotation_scale() * odometry_step.theta};
}

void OdometryCalibration::observe(const Pose2& odometry_step, const Pose2& matched_step) {
  if (!options_.enabled) return;
  segment_odometry_ = segment_odometry_ * odometry_step;
  segment_matched_ = segment_matched_ * matched_step;
  segment_turn_rad_ += std::abs(odometry_step.theta);
  if (std::hypot(segment_odometry_.x, segment_odometry_.y) >= options_.segment_m ||
      segment_turn_rad_ >= options_.segment_rad) {
    add_segment();
    break_segment();
  }
}

void OdometryCalibration::add_segment() {
  const double length_m = std::hypot(segment_odometry_.x, segment_odometry_.y);
  if (length_m >= 0.5 * options_.segment_m) {
    const double along_m =
        (segment_matched_.x * segment_odometry_.x + segment_matched_.y * segment_odometry_.y) /
        length_m;
    const double predicted_m = translation_scale() * length_m;
    if (std::abs(along_m - predicted_m) <= options_.outlier_share * predicted_m) {
      const double fade = std::exp(-length_m / options_.memory_m);
      matched_along_m_ = fade * matched_along_m_ + along_m;
      odometry_m_ = fade * odometry_m_ + length_m;
      travel_m_ += length_m;
    }
  }
  const double turn_rad = std::abs(segment_odometry_.theta);
  if (turn_rad >= 0.5 * options_.segment_rad) {
    const double matched_rad = std::copysign(1.0, segment_odometry_.theta) * segment_matched_.theta;
    const double predicted_rad = rotation_scale() * turn_rad;
    if (std::abs(matched_rad - predicted_rad) <= options_.outlier_share * predicted_rad) {
      const double fade = std::exp(-turn_rad / options_.memory_rad);
      matched_turn_rad_ = fade * matched_turn_rad_ + matched_rad;
      odometry_turn_rad_ = fade * odometry_turn_rad_ + turn_rad;
      turn_rad_ += turn_rad;
    }
  }
}

}  // namespace tessera::slam
