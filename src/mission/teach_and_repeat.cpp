#include "tessera/mission/teach_and_repeat.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <utility>

#include "tessera/core/angle.hpp"
#include "tessera/eval/drift_correction.hpp"
#include "tessera/eval/heading_reversals.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/nav/cell_polyline.hpp"
#include "tessera/nav/greedy_cell_controller.hpp"
#include "tessera/nav/wavefront.hpp"
#include "tessera/sim/differential_drive.hpp"

namespace tessera {
namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

/// The view's score as a goal node: the coverage cells (8 x 6 over the image, as the matcher's
/// check) with features that have depth, then the features with depth. A node that covers the
/// image well is one the search can confirm (6.2 item 4). (-1, -1) when the view makes no node.
std::pair<int, int> goal_view_score(const fusion::NodeCreation& view) {
  if (!view.ok()) return {-1, -1};
  std::vector<std::uint8_t> covered(48, 0);
  for (const fusion::NodeFeature& f : view.node.features) {
    if (!f.has_depth) continue;
    const int cx = std::clamp(static_cast<int>(f.u_px * 8 / view.node.intrinsics.width_px), 0, 7);
    const int cy = std::clamp(static_cast<int>(f.v_px * 6 / view.node.intrinsics.height_px), 0, 5);
    covered[static_cast<std::size_t>(cy * 8 + cx)] = 1;
  }
  return {static_cast<int>(std::count(covered.begin(), covered.end(), 1)),
          view.features_with_depth};
}

// The sonar echoes that lie within reach_m of the taught path (map frame), seen from the robot's
// estimate: what stands now where the robot drove while teaching. Others read "no echo". An echo
// comes from somewhere on its cone's arc, not only from the axis: it counts only when the arc's
// middle and both ends lie within reach, so a wall beside the route seen at a cone's edge (near a
// goal between walls, where the axis point falls on the route) is not taken for something new.
ObstacleSensing new_on_route(ObstacleSensing sensing, const Pose2& T_map_robot,
                             const std::vector<Vec2>& taught_m, const P3dxBodyOptions& body,
                             double reach_m) {
  for (ObstacleRange& r : sensing.sonar) {
    if (!std::isfinite(r.range_m)) continue;
    const double along = body.sonar_radius_m + r.range_m;
    for (const double off : {0.0, -body.sonar_half_cone_rad, body.sonar_half_cone_rad}) {
      const double a = r.bearing_rad + off;
      const Vec2 p = T_map_robot * Vec2{along * std::cos(a), along * std::sin(a)};
      if (distance_to_polyline(p, taught_m) > reach_m) {
        r.range_m = std::numeric_limits<double>::infinity();
        break;
      }
    }
  }
  return sensing;
}

// Where a replanned path starts: of the cells within two cell spacings of the robot, the one
// nearest the goal by the wavefront (the nearest cell alone when none is that close). Starting
// from the nearest cell would send a robot that an obstacle has pushed beside its path back to
// the cell it has just passed.
std::size_t replan_start_cell(const CellGraph& graph, const WavefrontField& field, Vec2 p_m,
                              double cell_radius_m) {
  std::size_t best = graph.nearest(p_m);
  for (std::size_t i = 0; i < graph.size(); ++i) {
    if ((graph.centres_m[i] - p_m).norm() > 2.0 * cell_radius_m) continue;
    if (field.value[i] == kNoWavefrontValue) continue;
    if (field.value[best] == kNoWavefrontValue || field.value[i] > field.value[best]) best = i;
  }
  return best;
}

}  // namespace

std::optional<std::string> validate(const TeachAndRepeatOptions& o) {
  if (auto e = fusion::validate(o.slam)) return "slam: " + *e;
  if (auto e = validate(o.odometry)) return "odometry: " + *e;
  if (auto e = validate(o.follower)) return "follower: " + *e;
  if (!positive(o.clearance_m)) return std::string("clearance_m must be > 0");
  if (!positive(o.max_speed_m_per_s)) return std::string("max_speed_m_per_s must be > 0");
  if (!positive(o.max_turn_rate_rad_per_s))
    return std::string("max_turn_rate_rad_per_s must be > 0");
  if (!positive(o.control_period_s)) return std::string("control_period_s must be > 0");
  if (o.steps_per_update < 1) return std::string("steps_per_update must be >= 1");
  if (!std::isfinite(o.neck_pan_rad) || std::abs(o.neck_pan_rad) > std::numbers::pi / 2) {
    return std::string("neck_pan_rad must be within +-pi/2 (the thesis' 180-degree servo)");
  }
  if (o.capture_neck_angles_rad.empty()) return std::string("capture_neck_angles_rad is empty");
  for (double a : o.capture_neck_angles_rad) {
    if (!std::isfinite(a) || std::abs(a) > std::numbers::pi / 2) {
      return std::string("capture_neck_angles_rad must be within +-pi/2");
    }
  }
  if (!positive(o.search_tolerance_m)) return std::string("search_tolerance_m must be > 0");
  if (o.max_search_drives < 1) return std::string("max_search_drives must be >= 1");
  if (!positive(o.max_drive_s)) return std::string("max_drive_s must be > 0");
  if (!(o.frame_drop_probability >= 0.0 && o.frame_drop_probability < 1.0)) {
    return std::string("frame_drop_probability must be within [0, 1)");
  }
  if (o.obstacle_course) {
    const ObstacleCourseOptions& c = *o.obstacle_course;
    if (auto e = validate(c.body)) return "obstacle_course.body: " + *e;
    if (auto e = validate(c.avoidance)) return "obstacle_course.avoidance: " + *e;
    if (auto e = validate(c.sonar_grid)) return "obstacle_course.sonar_grid: " + *e;
    if (auto e = validate(c.detour)) return "obstacle_course.detour: " + *e;
    if (!positive(c.forget_memory_jump_m)) {
      return std::string("obstacle_course.forget_memory_jump_m must be > 0");
    }
    if (c.body.body_radius_m >= o.clearance_m) {
      return std::string("obstacle_course.body.body_radius_m must be < clearance_m");
    }
    if (c.obstacles < 0) return std::string("obstacle_course.obstacles must be >= 0");
    if (!positive(c.obstacle_side_m))
      return std::string("obstacle_course.obstacle_side_m must be > 0");
    if (!(std::isfinite(c.min_end_distance_m) && c.min_end_distance_m >= 0.0)) {
      return std::string("obstacle_course.min_end_distance_m must be >= 0");
    }
    if (!(std::isfinite(c.free_around_m) && c.free_around_m >= 0.0)) {
      return std::string("obstacle_course.free_around_m must be >= 0");
    }
    if (!(std::isfinite(c.stop_when_blocked_s) && c.stop_when_blocked_s >= 0.0)) {
      return std::string("obstacle_course.stop_when_blocked_s must be >= 0 (0: never)");
    }
  }
  return std::nullopt;
}

