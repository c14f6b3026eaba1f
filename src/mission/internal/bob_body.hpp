#pragma once
// How the simulated BOBMapping robot moves and knows where it is (BOBMapping 3.3): it turns in
// place and drives straight, dead-reckons with its wheel encoders while it moves, and takes
// ultrasonic beacon fixes when it stands still. The true pose follows the motor commands, except
// that now and then a track slips ("the slipping of wheels causes the robot to turn less than the
// planned angle or to move a shorter distance", 3.4) while the encoders count the full command;
// the believed pose integrates what the encoders counted, so the two drift apart until a fix.
//
// Beyond the paper, which replaces the position by the fix, the belief is an extended Kalman
// filter on (x, y, theta): fixes correct the position and, through the correlation that driving
// builds between heading and position, the heading too (the robot has no compass).
#include <array>
#include <cmath>
#include <optional>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sensors/beacon_trilateration.hpp"
#include "tessera/sensors/wheel_encoders.hpp"

namespace tessera::internal {

struct BobBodyOptions {
  bool perfect = false;  // exact motion and localisation: belief == truth, no fixes
  WheelEncoderOptions encoders;
  BeaconOptions beacons;
  /// A motion slips with this probability and then achieves only (1 - u) of the command, u
  /// uniform in [0, slip_max_fraction].
  double slip_probability = 0.02;
  double slip_max_fraction = 0.2;
  /// Fixes averaged at each stop: the beacons are accurate only at rest (3.3), so the robot
  /// waits for several; their mean halves the error with 4.
  int fixes_per_stop = 4;
  /// Standard deviation of one fix per axis, as the filter assumes it (the default beacons give
  /// a mean error of about 2 cm).
  double fix_stddev_m = 0.02;
  /// A fix farther than this from odometry means a slip: the filter then stops trusting the
  /// odometry before it takes the fix (BOBMapping 3.4 repositions the robot in that case).
  double slip_detection_m = 0.05;
};

class BobBody {
 public:
  /// Placed by hand at `start`: belief == truth. Draws the encoders' scale errors from rng.
  BobBody(const BobBodyOptions& options, const Pose2& start, Rng& rng);

  [[nodiscard]] const Pose2& truth() const { return truth_; }
  [[nodiscard]] const Pose2& belief() const { return belief_; }
  /// Filter standard deviations: position (the larger axis) and heading.
  [[nodiscard]] double position_stddev_m() const;
  [[nodiscard]] double heading_stddev_rad() const { return std::sqrt(p_[2][2]); }

  /// Turns in place until the believed heading points at `target_m`.
  void face(Vec2 target_m, Rng& rng);
  /// Drives straight by `distance_m` (negative: backwards).
  void drive(double distance_m, Rng& rng);

  /// Beacon fixes at rest (BOBMapping 3.3), averaged and fused into the belief. Returns the
  /// distance between the odometry position and the fix, or nullopt when trilateration fails
  /// (belief kept). With `perfect`, returns 0.
  std::optional<double> fix(Rng& rng);

 private:
  using Mat3 = std::array<std::array<double, 3>, 3>;
  void move(const WheelTravel& command, Rng& rng);

  BobBodyOptions options_;
  WheelEncoders encoders_;
  double side_stddev_per_sqrt_m_ = 0.0;  // encoder noise of one side, from the encoder model
  Pose2 truth_;
  Pose2 belief_;
  Mat3 p_{};  // covariance of the belief (x, y, theta)
};

}  // namespace tessera::internal
