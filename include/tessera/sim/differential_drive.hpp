#pragma once
// A differential-drive robot for closed-loop simulation: its true pose, and the pose its wheel
// odometry reports, drifting as sensors/odometry_model.hpp describes. A controller (the waypoint
// driver of sim/rgbd_run.hpp, later the fusion navigation) commands a forward speed and a turn
// rate per time step; the robot moves exactly along the commanded arc (no slip in where it goes:
// all the error is in what odometry reports, as in sim/laser_run.hpp).
#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/odometry_model.hpp"

namespace tessera {

/// What one step did: the true motion and what odometry reports, both as T_prev_cur.
struct DriveStep {
  Pose2 true_increment;
  Pose2 odometry_increment;
};

class DifferentialDriveRobot {
 public:
  /// Odometry starts at the true start pose (the odometry frame is the world frame at the start).
  /// Precondition: validate(odometry) is empty.
  DifferentialDriveRobot(const Pose2& T_world_robot, const OdometryErrorOptions& odometry, Rng rng);

  /// Drives for dt_s at forward speed v_m_per_s and turn rate w_rad_per_s (counter-clockwise
  /// positive): the exact circular arc (a straight line when w = 0). Odometry composes
  /// noisy_odometry_increment of the true motion. Precondition: dt_s >= 0, all finite. O(1).
  DriveStep step(double v_m_per_s, double w_rad_per_s, double dt_s);

  [[nodiscard]] const Pose2& true_pose() const { return truth_; }
  [[nodiscard]] const Pose2& odometry_pose() const { return odometry_; }
  /// Distance driven (|v| dt summed) and angle turned (|w| dt summed).
  [[nodiscard]] double path_length_m() const { return path_length_m_; }
  [[nodiscard]] double turned_rad() const { return turned_rad_; }

 private:
  Pose2 truth_;
  Pose2 odometry_;
  OdometryErrorOptions odometry_options_;
  Rng rng_;
  double path_length_m_ = 0.0;
  double turned_rad_ = 0.0;
};

/// The exact motion of driving at (v, w) for dt: {sin(w dt) v / w, (1 - cos(w dt)) v / w, w dt}.
[[nodiscard]] Pose2 arc_motion(double v_m_per_s, double w_rad_per_s, double dt_s);

}  // namespace tessera