/// The simulation of one experiment: the true robot, its odometry, the SLAM and the camera.
class TeachAndRepeatSimulation {
 public:
  TeachAndRepeatSimulation(const RgbdCamera& camera, const TeachAndRepeatOptions& o,
                           const Pose2& start, std::uint64_t seed)
      : camera_(camera),
        o_(o),
        robot_(start, o.odometry, Rng(seed).fork(1)),
        frame_rng_(Rng(seed).fork(2)),
        slam_(o.slam),
        neck_(o.neck_pan_rad),
        sonar_rng_(Rng(seed).fork(4)),
        drop_rng_(Rng(seed).fork(5)) {
    if (o.obstacle_course) body_world_ = &camera.world();
    truth_.push_back({0.0, start});
    update();
  }

  fusion::FusionSlam& slam() { return slam_; }
  [[nodiscard]] const fusion::FusionSlam& slam() const { return slam_; }
  [[nodiscard]] const Pose2& truth() const { return robot_.true_pose(); }
  [[nodiscard]] Pose2 odometry() const { return robot_.odometry_pose(); }
  [[nodiscard]] double time_s() const { return t_s_; }
  [[nodiscard]] double path_m() const { return robot_.path_length_m(); }
  [[nodiscard]] const std::vector<StampedPose2>& truth_log() const { return truth_; }
  /// The true pose at an update's stamp (one truth sample per update period).
  [[nodiscard]] Pose2 truth_at(double t_s) const {
    const auto k =
        static_cast<std::size_t>(std::llround(t_s / (o_.control_period_s * o_.steps_per_update)));
    return truth_[std::min(k, truth_.size() - 1)].pose;
  }
  std::vector<Vec2>* estimate_path = nullptr;  // where estimates are recorded: one of these two
  std::vector<Vec2> taught_path;
  std::vector<Vec2> repeated_path;
  std::vector<Vec2> true_path;
  int corrections = 0;  // optimisations seen

  RgbdFrame render() { return camera_.render(robot_.true_pose(), neck_, t_s_, frame_rng_); }
  void set_neck(double neck_rad) { neck_ = neck_rad; }
  [[nodiscard]] double neck() const { return neck_; }

  /// One SLAM update at the current time, and a capture when the SLAM wants one.
  fusion::FusionUpdate update() {
    fusion::FusionUpdate u = slam_.update(t_s_, robot_.odometry_pose(), neck_);
    if (u.wants_frame) {
      const double driving_neck = neck_;
      for (double angle : o_.capture_neck_angles_rad) {
        if (o_.frame_drop_probability > 0.0 &&
            drop_rng_.uniform(0.0, 1.0) < o_.frame_drop_probability) {
          ++frames_dropped;
          continue;
        }
        neck_ = angle;
        const fusion::FusionCapture c = slam_.add_frame(render(), angle);
        if (c.optimised) ++corrections;
      }
      neck_ = driving_neck;
    }
    if (estimate_path) estimate_path->push_back({slam_.estimate().x, slam_.estimate().y});
    true_path.push_back({robot_.true_pose().x, robot_.true_pose().y});
    return u;
  }

  /// Drives one update period with the command; returns false when the time limit is hit.
  bool drive(double v, double w) {
    for (int k = 0; k < o_.steps_per_update; ++k) {
      if (body_world_ && !body_can_move(v, w)) {
        robot_.step(0.0, w, o_.control_period_s);  // the wheels stall; a disc can still turn
        ++blocked_steps;
        ++blocked_in_a_row_;
      } else {
        robot_.step(v, w, o_.control_period_s);
        blocked_in_a_row_ = 0;
      }
      ++steps_;
      t_s_ = static_cast<double>(steps_) * o_.control_period_s;
    }
    truth_.push_back({t_s_, robot_.true_pose()});
    update();
    return t_s_ - drive_start_s_ <= o_.max_drive_s;
  }

  void start_drive() { drive_start_s_ = t_s_; }

