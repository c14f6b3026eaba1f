#pragma once
// The odometry's scale errors, estimated while mapping from local SLAM's matches: a wheel radius
// a few percent off (or a log whose odometry was made so) stretches every predicted step, and the
// scan matcher, tied to that prediction (LaserSlamOptions::refiner), keeps part of the stretch
// where the walls do not fix the pose: along corridors. Each matched step is set against its
// odometry step; the translation scale is the matched length along the odometry's direction per
// metre the odometry reports, the rotation scale the matched turn per radian it reports on steps
// that turn, both over a fading memory of the path (the idea of online odometry calibration as in
// Censi et al. 2013, "Simultaneous calibration of odometry and sensor parameters", reduced to the
// two scales and to local SLAM's steps). A step along a corridor agrees with the scale it was
// predicted with, so it neither moves the estimate nor biases it; steps whose walls fix the pose
// carry the correction.
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"

namespace tessera::slam {

struct OdometryCalibrationOptions {
  bool enabled = true;
  /// Steps are compared over segments of the path, not one by one: a single step's odometry
  /// carries noise the true motion does not (a sideways jitter lengthens it, a ratio of lengths
  /// then reads short), and over a segment that noise is small against the displacement. A
  /// segment ends when the odometry has moved segment_m from its start or turned segment_rad
  /// along it; it gives a translation sample when it moved at least half of segment_m, and a
  /// rotation sample when its net turn is at least half of segment_rad.
  double segment_m = 2.0;
  double segment_rad = 1.0;
  /// The translation scale is used once the samples cover this much travel, the rotation scale
  /// once they cover this much turning.
  double min_travel_m = 10.0;
  double min_turn_rad = 6.283185307179586;
  /// Memory: older samples fade by exp(-travel / memory_m) (and turning by exp(-turn /
  /// memory_rad)), so a scale that changes (a load, a worn tyre) is followed.
  double memory_m = 200.0;
  double memory_rad = 60.0;
  /// Scales are held within 1 +- this: beyond it the odometry is broken, not miscalibrated.
  double max_scale_error = 0.1;
  /// A segment whose matched length differs from the calibrated prediction by more than this
  /// share, or whose turn does, is a failed match or a slip and is not counted.
  double outlier_share = 0.2;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const OdometryCalibrationOptions& o);

class OdometryCalibration {
 public:
  explicit OdometryCalibration(const OdometryCalibrationOptions& options) : options_(options) {}

  /// The odometry step (T_odomprev_odom) with the estimated scales applied.
  [[nodiscard]] Pose2 corrected(const Pose2& odometry_step) const;
  /// Records one step: what the odometry reported and what matching found (both from the
  /// previous scan's robot frame).
  void observe(const Pose2& odometry_step, const Pose2& matched_step);
  /// The path breaks here (a new trajectory): the open segment is dropped.
  void break_segment() { segment_odometry_ = segment_matched_ = Pose2{}, segment_turn_rad_ = 0.0; }

  /// The scales in use (1 until enough has been observed).
  [[nodiscard]] double translation_scale() const;
  [[nodiscard]] double rotation_scale() const;

 private:
  void add_segment();

  OdometryCalibrationOptions options_;
  Pose2 segment_odometry_;  // the open segment, from its start
  Pose2 segment_matched_;
  double segment_turn_rad_ = 0.0;  // turned along it, as the odometry reports
  double matched_along_m_ = 0.0;   // sum of matched length along the odometry's direction
  double odometry_m_ = 0.0;        // sum of the odometry's lengths (faded like the above)
  double travel_m_ = 0.0;          // unfaded: enough seen?
  double matched_turn_rad_ = 0.0;
  double odometry_turn_rad_ = 0.0;
  double turn_rad_ = 0.0;
};

}  // namespace tessera::slam
