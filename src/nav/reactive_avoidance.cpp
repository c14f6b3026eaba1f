#include "tessera/nav/reactive_avoidance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

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
  }
  return "unknown";
}

ReactiveAvoidance::ReactiveAvoidance(ReactiveAvoidanceOptions options) : options_(options) {
  TESSERA_ASSERT(!validate(options_));
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

  // 2. The closest sonar (to 1.0 m) or depth (to 0.6 m) obstacle ahead.
  double closest = std::numeric_limits<double>::infinity();
  double bearing = 0.0;
  const auto consider = [&](const std::vector<ObstacleRange>& readings, double max_range_m) {
    for (const ObstacleRange& r : readings) {
      if (!positive_finite(r.range_m) || !std::isfinite(r.bearing_rad)) continue;
      if (std::abs(r.bearing_rad) > o.field_of_view_half_rad) continue;
      if (r.range_m <= max_range_m && r.range_m < closest) {
        closest = r.range_m;
        bearing = r.bearing_rad;
      }
    }
  };
  consider(sensing.sonar, o.sonar_range_m);
  consider(sensing.depth, o.depth_range_m);
  if (!std::isfinite(closest)) {
    last_action_ = AvoidanceAction::kPassThrough;
    return navigation;
  }
  // Turn away: obstacle on the left (bearing > 0) -> clockwise; straight ahead or right -> left.
  const bool near = closest <= o.near_range_m;
  const double rate = near ? o.near_turn_rate_rad_per_s : o.far_turn_rate_rad_per_s;
  VelocityCommand c;
  c.omega_rad_per_s = bearing > 0.0 ? -rate : rate;
  c.v_m_per_s = near ? 0.0 : std::clamp(navigation.v_m_per_s, 0.0, o.avoid_speed_m_per_s);
  last_action_ = near ? AvoidanceAction::kTurnAwayNear : AvoidanceAction::kTurnAwayFar;
  return c;
}

}  // namespace tessera