  /// The world the body meets (obstacle course only): the camera's while teaching, the one with
  /// the boxes while repeating. Must outlive this object.
  void set_body_world(const World* world) { body_world_ = world; }
  /// The sonars and bumpers now. Precondition: an obstacle course.
  [[nodiscard]] ObstacleSensing sense() {
    return sense_p3dx(*body_world_, robot_.true_pose(), o_.obstacle_course->body, sonar_rng_);
  }
  int blocked_steps = 0;   // control steps a contact stopped the body
  int frames_dropped = 0;  // frames lost (frame_drop_probability)
  /// How long a contact has stopped the wheels without a break, up to now.
  [[nodiscard]] double blocked_for_s() const { return blocked_in_a_row_ * o_.control_period_s; }

  /// Turn in place to `heading_rad` on `pose_of()`, then drive straight to `target` with a
  /// heading correction, braking to stop on it. The operator's (teach) or the navigation's
  /// (search) point-to-point motion. On the obstacle course a drive that a contact has stopped for
  /// stop_when_blocked_s ends where it is (Ok): the bumpers say the robot cannot get closer.
  template <typename PoseOf>
  Status go_to(Vec2 target, PoseOf pose_of, double tolerance_m) {
    const double stop_when_blocked_s =
        o_.obstacle_course ? o_.obstacle_course->stop_when_blocked_s : 0.0;
    start_drive();
    for (;;) {
      const Pose2 p = pose_of();
      const double dx = target.x - p.x, dy = target.y - p.y;
      const double dist = std::hypot(dx, dy);
      if (dist <= tolerance_m) return Ok{};
      const double err = normalize_angle(std::atan2(dy, dx) - p.theta);
      const double period = o_.control_period_s * o_.steps_per_update;
      const double speed =
          std::min({o_.max_speed_m_per_s, std::sqrt(2.0 * 0.3 * dist), dist / period});
      double v = 0.0, w = 0.0;
      if (dist < 0.1 && std::abs(err) > std::numbers::pi / 2) {
        // Just past the target: back onto it rather than turning round.
        const double err_back = normalize_angle(err - std::numbers::pi);
        if (std::abs(err_back) > 0.05) {
          w = std::clamp(2.0 * err_back, -o_.max_turn_rate_rad_per_s, o_.max_turn_rate_rad_per_s);
          if (std::abs(w * period) > std::abs(err_back)) w = err_back / period;
        } else {
          v = -speed;
        }
      } else if (std::abs(err) > 0.05) {
        w = std::clamp(2.0 * err, -o_.max_turn_rate_rad_per_s, o_.max_turn_rate_rad_per_s);
        if (std::abs(w * period) > std::abs(err)) w = err / period;
      } else {
        v = speed;
        w = std::clamp(1.5 * err, -o_.max_turn_rate_rad_per_s, o_.max_turn_rate_rad_per_s);
      }
      if (!drive(v, w)) return runtime_error("drive to a waypoint exceeded max_drive_s");
      if (stop_when_blocked_s > 0.0 && blocked_for_s() >= stop_when_blocked_s) return Ok{};
    }
  }

  template <typename PoseOf>
  Status turn_to(double heading_rad, PoseOf pose_of) {
    start_drive();
    for (;;) {
      const double err = normalize_angle(heading_rad - pose_of().theta);
      if (std::abs(err) < 0.01) return Ok{};
      const double period = o_.control_period_s * o_.steps_per_update;
      const double w =
          std::clamp(2.0 * err, -o_.max_turn_rate_rad_per_s, o_.max_turn_rate_rad_per_s);
      const double w_capped = std::abs(w * period) > std::abs(err) ? err / period : w;
      if (!drive(0.0, w_capped)) return runtime_error("turn exceeded max_drive_s");
    }
  }

 private:
  // Whether the body can drive (v, w) for one control period without going deeper into a contact.
  bool body_can_move(double v, double w) const {
    const Pose2& from = robot_.true_pose();
    const Pose2 to = from * arc_motion(v, w, o_.control_period_s);
    const Pose2 allowed =
        blocked_motion(*body_world_, from, to, o_.obstacle_course->body.body_radius_m);
    return allowed.x == to.x && allowed.y == to.y;
  }

  const RgbdCamera& camera_;
  TeachAndRepeatOptions o_;
  DifferentialDriveRobot robot_;
  Rng frame_rng_;
  fusion::FusionSlam slam_;
  double neck_ = 0.0;
  std::int64_t steps_ = 0;
  int blocked_in_a_row_ = 0;  // control steps, up to now
  double t_s_ = 0.0;
  double drive_start_s_ = 0.0;
  std::vector<StampedPose2> truth_;
  const World* body_world_ = nullptr;  // null: no body (no obstacle course)
  Rng sonar_rng_;
  Rng drop_rng_;
};

