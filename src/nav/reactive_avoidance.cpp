#include "tessera/nav/reactive_avoidance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

// Turn rate and direction for one bumper ring: step x (1 + positions from the mean pressed index to
// the nearer outer bumper), turning away from the side that was hit (a centred hit turns left).
// 0 when nothing in the ring is pressed.
double bumper_turn(const std::array<bool, 5>& ring, double step_rad_per_s) {
  double sum = 0.0;
  int n = 0;
  for (int i = 0; i < 5; ++i) {
    if (ring[static_cast<std::size_t>(i)]) {
      sum += i;
      ++n;
    }
  }
  if (n == 0) return 0.0;
  const double centre = sum / n;  // 0 = left-most ... 4 = right-most
  const double to_outer = std::min(centre, 4.0 - centre);
  const double rate = step_rad_per_s * (1.0 + to_outer);
  return centre < 2.0 ? -rate : rate;  // hit on the left: turn right (clockwise)
}

// Ours (the strip rule): whether the point (x, y) of the robot frame lies within half_width_m of
// the arc that driving `c` sweeps, ahead along it by at most a quarter turn. Turning in place or
// backing up sweeps nothing ahead: a disc can always turn.
bool in_swept_path(double x, double y, VelocityCommand c, double half_width_m) {
  if (c.v_m_per_s <= 0.0) return false;
  const double radius = std::abs(c.omega_rad_per_s) < 1e-6
                            ? std::numeric_limits<double>::infinity()
                            : c.v_m_per_s / c.omega_rad_per_s;  // signed: > 0 turning left
  if (std::abs(radius) > 100.0) return x > 0.0 && std::abs(y) <= half_width_m;
  // The arc's centre is (0, radius); the robot is at angle 0 along it, moving forwards.
  const double from_centre = std::hypot(x, y - radius);
  if (std::abs(from_centre - std::abs(radius)) > half_width_m) return false;
  const double along_rad = std::atan2(x, std::abs(radius) - std::copysign(1.0, radius) * y);
  return along_rad >= 0.0 && along_rad <= std::numbers::pi / 2;
}

}  // namespace

std::optional<std::string> validate(const ReactiveAvoidanceOptions& o) {
  if (!positive_finite(o.sonar_range_m)) return "sonar_range_m must be > 0";
  if (!positive_finite(o.depth_range_m)) return "depth_range_m must be > 0";
  if (!positive_finite(o.near_range_m)) return "near_range_m must be > 0";
  if (!positive_finite(o.far_turn_rate_rad_per_s)) return "far_turn_rate_rad_per_s must be > 0";
  if (!positive_finite(o.near_turn_rate_rad_per_s)) return "near_turn_rate_rad_per_s must be > 0";
  if (!positive_finite(o.bumper_turn_rate_step_rad_per_s)) {
    return "bumper_turn_rate_step_rad_per_s must be > 0";
  }
  if (!positive_finite(o.field_of_view_half_rad)) return "field_of_view_half_rad must be > 0";
  if (!(std::isfinite(o.path_half_width_m) && o.path_half_width_m >= 0.0)) {
    return "path_half_width_m must be >= 0";
  }
  if (!(std::isfinite(o.sensor_radius_m) && o.sensor_radius_m >= 0.0)) {
    return "sensor_radius_m must be >= 0";
  }
  if (!(std::isfinite(o.straight_after_turn_s) && o.straight_after_turn_s >= 0.0)) {
    return "straight_after_turn_s must be >= 0";
  }
  if (!positive_finite(o.beside_range_m)) return "beside_range_m must be > 0";
  if (!(std::isfinite(o.bypass_limit_s) && o.bypass_limit_s >= o.straight_after_turn_s)) {
    return "bypass_limit_s must be >= straight_after_turn_s";
  }
  if (!(std::isfinite(o.avoid_speed_m_per_s) && o.avoid_speed_m_per_s >= 0.0)) {
    return "avoid_speed_m_per_s must be >= 0";
  }
  if (!(std::isfinite(o.backoff_speed_m_per_s) && o.backoff_speed_m_per_s >= 0.0)) {
    return "backoff_speed_m_per_s must be >= 0";
  }
  if (!(std::isfinite(o.backoff_duration_s) && o.backoff_duration_s >= 0.0)) {
    return "backoff_duration_s must be >= 0";
  }
  return std::nullopt;
}

const char* to_string(AvoidanceAction a) {
  switch (a) {
    case AvoidanceAction::kPassThrough:
      return "pass_through";
    case AvoidanceAction::kTurnAwayFar:
      return "turn_away_far";
    case AvoidanceAction::kTurnAwayNear:
      return "turn_away_near";
    case AvoidanceAction::kBumperEscape:
      return "bumper_escape";
    case AvoidanceAction::kStraightOn:
      return "straight_on";
  }
  return "unknown";
}

ReactiveAvoidance::ReactiveAvoidance(ReactiveAvoidanceOptions options) : options_(options) {
  TESSERA_ASSERT(!validate(options_));
}

bool ReactiveAvoidance::obstacle_beside(const std::vector<ObstacleRange>& sonar) const {
  // The obstacle's side is opposite the turn: bearings from 20 to 100 degrees on that side.
  for (const ObstacleRange& r : sonar) {
    if (!positive_finite(r.range_m) || !std::isfinite(r.bearing_rad)) continue;
    const double side_bearing = -turn_sign_ * r.bearing_rad;
    if (side_bearing >= 0.35 && side_bearing <= 1.75 && r.range_m <= options_.beside_range_m) {
      return true;
    }
  }
  return false;
}

