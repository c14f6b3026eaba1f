#pragma once
// Following a committed polyline (nav/cell_polyline.hpp) with pure pursuit (Coulter,
// "Implementation of the Pure Pursuit Path Tracking Algorithm", CMU-RI-TR-92-01): the robot steers
// towards the point one look-ahead distance further along the path than its own projection.
// Progress along the path only moves forward, so crossing a cell border back and forth never
// changes the target: this is the zigzag fix of thesis section 6.2 item 3 (the thesis re-decided at
// every border, 4.3.5).
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/nav/velocity_command.hpp"

namespace tessera {

/// Motion limits and gains of a differential-drive robot driving to points. The defaults suit a
/// Pioneer 3-DX indoors (thesis section 3.1.1) at the thesis' avoidance turn rates (0.3-0.5 rad/s).
struct PathFollowerOptions {
  double max_speed_m_per_s = 0.3;
  double max_turn_rate_rad_per_s = 0.5;
  /// omega = heading_gain_per_s * heading error, clamped to max_turn_rate_rad_per_s.
  double heading_gain_per_s = 1.5;
  /// Heading errors beyond this turn in place (v = 0); below it v = max speed * cos(error).
  double turn_in_place_rad = 0.8;
  /// Pure-pursuit look-ahead along the path; one cell spacing by default.
  double lookahead_m = 0.3;
  /// Within this distance of the last point the robot has arrived and stops.
  double goal_tolerance_m = 0.05;
  /// Speed falls linearly to min_speed_fraction * max within this distance of the last point.
  double slow_down_m = 0.3;
  double min_speed_fraction = 0.2;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const PathFollowerOptions& o);

/// Pure pursuit along a fixed polyline in the map frame.
class PathFollower {
 public:
  /// Preconditions: waypoints_m non-empty, !validate(options).
  PathFollower(std::vector<Vec2> waypoints_m, PathFollowerOptions options = {});

  /// The command for the robot at T_map_robot; advances the progress along the path (never
  /// backwards). Zero once arrived. Cost: O(1) amortised.
  [[nodiscard]] VelocityCommand command(const Pose2& T_map_robot);

  [[nodiscard]] bool arrived() const { return arrived_; }
  /// Distance from the robot to the path ahead (from the segment of the progress point on) at the
  /// last command, metres: the caller replans when the robot has been pushed off its corridor
  /// (e.g. by obstacle avoidance).
  [[nodiscard]] double cross_track_m() const { return cross_track_m_; }
  /// Arc length of the robot's projection onto the path, metres.
  [[nodiscard]] double progress_m() const { return progress_m_; }
  [[nodiscard]] const std::vector<Vec2>& waypoints() const { return waypoints_; }

 private:
  [[nodiscard]] Vec2 point_at(double s_m) const;

  std::vector<Vec2> waypoints_;
  std::vector<double> arc_m_;  // arc_m_[i]: path length up to waypoint i
  PathFollowerOptions options_;
  std::size_t segment_ = 0;  // segment of the progress point
  double progress_m_ = 0.0;
  double cross_track_m_ = 0.0;
  bool arrived_ = false;
};

}  // namespace tessera