namespace {

// The obstacle course's state in the navigation loop.
struct CourseLoop {
  std::optional<ReactiveAvoidance> avoidance;  // empty: the robot drives blind
  std::optional<SonarGrid> memory;             // empty: no detours
  std::optional<double> detour_end_m;          // on a detour: where it rejoins the old path
  double since_detour_s = std::numeric_limits<double>::infinity();  // since the last detour
  std::vector<Vec2> taught_m;                  // the taught path (only_new_obstacles)
  bool bumped = false;                         // a bumper was pressed at the last update
  // Progress towards the goal: the path still ahead at best since the last detour (paths counts
  // them), and for how long it has not shortened. A robot that stops getting nearer is stuck.
  int paths = 0;
  int watched_path = -1;
  double best_remaining_m = 0.0;
  double stalled_s = 0.0;
  bool stuck = false;  // plan a way round what is remembered from where the robot stands
  // The estimate and the odometry at the last update: a correction's jump forgets the memory.
  std::optional<std::pair<Pose2, Pose2>> last_estimate_odometry;
};

// Forgets the sonar memory when the estimate has jumped (a correction) further than jump_m from
// where the odometry since the last update would have carried it.
void forget_after_jump(CourseLoop& loop, const Pose2& estimate, const Pose2& odometry,
                       double jump_m) {
  if (!loop.memory) return;
  if (loop.last_estimate_odometry) {
    const auto& [last_estimate, last_odometry] = *loop.last_estimate_odometry;
    const Pose2 predicted = last_estimate * (last_odometry.inverse() * odometry);
    if (std::hypot(estimate.x - predicted.x, estimate.y - predicted.y) > jump_m) {
      // The options are copied first: emplace ends the old grid before it builds the new one.
      loop.memory.emplace(SonarGridOptions{loop.memory->options()});
    }
  }
  loop.last_estimate_odometry = {estimate, odometry};
}

// True once the path ahead has not shortened by kAdvanceM in give_up_after_s (a new detour, which
// lengthens it on purpose, starts the watch again): the avoidance holds the robot, e.g. against a
// wall that a detour was planned through before the sonars saw it, or short of a box nearer than
// the blockage check looks.
bool stalled(CourseLoop& loop, const PathFollower& follower, double period_s,
             const DetourOptions& o) {
  constexpr double kAdvanceM = 0.1;
  const double remaining_m = polyline_length_m(follower.waypoints()) - follower.progress_m();
  if (loop.watched_path != loop.paths || remaining_m < loop.best_remaining_m - kAdvanceM) {
    loop.watched_path = loop.paths;
    loop.best_remaining_m = remaining_m;
    loop.stalled_s = 0.0;
    return false;
  }
  loop.stalled_s += period_s;
  if (loop.stalled_s < o.give_up_after_s) return false;
  loop.stalled_s = 0.0;
  loop.best_remaining_m = remaining_m;
  return true;
}

// True when any front or rear bumper is pressed.
bool any_bumper_pressed(const BumperState& b) {
  return std::ranges::any_of(b.front, std::identity{}) ||
         std::ranges::any_of(b.rear, std::identity{});
}

// Remembers this update's sonar sweep and, when a remembered obstacle new on the taught route
// blocks the follower's path ahead, replaces the path by a detour round it. A detour is kept until
// the robot is back on the old path unless something comes within the body's reach of it.
void plan_round_obstacles(const ObstacleSensing& sensing, const Pose2& T_map_robot,
                          const ObstacleCourseOptions& course, CourseLoop& loop,
                          std::optional<PathFollower>& follower,
                          const PathFollowerOptions& follower_options, double period_s,
                          TeachAndRepeatRun& run) {
  if (!loop.memory) return;
  loop.memory->insert(T_map_robot, sensing.sonar);
  loop.since_detour_s += period_s;
  if (!follower || follower->arrived()) return;
  const bool bumped = any_bumper_pressed(sensing.bumpers) || loop.stuck;
  loop.stuck = false;
  if (!bumped && loop.since_detour_s < course.detour.min_replan_interval_s) return;
  const std::vector<Vec2>& path = follower->waypoints();
  const double progress_m = follower->progress_m();
  if (loop.detour_end_m && progress_m >= *loop.detour_end_m) loop.detour_end_m.reset();
  std::optional<PathBlockage> blockage;
  if (loop.detour_end_m) {  // on a detour, up to where it rejoins: what the body would touch
    DetourOptions near = course.detour;
    near.block_radius_m = near.replan_radius_m;
    near.look_ahead_m = std::min(near.replan_look_ahead_m, *loop.detour_end_m - progress_m);
    blockage = find_blockage(path, progress_m, *loop.memory, near);
  } else {
    const auto on_route = [&](Vec2 c) {
      return loop.taught_m.empty() ||
             distance_to_polyline(c, loop.taught_m) <= course.body.body_radius_m;
    };
    blockage = find_blockage(path, progress_m, *loop.memory, course.detour, on_route);
    // Pushed off the path (by the avoidance) or against something: back to the path by a route
    // that keeps clear of everything remembered, not straight at it past a door post.
    if (!blockage && (bumped || follower->cross_track_m() > course.detour.off_path_m)) {
      blockage = PathBlockage{progress_m, progress_m};
    }
  }
  if (!blockage) return;
  std::optional<Detour> detour = plan_detour(path, {T_map_robot.x, T_map_robot.y}, *blockage,
                                             *loop.memory, course.detour, loop.taught_m);
  if (!detour) return;
  // The old detour's end, carried onto the new path (it rejoins the old one before that end).
  double end_m = detour->rejoin_m;
  if (loop.detour_end_m && *loop.detour_end_m > detour->rejoin_on_old_path_m) {
    end_m += *loop.detour_end_m - detour->rejoin_on_old_path_m;
  }
  loop.detour_end_m = end_m;
  loop.since_detour_s = 0.0;
  follower.emplace(std::move(detour->path), follower_options);
  ++loop.paths;
  ++run.detours;
}

// One navigation update on the obstacle course: counts bumper hits and lets the avoidance filter
// the navigation's command (thesis 4.3.4), hearing only what is new on the taught route when
// only_new_obstacles is set (decision 0028).
VelocityCommand on_course(TeachAndRepeatSimulation& x, ObstacleSensing sensing,
                          const ObstacleCourseOptions& course, CourseLoop& loop,
                          VelocityCommand cmd, double period_s, TeachAndRepeatRun& run) {
  const bool bump = any_bumper_pressed(sensing.bumpers);
  if (bump && !loop.bumped) ++run.bumper_hits;
  loop.bumped = bump;
  if (!loop.avoidance) return cmd;
  if (course.only_new_obstacles) {
    sensing = new_on_route(std::move(sensing), x.slam().estimate(), loop.taught_m, course.body,
                           course.body.body_radius_m);
  }
  cmd = loop.avoidance->filter(sensing, cmd, period_s);
  const AvoidanceAction a = loop.avoidance->last_action();
  if (a == AvoidanceAction::kTurnAwayFar || a == AvoidanceAction::kTurnAwayNear) {
    ++run.avoidance_updates;
  }
  return cmd;
}

}  // namespace

