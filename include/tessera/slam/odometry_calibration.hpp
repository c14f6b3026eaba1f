#pragma once
// The odometry's systematic errors, estimated while mapping from local SLAM's matches: a wheel
// radius a few percent off stretches every predicted step, a wheel base off scales every turn, and
// two wheels of unequal radius turn the robot a little with every metre driven. The scan matcher,
// tied to the prediction (LaserSlamOptions::refiner), keeps part of each error where the walls do
// not pin the pose: the stretch along a corridor, the turn where a view is new. These are the
// three parameters of a differential drive's calibration (wheel radii and base; Censi et al. 2013,
// "Simultaneous calibration of odometry and sensor parameters", here without the sensor's pose):
//   true displacement = translation_scale * odometry's displacement
//   true turn         = rotation_scale * odometry's turn + drift_rad_per_m * odometry's distance
// Matched and reported motion are compared over segments of the path (not step by step: a single
// step's odometry carries noise the motion does not, and a sideways jitter reads as a longer
// step), the translation scale as matched length along the odometry's displacement per metre, the
// turn terms by least squares over the segments, all under a memory that fades along the path. A
// segment along a corridor that lands where the calibrated prediction put it agrees with the
// estimate and does not move it; segments whose walls pin the pose carry the correction.
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"

namespace tessera::slam {

struct OdometryCalibrationOptions {
  bool enabled = true;
  /// A segment ends when the odometry has moved segment_m from its start or turned segment_rad
  /// along it. It counts for the translation scale when it moved at least half of segment_m.
  double segment_m = 2.0;
  double segment_rad = 1.0;
  /// The translation scale and the drift are used once the segments counted cover this much
  /// travel; the rotation scale once they cover this much turning.
  double min_travel_m = 10.0;
  double min_turn_rad = 6.283185307179586;
  /// Memory: a segment's weight fades by exp(-travel / memory_m - turn / memory_rad) for every
  /// later segment's travel and turn, so a change (a load, a worn tyre) is followed.
  double memory_m = 200.0;
  double memory_rad = 60.0;
  /// The scales are held within 1 +- this and the drift within +- max_drift_rad_per_m: beyond
  /// them the odometry is broken, not miscalibrated. The heading drifts by the difference of the
  /// wheels' paths over the wheel base: 0.1 rad/m is one wheel's radius 4 % off its twin's on a
  /// 0.4 m base; Intel's robot drifts 0.06 rad/m (decision 0040).
  double max_scale_error = 0.1;
  double max_drift_rad_per_m = 0.1;
  /// A segment whose matched length differs from the calibrated prediction by more than this
  /// share of it, or whose turn by more than this share of the turn plus turn_slack_rad, is a
  /// failed match or a slip and is not counted.
  double outlier_share = 0.2;
  double turn_slack_rad = 0.05;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const OdometryCalibrationOptions& o);

class OdometryCalibration {
 public:
  explicit OdometryCalibration(const OdometryCalibrationOptions& options) : options_(options) {}

  /// The odometry step (T_odomprev_odom) with the estimated errors taken out.
  [[nodiscard]] Pose2 corrected(const Pose2& odometry_step) const;
  /// Records one step: what the odometry reported and what matching found (both from the
  /// previous scan's robot frame).
  void observe(const Pose2& odometry_step, const Pose2& matched_step);
  /// The path breaks here (a new trajectory): the open segment is dropped.
  void break_segment();

  /// The estimates in use (1, 1 and 0 until enough has been observed).
  [[nodiscard]] double translation_scale() const;
  [[nodiscard]] double rotation_scale() const;
  [[nodiscard]] double drift_rad_per_m() const;

 private:
  void add_segment();
  /// Solves the turn model's least squares (with a weak prior at 1 and 0) into rotation_ and
  /// drift_.
  void solve_turn();

  OdometryCalibrationOptions options_;
  // The open segment, from its start: composed steps and the odometry's signed distance
  // (forward positive) and absolute turn along it.
  Pose2 segment_odometry_;
  Pose2 segment_matched_;
  double segment_distance_m_ = 0.0;
  double segment_turn_rad_ = 0.0;
  // Translation: sums of matched length along the odometry's displacement, and of its length.
  double matched_along_m_ = 0.0;
  double odometry_m_ = 0.0;
  // Turn: the normal equations of matched = rotation * turn + drift * distance.
  double s_tt_ = 0.0, s_td_ = 0.0, s_dd_ = 0.0, s_mt_ = 0.0, s_md_ = 0.0;
  double rotation_ = 1.0;
  double drift_ = 0.0;
  // Unfaded: has enough been seen?
  double travel_m_ = 0.0;
  double turn_rad_ = 0.0;
};

}  // namespace tessera::slam
