#include "tessera/nav/greedy_cell_controller.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

#include "internal/heading_control.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {

GreedyCellController::GreedyCellController(CellGraph graph, std::size_t goal_cell,
                                           GreedyCellControllerOptions options)
    : graph_(std::move(graph)), options_(options) {
  TESSERA_ASSERT(goal_cell < graph_.size() && !validate(options_.motion) &&
                 options_.aligned_rad > 0.0);
  field_ = wavefront(graph_, goal_cell);
}

VelocityCommand GreedyCellController::command(const Pose2& T_map_robot) {
  if (arrived_) return {};
  const Vec2 p = T_map_robot.translation();
  const Vec2 goal_c = graph_.centres_m[field_.goal];
  const double to_goal = (goal_c - p).norm();
  // Thesis 4.3.5: the current cell is the closest one; head for its best neighbour.
  const std::size_t current = graph_.nearest(p);
  std::size_t target = wavefront_next(graph_, field_, current);
  if (current == field_.goal) {
    if (to_goal < options_.motion.goal_tolerance_m) {
      arrived_ = true;
      return {};
    }
    target = field_.goal;
  } else if (target == current) {
    stuck_ = true;
    return {};
  }
  stuck_ = false;
  if (!has_target_ || target != target_) {
    if (has_target_) ++target_changes_;
    target_ = target;
    has_target_ = true;
  }
  const PathFollowerOptions& m = options_.motion;
  const double speed = nav_internal::approach_speed(to_goal, m);
  const Vec2 target_c = graph_.centres_m[target_];
  if (!options_.turn_then_drive)
    return nav_internal::steer_towards(T_map_robot, target_c, speed, m);
  const Vec2 d = target_c - p;
  const double error = normalize_angle(std::atan2(d.y, d.x) - T_map_robot.theta);
  VelocityCommand c;
  if (std::abs(error) > options_.aligned_rad) {
    c.omega_rad_per_s = error > 0.0 ? m.max_turn_rate_rad_per_s : -m.max_turn_rate_rad_per_s;
    return c;  // face the cell first
  }
  c.v_m_per_s = speed;
  c.omega_rad_per_s = std::clamp(m.heading_gain_per_s * error, -m.max_turn_rate_rad_per_s,
                                 m.max_turn_rate_rad_per_s);
  return c;
}

}  // namespace tessera