const char* describe(TeachAndRepeatStage stage) {
  switch (stage) {
    case TeachAndRepeatStage::kTeachToGoal:
      return "teach: driving to the goal";
    case TeachAndRepeatStage::kCaptureGoalNode:
      return "teach: capturing the goal node";
    case TeachAndRepeatStage::kTeachBack:
      return "teach: driving back to the start";
    case TeachAndRepeatStage::kConfirmStartNode:
      return "repeat: confirming a node of the start cell";
    case TeachAndRepeatStage::kNavigate:
      return "repeat: navigating to the goal cell";
    case TeachAndRepeatStage::kFindGoalNode:
      return "repeat: searching the goal node";
    case TeachAndRepeatStage::kDone:
      return "done";
  }
  return "?";
}

Result<TeachAndRepeat> TeachAndRepeat::create(const RgbdCamera& camera,
                                              const TeachAndRepeatOptions& options,
                                              const Pose2& start, Vec2 goal_m, std::uint64_t seed) {
  if (auto e = validate(options)) return input_error("teach and repeat: " + *e);
  Result<std::vector<Vec2>> route =
      plan_route(camera.world(), {start.x, start.y}, goal_m, options.clearance_m);
  if (!route) return route.error();
  std::optional<RouteObstacles> obstacles;
  if (const auto& course = options.obstacle_course; course && course->obstacles > 0) {
    Rng rng = Rng(seed).fork(3);
    Result<RouteObstacles> placed = place_route_obstacles(
        camera.world(), *route, course->obstacles, course->obstacle_side_m,
        course->min_end_distance_m, options.clearance_m, course->free_around_m, rng);
    if (!placed) return placed.error();
    obstacles = std::move(*placed);
  }
  return TeachAndRepeat(camera, options, std::move(*route), std::move(obstacles), start, goal_m,
                        seed);
}

TeachAndRepeat::TeachAndRepeat(const RgbdCamera& camera, const TeachAndRepeatOptions& options,
                               std::vector<Vec2> route, std::optional<RouteObstacles> obstacles,
                               const Pose2& start, Vec2 goal_m, std::uint64_t seed)
    : options_(options),
      sim_(std::make_unique<TeachAndRepeatSimulation>(camera, options, start, seed)) {
  if (obstacles) {
    run_.obstacles_m = std::move(obstacles->boxes_m);
    repeat_world_ = std::make_unique<World>(std::move(obstacles->world));
  }
  run_.seed = seed;
  run_.start = start;
  run_.goal_m = goal_m;
  run_.route_m = std::move(route);
  run_.taught_route_length_m = polyline_length_m(run_.route_m);
}

TeachAndRepeat::TeachAndRepeat(TeachAndRepeat&&) noexcept = default;
TeachAndRepeat& TeachAndRepeat::operator=(TeachAndRepeat&&) noexcept = default;
TeachAndRepeat::~TeachAndRepeat() = default;

const fusion::FusionSlam& TeachAndRepeat::slam() const { return sim_->slam(); }

Status TeachAndRepeat::step() {
  Status s = Ok{};
  switch (stage_) {
    case TeachAndRepeatStage::kTeachToGoal:
      s = teach_to_goal();
      break;
    case TeachAndRepeatStage::kCaptureGoalNode:
      s = capture_goal_node();
      break;
    case TeachAndRepeatStage::kTeachBack:
      s = teach_back();
      break;
    case TeachAndRepeatStage::kConfirmStartNode:
      s = confirm_start_node();
      break;
    case TeachAndRepeatStage::kNavigate:
      s = navigate();
      break;
    case TeachAndRepeatStage::kFindGoalNode:
      s = find_goal_node();
      break;
    case TeachAndRepeatStage::kDone:
      return Ok{};
  }
  if (!s) {
    stage_ = TeachAndRepeatStage::kDone;
    return s;
  }
  stage_ = static_cast<TeachAndRepeatStage>(static_cast<int>(stage_) + 1);
  return Ok{};
}

// TEACH, Table 5.1 steps 1-5: driven along the route to the goal.
Status TeachAndRepeat::teach_to_goal() {
  TeachAndRepeatSimulation& x = *sim_;
  x.estimate_path = &x.taught_path;
  auto truth = [&] { return x.truth(); };
  for (std::size_t i = 1; i < run_.route_m.size(); ++i) {
    if (Status s = x.go_to(run_.route_m[i], truth, 0.02); !s) return s;
  }
  return Ok{};
}

