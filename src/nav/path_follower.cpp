#include "tessera/nav/path_follower.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "internal/heading_control.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

// Segments ahead of the current one searched for the robot's projection: enough to skip short
// segments, few enough that a path folding back on itself is not short-cut.
constexpr std::size_t kProjectionWindow = 3;

}  // namespace

std::optional<std::string> validate(const PathFollowerOptions& o) {
  if (!positive_finite(o.max_speed_m_per_s)) return "max_speed_m_per_s must be > 0";
  if (!positive_finite(o.max_turn_rate_rad_per_s)) return "max_turn_rate_rad_per_s must be > 0";
  if (!positive_finite(o.heading_gain_per_s)) return "heading_gain_per_s must be > 0";
  if (!positive_finite(o.turn_in_place_rad)) return "turn_in_place_rad must be > 0";
  if (!positive_finite(o.lookahead_m)) return "lookahead_m must be > 0";
  if (!positive_finite(o.goal_tolerance_m)) return "goal_tolerance_m must be > 0";
  if (!positive_finite(o.slow_down_m)) return "slow_down_m must be > 0";
  if (!(o.min_speed_fraction > 0.0 && o.min_speed_fraction <= 1.0)) {
    return "min_speed_fraction must be in (0, 1]";
  }
  return std::nullopt;
}

PathFollower::PathFollower(std::vector<Vec2> waypoints_m, PathFollowerOptions options)
    : waypoints_(std::move(waypoints_m)), options_(options) {
  TESSERA_ASSERT(!waypoints_.empty() && !validate(options_));
  arc_m_.assign(waypoints_.size(), 0.0);
  for (std::size_t i = 1; i < waypoints_.size(); ++i) {
    arc_m_[i] = arc_m_[i - 1] + (waypoints_[i] - waypoints_[i - 1]).norm();
  }
}

Vec2 PathFollower::point_at(double s_m) const {
  if (s_m >= arc_m_.back()) return waypoints_.back();
  std::size_t i = segment_;
  while (i + 1 < waypoints_.size() && arc_m_[i + 1] < s_m) ++i;
  if (i + 1 >= waypoints_.size()) return waypoints_.back();
  const double len = arc_m_[i + 1] - arc_m_[i];
  if (len <= 0.0) return waypoints_[i + 1];
  return waypoints_[i] + (waypoints_[i + 1] - waypoints_[i]) * ((s_m - arc_m_[i]) / len);
}

VelocityCommand PathFollower::command(const Pose2& T_map_robot) {
  if (arrived_) return {};
  const Vec2 p = T_map_robot.translation();
  const double to_goal = (waypoints_.back() - p).norm();
  if (to_goal < options_.goal_tolerance_m) {
    arrived_ = true;
    cross_track_m_ = 0.0;
    return {};
  }
  if (waypoints_.size() > 1) {
    // Project onto the segments from the current one on; keep the nearest projection and move
    // the progress forward only.
    double best_d = std::numeric_limits<double>::infinity();
    double best_s = progress_m_;
    std::size_t best_seg = segment_;
    const std::size_t last = std::min(waypoints_.size() - 1, segment_ + kProjectionWindow);
    for (std::size_t i = segment_; i < last; ++i) {
      const Vec2 a = waypoints_[i], ab = waypoints_[i + 1] - a;
      const double len2 = ab.dot(ab);
      const double t = len2 > 0.0 ? std::clamp((p - a).dot(ab) / len2, 0.0, 1.0) : 0.0;
      const double d = (p - (a + ab * t)).norm();
      if (d < best_d) {
        best_d = d;
        best_s = arc_m_[i] + t * std::sqrt(len2);
        best_seg = i;
      }
    }
    cross_track_m_ = best_d;
    if (best_s > progress_m_) {
      progress_m_ = best_s;
      segment_ = best_seg;
    }
  } else {
    cross_track_m_ = to_goal;
  }
  const Vec2 target = point_at(progress_m_ + options_.lookahead_m);
  return nav_internal::steer_towards(T_map_robot, target,
                                     nav_internal::approach_speed(to_goal, options_), options_);
}

}  // namespace tessera