VelocityCommand ReactiveAvoidance::filter(const ObstacleSensing& sensing,
                                          VelocityCommand navigation, double dt_s) {
  TESSERA_ASSERT(dt_s >= 0.0);
  const ReactiveAvoidanceOptions& o = options_;

  // 1. Bumpers, every iteration, before anything else.
  const double front_turn = bumper_turn(sensing.bumpers.front, o.bumper_turn_rate_step_rad_per_s);
  const double rear_turn = bumper_turn(sensing.bumpers.rear, o.bumper_turn_rate_step_rad_per_s);
  const bool front_hit = front_turn != 0.0, rear_hit = rear_turn != 0.0;
  if (front_hit || rear_hit) {
    escape_ = {};
    if (front_hit && !rear_hit) escape_.v_m_per_s = -o.backoff_speed_m_per_s;
    if (rear_hit && !front_hit) escape_.v_m_per_s = o.backoff_speed_m_per_s;
    // Front and rear at once: turn in place. A rear hit on the left is escaped by moving forward
    // and turning the same way as a front hit on the left (away from that side).
    escape_.omega_rad_per_s = front_hit ? front_turn : rear_turn;
    escape_left_s_ = o.backoff_duration_s;
    last_action_ = AvoidanceAction::kBumperEscape;
    return escape_;
  }
  if (escape_left_s_ > 1e-9) {  // tolerance: repeated subtraction of dt leaves rounding residue
    escape_left_s_ -= dt_s;
    last_action_ = AvoidanceAction::kBumperEscape;
    return escape_;
  }

  // 2. What the robot would drive: the navigation command or, ours, after a turn away, straight on
  // past the obstacle before turning back to it: straight on for straight_after_turn_s, then for
  // as long as something is still beside the robot on the obstacle's side (at most
  // bypass_limit_s) the navigation may not turn it towards that side.
  VelocityCommand drive = navigation;
  AvoidanceAction action = AvoidanceAction::kPassThrough;
  if (bypass_left_s_ > 1e-9) {
    straight_left_s_ -= dt_s;
    bypass_left_s_ -= dt_s;
    const bool beside = obstacle_beside(sensing.sonar);
    const bool turns_back = navigation.omega_rad_per_s * turn_sign_ < 0.0;
    if (straight_left_s_ > 1e-9 || (turns_back && beside)) {
      drive = {o.avoid_speed_m_per_s, 0.0};
      action = AvoidanceAction::kStraightOn;
    } else if (!beside) {
      bypass_left_s_ = 0.0;
    }
  }

  // 3. The closest sonar (to 1.0 m) or depth (to 0.6 m) obstacle ahead: within the field of view
  // (thesis) or in the path that `drive` sweeps (ours).
  double closest = std::numeric_limits<double>::infinity();
  double bearing = 0.0;
  const auto consider = [&](const std::vector<ObstacleRange>& readings, double max_range_m) {
    for (const ObstacleRange& r : readings) {
      if (!positive_finite(r.range_m) || !std::isfinite(r.bearing_rad)) continue;
      if (std::abs(r.bearing_rad) > o.field_of_view_half_rad) continue;
      if (o.path_half_width_m > 0.0) {
        const double from_centre_m = o.sensor_radius_m + r.range_m;
        const double x = from_centre_m * std::cos(r.bearing_rad);
        const double y = from_centre_m * std::sin(r.bearing_rad);
        if (!in_swept_path(x, y, drive, o.path_half_width_m)) continue;
      }
      if (r.range_m <= max_range_m && r.range_m < closest) {
        closest = r.range_m;
        bearing = r.bearing_rad;
      }
    }
  };
  consider(sensing.sonar, o.sonar_range_m);
  consider(sensing.depth, o.depth_range_m);
  if (!std::isfinite(closest)) {
    last_action_ = action;
    return drive;
  }
  if (o.straight_after_turn_s > 0.0) {
    straight_left_s_ = o.straight_after_turn_s;
    bypass_left_s_ = o.bypass_limit_s;
  }
  // Turn away: obstacle on the left (bearing > 0) -> clockwise; straight ahead or right -> left.
  // Ours, with the strip rule: a turn away keeps its side until the way is clear, so that noise in
  // which sonar is nearest cannot turn the robot to and fro in front of an obstacle dead ahead.
  const bool near = closest <= o.near_range_m;
  const double rate = near ? o.near_turn_rate_rad_per_s : o.far_turn_rate_rad_per_s;
  const bool turning = last_action_ == AvoidanceAction::kTurnAwayFar ||
                       last_action_ == AvoidanceAction::kTurnAwayNear ||
                       last_action_ == AvoidanceAction::kStraightOn;
  if (o.path_half_width_m <= 0.0 || !turning) turn_sign_ = bearing > 0.0 ? -1.0 : 1.0;
  VelocityCommand c;
  c.omega_rad_per_s = turn_sign_ * rate;
  c.v_m_per_s = near ? 0.0 : std::clamp(drive.v_m_per_s, 0.0, o.avoid_speed_m_per_s);
  last_action_ = near ? AvoidanceAction::kTurnAwayNear : AvoidanceAction::kTurnAwayFar;
  return c;
}

}  // namespace tessera