// Step 6: stopped in a firing field to acquire the goal image node: drive (by the map) into the
// current cell's firing field; the operator turns the robot round once and keeps the view that
// makes the best node (goal_view_score).
Status TeachAndRepeat::capture_goal_node() {
  TeachAndRepeatSimulation& x = *sim_;
  fusion::FusionSlam& slam = x.slam();
  auto truth = [&] { return x.truth(); };
  auto estimate = [&] { return slam.estimate(); };
  const Vec2 centre = slam.map().cell(slam.map().current_cell()).centre_m;
  if (Status s = x.go_to(centre, estimate, 0.03); !s) return s;
  const double heading0 = x.truth().theta;
  int best_k = -1;
  std::pair<int, int> best_score{-1, -1};
  for (int k = 0; k < 12; ++k) {
    if (Status s = x.turn_to(heading0 + k * std::numbers::pi / 6.0, truth); !s) return s;
    const fusion::NodeCreation view = fusion::create_image_node(x.render(), {}, options_.slam.node);
    if (!view.ok()) continue;
    const std::pair<int, int> score = goal_view_score(view);
    if (score > best_score) {
      best_score = score;
      best_k = k;
    }
  }
  if (best_k >= 0) {
    if (Status s = x.turn_to(heading0 + best_k * std::numbers::pi / 6.0, truth); !s) return s;
    const fusion::FusionCapture c = slam.add_frame(x.render());
    if (c.stored) {
      run_.goal_node = c.node_id;
      run_.goal_cell = slam.image_nodes()[c.node_id].cell;
      run_.taught_goal_pose = x.truth();
      return Ok{};
    }
  }
  return runtime_error(
      "teach and repeat: no view at the goal passes the image-node checks "
      "(no posters in sight?)");
}

// Step 7: driven back to the start in reverse order; there it turns to face the route again.
Status TeachAndRepeat::teach_back() {
  TeachAndRepeatSimulation& x = *sim_;
  auto truth = [&] { return x.truth(); };
  for (std::size_t i = run_.route_m.size() - 1; i-- > 0;) {
    if (Status s = x.go_to(run_.route_m[i], truth, 0.02); !s) return s;
  }
  if (Status s = x.turn_to(run_.start.theta, truth); !s) return s;
  run_.slam_after_teach = x.slam().statistics();
  teach_graph_nodes_ = x.slam().graph_nodes();
  return Ok{};
}

// REPEAT, step 8: the image-node search (thesis 4.3.4, 6.2 item 4): drive onto the node's pose by
// the estimate, turn the neck to its angle, confirm by matching; drive again while the match shows
// an offset beyond search_tolerance_m.
Status TeachAndRepeat::search(std::size_t node_id) {
  TeachAndRepeatSimulation& x = *sim_;
  fusion::FusionSlam& slam = x.slam();
  auto estimate = [&] { return slam.estimate(); };
  ++run_.search_trials;
  bool confirmed = false;
  TeachAndRepeatRun::Search record;
  record.node = node_id;
  record.odometry_error_m = std::hypot(x.odometry().x - x.truth().x, x.odometry().y - x.truth().y);
  for (int drive = 0; drive < options_.max_search_drives; ++drive) {
    const fusion::StoredImageNode& node = slam.image_nodes()[node_id];
    const Pose2 target = node.node.placement.T_map_robot;
    if (Status s = x.go_to({target.x, target.y}, estimate, 0.01); !s) return s;
    if (Status s = x.turn_to(target.theta, estimate); !s) return s;
    x.set_neck(node.node.placement.neck_rad);
    (void)x.drive(0.0, 0.0);  // one update at rest with the neck turned
    ++run_.search_captures;
    const fusion::NodeConfirmation c = slam.confirm_node(node_id, x.render());
    x.set_neck(options_.neck_pan_rad);
    ++record.captures;
    record.last_reason = c.reason;
    if (!c.confirmed) continue;
    record.offset_m = std::hypot(c.T_node_robot.x, c.T_node_robot.y);
    if (!confirmed) record.first_offset_m = record.offset_m;
    confirmed = true;
    if (record.offset_m <= options_.search_tolerance_m) break;
  }
  if (confirmed) ++run_.search_successes;
  record.confirmed = confirmed;
  const Pose2 node_truth = x.truth_at(slam.image_nodes()[node_id].node.t_s);
  record.true_offset_m = std::hypot(x.truth().x - node_truth.x, x.truth().y - node_truth.y);
  run_.searches.push_back(record);
  return Ok{};
}

// Step 8, first half: the image-node search in the start cell (6.2 item 4), for the stored node of
// the current cell with the most features with depth.
Status TeachAndRepeat::confirm_start_node() {
  TeachAndRepeatSimulation& x = *sim_;
  const fusion::FusionSlam& slam = x.slam();
  x.estimate_path = &x.repeated_path;
  if (repeat_world_) x.set_body_world(repeat_world_.get());  // the boxes are on the route now
  std::size_t best = 0;
  int best_features = -1;
  for (std::size_t id : slam.nodes_in_cell(slam.map().current_cell())) {
    const int f = slam.image_nodes()[id].node.features_with_depth();
    if (f > best_features) {
      best_features = f;
      best = id;
    }
  }
  if (best_features < 0) return Ok{};
  return search(best);
}

