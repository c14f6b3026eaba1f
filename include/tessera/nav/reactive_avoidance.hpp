#pragma once
// The reactive obstacle avoidance of the Fusion SLAM thesis, section 4.3.4 (robot process loop),
// on a Pioneer 3-DX (section 3.1.1: 8 front sonars, 5 front and 5 rear bumpers) with a Kinect:
// - Bumpers are checked every iteration. "If any of the bumpers show a collision the position of
//   the crashed bumper position is used to turn away from the obstacle by a speed of 0.1 rad/s
//   times the distance to the outside bumpers." We read that as 0.1 rad/s x (1 + bumper positions
//   between the hit and the nearer outer bumper): 0.1 rad/s for an outer bumper, 0.3 rad/s for the
//   centre one, so a head-on hit turns hardest; and we also back off (the thesis only says "turn
//   away").
// - "The sonar checks out to a distance of 1.0 m and the Kinect checks out to a distance of 0.6 m.
//   The function determines which position has the closest obstacle and turns away from the
//   obstacle direction. The speed to turn away by is 0.3 rad/s for obstacles out to 1.0 m and
//   0.5 rad/s for any obstacle within 0.4 m."
// - Otherwise the navigation command passes through unchanged.
// Forward speeds while avoiding are not in the thesis and are ours (options below).
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "tessera/nav/velocity_command.hpp"

namespace tessera {

/// Pressed bumpers. Index 0 is the left-most bumper and 4 the right-most, seen from above with the
/// robot facing forward, for the front and the rear ring alike (P3DX, thesis Figure 3.4).
struct BumperState {
  std::array<bool, 5> front{};
  std::array<bool, 5> rear{};
};

/// One range to an obstacle: a sonar reading, or the minimum depth of a band of image columns.
/// bearing_rad is in the robot frame, counter-clockwise from straight ahead (left positive).
/// Readings with a range that is not finite and positive are "no echo" and ignored.
struct ObstacleRange {
  double bearing_rad = 0.0;
  double range_m = 0.0;
};

struct ObstacleSensing {
  BumperState bumpers;
  std::vector<ObstacleRange> sonar;
  std::vector<ObstacleRange>
      depth;  // e.g. min depth per column band, or one reading straight ahead
};

struct ReactiveAvoidanceOptions {
  double sonar_range_m = 1.0;                    // thesis 4.3.4
  double depth_range_m = 0.6;                    // thesis 4.3.4
  double near_range_m = 0.4;                     // thesis 4.3.4: the faster turn inside this
  double far_turn_rate_rad_per_s = 0.3;          // thesis 4.3.4
  double near_turn_rate_rad_per_s = 0.5;         // thesis 4.3.4
  double bumper_turn_rate_step_rad_per_s = 0.1;  // thesis 4.3.4, per bumper position
  /// Only obstacles within this angle of straight ahead make the robot turn (the P3DX's front
  /// sonars cover +-90 degrees). Ours.
  double field_of_view_half_rad = 1.5707963267948966;
  /// Ours; 0 keeps the thesis' rule. When > 0 a reading makes the robot turn only if the obstacle
  /// lies in the path the navigation command would sweep: within this distance of the arc it
  /// drives, ahead along it by up to a quarter turn (a command that turns in place sweeps
  /// nothing); and a turn away keeps its side until the way is clear. Under the thesis' rule every
  /// wall within 1 m at up to 90 degrees turns the robot away, so it cannot follow a corridor
  /// narrower than 2 m or turn a corner (docs/fusion-navigation.md, "The obstacle course").
  double path_half_width_m = 0.0;
  /// Where range readings start: this far from the robot's centre along their bearing (a P3DX's
  /// sonars sit on its edge). Only the strip test uses it.
  double sensor_radius_m = 0.0;
  /// Ours; 0 keeps the thesis' rule (the navigation command passes through as soon as nothing is
  /// in range). When > 0, once a turn away has cleared the way the robot drives straight on at
  /// avoid_speed_m_per_s for this long, and then, while a sonar on the obstacle's side (20 to 100
  /// degrees) reads within beside_range_m, the navigation may not turn it back towards that side,
  /// for at most bypass_limit_s. Without it a navigation that turns back to its path meets the
  /// obstacle again at once, and the two turn the robot to and fro in front of it.
  double straight_after_turn_s = 0.0;
  double beside_range_m = 0.4;
  double bypass_limit_s = 10.0;
  double avoid_speed_m_per_s = 0.1;    // ours: forward speed cap while turning away (far)
  double backoff_speed_m_per_s = 0.1;  // ours: reverse speed after a front bumper hit
  double backoff_duration_s = 1.0;     // ours: keep backing off this long after release
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ReactiveAvoidanceOptions& o);

/// What the last filter() call did.
enum class AvoidanceAction {
  kPassThrough,   // nothing in range: the navigation command unchanged
  kTurnAwayFar,   // obstacle within sonar/depth range: turn at the far rate, slow forward
  kTurnAwayNear,  // obstacle within near_range_m: turn in place at the near rate
  kBumperEscape,  // a bumper is (or was recently) pressed: back off and turn
  kStraightOn,    // after a turn away: straight on past the obstacle (straight_after_turn_s)
};

[[nodiscard]] const char* to_string(AvoidanceAction a);

/// Stateful only for the back-off timer after a bumper release.
class ReactiveAvoidance {
 public:
  /// Precondition: !validate(options).
  explicit ReactiveAvoidance(ReactiveAvoidanceOptions options = {});

  /// The command to send, given the navigation command and this cycle's sensing; dt_s is the time
  /// since the previous call (for the back-off timer). Precondition: dt_s >= 0.
  [[nodiscard]] VelocityCommand filter(const ObstacleSensing& sensing, VelocityCommand navigation,
                                       double dt_s);

  [[nodiscard]] AvoidanceAction last_action() const { return last_action_; }

 private:
  ReactiveAvoidanceOptions options_;
  AvoidanceAction last_action_ = AvoidanceAction::kPassThrough;
  VelocityCommand escape_;  // the command of the last bumper hit
  double escape_left_s_ = 0.0;
  [[nodiscard]] bool obstacle_beside(const std::vector<ObstacleRange>& sonar) const;

  double straight_left_s_ = 0.0;
  double bypass_left_s_ = 0.0;
  double turn_sign_ = 1.0;  // +1 turning left (counter-clockwise) away from the obstacle
};

}  // namespace tessera