// Step 8: navigate to the goal cell: the wavefront over the learned cells as written (thesis
// 4.3.5), the non-zigzag polyline (6.2 item 3) and pure pursuit on the estimate, replanned from
// the current estimate after each correction; or, as the baseline, the thesis' re-decision at
// every border (nav/greedy_cell_controller). On an obstacle course the reactive avoidance (4.3.4)
// filters every command.
Status TeachAndRepeat::navigate() {
  TeachAndRepeatSimulation& x = *sim_;
  const fusion::FusionSlam& slam = x.slam();
  run_.start_cell = slam.map().current_cell();
  const double path_at_start = x.path_m();
  const double time_at_start = x.time_s();
  const int blocked_at_start = x.blocked_steps;
  const bool greedy = options_.navigation == RepeatNavigation::kThesisGreedy;
  const double period = options_.control_period_s * options_.steps_per_update;
  const double cell_radius_m = slam.map().options().cell_radius_m;
  std::optional<PathFollower> follower;
  std::optional<GreedyCellController> thesis;
  const std::optional<ObstacleCourseOptions>& course = options_.obstacle_course;
  CourseLoop course_loop;
  if (course && course->avoid) course_loop.avoidance.emplace(course->avoidance);
  if (course && course->detours && !greedy) {
    SonarGridOptions memory = course->sonar_grid;
    memory.sensor_radius_m = course->body.sonar_radius_m;
    course_loop.memory.emplace(memory);
  }
  HeadingReversalCounter reversals(0.1);
  reversals.add(x.truth().theta);
  bool planned = false;
  int seen_corrections = -1;  // plan at once
  CellPolylineOptions poly;
  poly.cell_radius_m = cell_radius_m;
  x.start_drive();
  for (;;) {
    // A detour is followed to its end: the path from the cells knows nothing of the boxes, and
    // replacing a detour by it at every correction turned the robot to and fro between them.
    if (seen_corrections != x.corrections && !course_loop.detour_end_m) {
      seen_corrections = x.corrections;
      // On an obstacle course the cells mapped going round a box join the taught ones only where
      // the robot crossed between them: plan over the lattice neighbours that are both mapped
      // (the clearance keeps walls out of them), from the cell ahead rather than the nearest.
      const CellGraph graph = slam.map().graph(course ? fusion::CellAdjacency::kGeometric
                                                      : fusion::CellAdjacency::kTraversed);
      const WavefrontField field = wavefront(graph, run_.goal_cell);
      const Pose2 p = slam.estimate();
      const std::size_t start = course ? replan_start_cell(graph, field, {p.x, p.y}, cell_radius_m)
                                       : graph.nearest({p.x, p.y});
      const std::vector<std::size_t> cell_path = wavefront_path(graph, field, start);
      if (cell_path.empty()) {
        return runtime_error("teach and repeat: the wavefront finds no path to the goal cell");
      }
      if (!planned) {
        run_.shortest_cell_path_m = cell_path_length_m(graph, cell_path);
        planned = true;
      }
      if (course && course->only_new_obstacles) {  // the taught path as the graph places it now
        course_loop.taught_m.clear();
        const std::vector<StampedPose2> nodes = slam.corrected_trajectory();
        for (std::size_t i = 0; i < std::min(teach_graph_nodes_, nodes.size()); ++i) {
          course_loop.taught_m.push_back({nodes[i].pose.x, nodes[i].pose.y});
        }
      }
      if (greedy) {
        thesis.emplace(graph, run_.goal_cell, GreedyCellControllerOptions{options_.follower});
      } else {
        const Vec2 centre_m = graph.centres_m[run_.goal_cell];
        // Ours, on the obstacle course: a cell's centre can lie nearer a wall than the body's
        // radius (the taught route keeps the clearance, the cells round it need not), where the
        // avoidance and the bumpers never let the robot arrive. The path ends instead at the
        // point of the taught route nearest the centre, which the robot has driven, when that
        // lies in the cell's inner half.
        Vec2 path_end_m = centre_m;
        if (course_loop.memory && !course_loop.taught_m.empty()) {
          const Vec2 q = nearest_on_polyline(centre_m, course_loop.taught_m);
          if ((q - centre_m).norm() <= 0.5 * cell_radius_m) path_end_m = q;
        }
        follower.emplace(cell_path_polyline(graph, cell_path, {p.x, p.y}, path_end_m, poly),
                         options_.follower);
        // A fresh path from the cells goes straight through what the sonars remember: check it
        // at once rather than after the replan interval.
        course_loop.since_detour_s = std::numeric_limits<double>::infinity();
      }
    }
    std::optional<ObstacleSensing> sensing;
    if (course_loop.memory) {
      forget_after_jump(course_loop, slam.estimate(), x.odometry(), course->forget_memory_jump_m);
      sensing = x.sense();
      plan_round_obstacles(*sensing, slam.estimate(), *course, course_loop, follower,
                           options_.follower, period, run_);
    }
    VelocityCommand cmd =
        greedy ? thesis->command(slam.estimate()) : follower->command(slam.estimate());
    if (greedy ? thesis->arrived() : follower->arrived()) break;
    if (course) {
      if (!sensing) sensing = x.sense();
      cmd = on_course(x, std::move(*sensing), *course, course_loop, cmd, period, run_);
      if (course_loop.memory && stalled(course_loop, *follower, period, course->detour)) {
        course_loop.detour_end_m.reset();
        course_loop.stuck = true;
        seen_corrections = -1;  // plan afresh from the cells at the next update
      }
    }
    if (!x.drive(cmd.v_m_per_s, cmd.omega_rad_per_s)) {
      return runtime_error("teach and repeat: navigation exceeded max_drive_s");
    }
    reversals.add(x.truth().theta);
  }
  run_.navigation_time_s = x.time_s() - time_at_start;
  run_.heading_reversals = reversals.reversals();
  run_.blocked_steps = x.blocked_steps - blocked_at_start;
  run_.navigation_path_m = x.path_m() - path_at_start;
  run_.path_ratio =
      run_.shortest_cell_path_m > 0.0 ? run_.navigation_path_m / run_.shortest_cell_path_m : 0.0;
  // Reached the goal cell: the robot's true position lies within the inscribed circle of the goal
  // cell as taught (the cell's centre carried from the goal node's estimated pose to its true
  // pose).
  const Pose2 node_est = slam.image_nodes()[run_.goal_node].node.placement.T_map_robot;
  const Vec2 c_in_node = node_est.inverse() * slam.map().cell(run_.goal_cell).centre_m;
  const Vec2 c_true = run_.taught_goal_pose * c_in_node;
  run_.goal_cell_distance_m = std::hypot(x.truth().x - c_true.x, x.truth().y - c_true.y);
  run_.reached_goal_cell = run_.goal_cell_distance_m <= 0.5 * slam.map().options().cell_radius_m;
  return Ok{};
}

// Step 8, second half: the image-node search for the goal node; step 9: the final figures.
Status TeachAndRepeat::find_goal_node() {
  if (Status s = search(run_.goal_node); !s) return s;
  finish();
  return Ok{};
}

void TeachAndRepeat::finish() {
  const TeachAndRepeatSimulation& x = *sim_;
  const fusion::FusionSlam& slam = x.slam();
  run_.final_pose = x.truth();
  run_.final_error_x_m = run_.final_pose.x - run_.taught_goal_pose.x;
  run_.final_error_y_m = run_.final_pose.y - run_.taught_goal_pose.y;
  run_.final_error_m = std::hypot(run_.final_error_x_m, run_.final_error_y_m);
  run_.final_heading_error_rad =
      normalize_angle(run_.final_pose.theta - run_.taught_goal_pose.theta);
  run_.odometry_error_at_goal_m =
      std::hypot(x.odometry().x - x.truth().x, x.odometry().y - x.truth().y);
  run_.estimate_error_at_goal_m =
      std::hypot(slam.estimate().x - x.truth().x, slam.estimate().y - x.truth().y);

  // Drift correction: the pose graph vs odometry alone, against the truth at the same stamps.
  run_.corrected_trajectory = slam.corrected_trajectory();
  std::unordered_map<std::int64_t, Pose2> truth_at;
  const double period = options_.control_period_s * options_.steps_per_update;
  for (const StampedPose2& p : x.truth_log()) truth_at[std::llround(p.t_s / period)] = p.pose;
  std::vector<StampedPose2> est, odo, ref;
  const std::vector<StampedPose2> odometry = slam.odometry_trajectory();
  for (std::size_t i = 0; i < run_.corrected_trajectory.size(); ++i) {
    const auto it = truth_at.find(std::llround(run_.corrected_trajectory[i].t_s / period));
    if (it == truth_at.end()) continue;
    // Unique, increasing stamps for the association (several graph nodes can share an update).
    const double t = static_cast<double>(i);
    est.push_back({t, run_.corrected_trajectory[i].pose});
    odo.push_back({t, odometry[i].pose});
    ref.push_back({t, it->second});
  }
  const Result<DriftCorrectionScore> score = score_drift_correction(est, odo, ref);
  run_.ate_corrected_m =
      score ? score->slam.trans_m.rmse : std::numeric_limits<double>::quiet_NaN();
  run_.ate_odometry_m =
      score ? score->odometry.trans_m.rmse : std::numeric_limits<double>::quiet_NaN();
  run_.ate_ratio = score ? score->odometry_over_slam() : 0.0;
  // Loop closures (thesis chapter 6: ambiguous images cause wrong ones): each match's claim
  // against the true motion between its stamps.
  const std::vector<Relation> claims = slam.match_relations();
  if (!claims.empty()) {
    if (const Result<RelationMetric> m = relation_metric(x.truth_log(), claims)) {
      run_.wrong_matches = static_cast<int>(relations_off_by_more_than(*m));
      for (const RelationError& e : m->errors) {
        run_.max_match_error_m = std::max(run_.max_match_error_m, e.trans_m);
      }
    }
  }
  run_.cells = slam.map().cell_count();
  run_.goal_cell_image_nodes = slam.nodes_in_cell(run_.goal_cell).size();
  run_.image_nodes = slam.image_nodes().size();
  run_.pose_nodes = slam.map().pose_nodes().size();
  run_.slam = slam.statistics();
  run_.duration_s = x.time_s();
  run_.frames_dropped = x.frames_dropped;
  run_.true_path_m = x.true_path;
  run_.taught_path_m = x.taught_path;
  run_.repeated_path_m = x.repeated_path;
}

TeachAndRepeatResult TeachAndRepeat::take_result() && {
  return TeachAndRepeatResult{std::move(run_), std::move(sim_->slam())};
}

Result<TeachAndRepeatResult> run_teach_and_repeat(
    const RgbdCamera& camera, const TeachAndRepeatOptions& options, const Pose2& start, Vec2 goal_m,
    std::uint64_t seed, const std::function<void(const std::string&)>& progress) {
  Result<TeachAndRepeat> mission = TeachAndRepeat::create(camera, options, start, goal_m, seed);
  if (!mission) return mission.error();
  while (!mission->done()) {
    if (progress) progress(describe(mission->stage()));
    if (Status s = mission->step(); !s) return s.error();
  }
  return std::move(*mission).take_result();
}

TeachAndRepeatSummary summarize(const std::vector<TeachAndRepeatRun>& runs) {
  TeachAndRepeatSummary s;
  s.runs = static_cast<int>(runs.size());
  s.min_ate_ratio = 1e300;
  for (const TeachAndRepeatRun& r : runs) {
    s.reached_goal_cell += r.reached_goal_cell ? 1 : 0;
    s.search_trials += r.search_trials;
    s.search_successes += r.search_successes;
    s.max_final_error_m = std::max(s.max_final_error_m, r.final_error_m);
    s.max_path_ratio = std::max(s.max_path_ratio, r.path_ratio);
    s.min_ate_ratio = std::min(s.min_ate_ratio, r.ate_ratio);
  }
  return s;
}

}  // namespace tessera
