#include "tessera/mission/teach_and_repeat.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <queue>
#include <unordered_map>
#include <utility>

#include "tessera/trajectory/stamped_pose3.hpp"
#include "tessera/eval/trajectory_error.hpp"
#include "tessera/nav/cell_polyline.hpp"
#include "tessera/nav/process_state_machine.hpp"
#include "tessera/nav/wavefront.hpp"
#include "tessera/sim/differential_drive.hpp"
#include "tessera/sim/tour.hpp"

namespace tessera {
namespace {

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

struct RoomSearch {
  std::vector<std::uint8_t> room;
  std::vector<double> dist_m;
  std::vector<std::int64_t> parent;
};

/// Dijkstra over the room cells from `start`, 8-connected without corner cutting.
RoomSearch search_room(const World& world, Cell start, std::vector<std::uint8_t> room) {
  const GridGeometry& g = world.geometry();
  RoomSearch s;
  s.room = std::move(room);
  s.dist_m.assign(g.size(), std::numeric_limits<double>::infinity());
  s.parent.assign(g.size(), -1);
  const double r = g.resolution_m();
  using Item = std::pair<double, std::size_t>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> open;
  const std::size_t s0 = g.index_of(start);
  s.dist_m[s0] = 0.0;
  open.emplace(0.0, s0);
  auto is_room = [&](Cell c) { return g.contains(c) && s.room[g.index_of(c)] != 0; };
  while (!open.empty()) {
    const auto [d, i] = open.top();
    open.pop();
    if (d > s.dist_m[i]) continue;
    const Cell c = g.cell_of(i);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const Cell n{c.x + dx, c.y + dy};
        if (!is_room(n)) continue;
        if (dx != 0 && dy != 0 && (!is_room({c.x + dx, c.y}) || !is_room({c.x, c.y + dy}))) continue;
        const double nd = d + ((dx != 0 && dy != 0) ? std::numbers::sqrt2 * r : r);
        const std::size_t ni = g.index_of(n);
        if (nd < s.dist_m[ni]) {
          s.dist_m[ni] = nd;
          s.parent[ni] = static_cast<std::int64_t>(i);
          open.emplace(nd, ni);
        }
      }
    }
  }
  return s;
}

/// True when the straight segment a-b stays in room cells (sampled every quarter cell).
bool segment_in_room(const World& world, const std::vector<std::uint8_t>& room, Vec2 a, Vec2 b) {
  const GridGeometry& g = world.geometry();
  const double len = std::hypot(b.x - a.x, b.y - a.y);
  const int n = std::max(1, static_cast<int>(std::ceil(len / (0.25 * g.resolution_m()))));
  for (int k = 0; k <= n; ++k) {
    const double u = static_cast<double>(k) / n;
    const std::optional<Cell> c = g.cell_at({a.x + u * (b.x - a.x), a.y + u * (b.y - a.y)});
    if (!c || room[g.index_of(*c)] == 0) return false;
  }
  return true;
}

std::vector<Vec2> string_pull(const World& world, const std::vector<std::uint8_t>& room,
                              const std::vector<Vec2>& path) {
  std::vector<Vec2> out;
  if (path.empty()) return out;
  std::size_t i = 0;
  out.push_back(path[0]);
  while (i + 1 < path.size()) {
    std::size_t j = i + 1;
    while (j + 1 < path.size() && segment_in_room(world, room, path[i], path[j + 1])) ++j;
    out.push_back(path[j]);
    i = j;
  }
  return out;
}

double ate_rmse(const std::vector<StampedPose2>& estimate, const std::vector<StampedPose2>& truth) {
  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(estimate, truth);
  return ate ? ate->trans_m.rmse : std::numeric_limits<double>::quiet_NaN();
}

}  // namespace

std::optional<std::string> validate(const TeachAndRepeatOptions& o) {
  if (auto e = fusion::validate(o.slam)) return "slam: " + *e;
  if (auto e = validate(o.odometry)) return "odometry: " + *e;
  if (auto e = validate(o.follower)) return "follower: " + *e;
  if (!positive(o.clearance_m)) return std::string("clearance_m must be > 0");
  if (!positive(o.max_speed_m_per_s)) return std::string("max_speed_m_per_s must be > 0");
  if (!positive(o.max_turn_rate_rad_per_s)) return std::string("max_turn_rate_rad_per_s must be > 0");
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
  return std::nullopt;
}

Result<std::vector<Vec2>> plan_route(const World& world, Vec2 from_m, Vec2 to_m,
                                     double clearance_m) {
  const GridGeometry& g = world.geometry();
  std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
  const std::optional<Cell> a = g.cell_at(from_m);
  const std::optional<Cell> b = g.cell_at(to_m);
  auto describe = [](Vec2 p) { return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")"; };
  if (!a || room[g.index_of(*a)] == 0) {
    return input_error("route: start " + describe(from_m) + " m is closer than clearance_m = " +
                       std::to_string(clearance_m) + " m to a wall or outside the map");
  }
  if (!b || room[g.index_of(*b)] == 0) {
    return input_error("route: goal " + describe(to_m) + " m is closer than clearance_m = " +
                       std::to_string(clearance_m) + " m to a wall or outside the map");
  }
  const RoomSearch s = search_room(world, *a, std::move(room));
  const std::size_t bi = g.index_of(*b);
  if (!std::isfinite(s.dist_m[bi])) {
    return input_error("route: no path from " + describe(from_m) + " to " + describe(to_m) +
                       " keeps clearance_m = " + std::to_string(clearance_m) + " m from walls");
  }
  std::vector<Vec2> path;
  for (std::int64_t i = static_cast<std::int64_t>(bi); i >= 0; i = s.parent[static_cast<std::size_t>(i)]) {
    path.push_back(g.center_of(g.cell_of(static_cast<std::size_t>(i))));
  }
  std::reverse(path.begin(), path.end());
  path.front() = from_m;
  path.back() = to_m;
  return string_pull(world, s.room, path);
}

Result<StartAndGoal> choose_start_and_goal(const World& world, double clearance_m,
                                           double route_length_m, Rng& rng) {
  const Result<Pose2> start = random_start_pose(world, clearance_m, rng);
  if (!start) return start.error();
  const GridGeometry& g = world.geometry();
  const Cell sc = g.cell_at_unchecked({start->x, start->y});
  const RoomSearch s = search_room(world, sc, room_for_robot(world, clearance_m));
  std::size_t best = g.index_of(sc);
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (!std::isfinite(s.dist_m[i])) continue;
    const double gap = std::abs(s.dist_m[i] - route_length_m);
    if (gap < best_gap) {
      best_gap = gap;
      best = i;
    }
  }
  StartAndGoal out;
  out.goal_m = g.center_of(g.cell_of(best));
  const Result<std::vector<Vec2>> route =
      plan_route(world, {start->x, start->y}, out.goal_m, clearance_m);
  if (!route) return route.error();
  if (route->size() < 2 || polyline_length_m(*route) < 1.0) {
    return input_error("start and goal: the robot's room around the start is too small for a route");
  }
  const Vec2 first = (*route)[1];
  out.start = {start->x, start->y, std::atan2(first.y - start->y, first.x - start->x)};
  out.route_length_m = polyline_length_m(*route);
  return out;
}

std::vector<Poster> place_poster_layers(const std::vector<WallFace>& faces,
                                        const std::vector<WallTexture>& textures,
                                        const PosterPlacementOptions& options, std::uint64_t seed,
                                        int layers) {
  std::vector<Poster> out;
  for (int layer = 0; layer < layers; ++layer) {
    for (const Poster& p : place_posters(faces, textures, options,
                                         seed + static_cast<std::uint64_t>(layer))) {
      const bool overlaps = std::any_of(out.begin(), out.end(), [&](const Poster& q) {
        return q.face == p.face && std::abs(q.center_m - p.center_m) <
                                       0.5 * (q.width_m + p.width_m) + options.margin_m;
      });
      if (!overlaps) out.push_back(p);
    }
  }
  return out;
}

namespace {

/// The simulation of one experiment: the true robot, its odometry, the SLAM and the camera.
class Experiment {
 public:
  Experiment(const RgbdCamera& camera, const TeachAndRepeatOptions& o, const Pose2& start,
             std::uint64_t seed)
      : camera_(camera),
        o_(o),
        robot_(start, o.odometry, Rng(seed).fork(1)),
        frame_rng_(Rng(seed).fork(2)),
        slam_(o.slam),
        neck_(o.neck_pan_rad) {
    truth_.push_back({0.0, start});
    update();
  }

  fusion::FusionSlam& slam() { return slam_; }
  [[nodiscard]] const Pose2& truth() const { return robot_.true_pose(); }
  [[nodiscard]] Pose2 odometry() const { return robot_.odometry_pose(); }
  [[nodiscard]] double time_s() const { return t_s_; }
  [[nodiscard]] double path_m() const { return robot_.path_length_m(); }
  [[nodiscard]] const std::vector<StampedPose2>& truth_log() const { return truth_; }
  /// The true pose at an update's stamp (one truth sample per update period).
  [[nodiscard]] Pose2 truth_at(double t_s) const {
    const auto k = static_cast<std::size_t>(
        std::llround(t_s / (o_.control_period_s * o_.steps_per_update)));
    return truth_[std::min(k, truth_.size() - 1)].pose;
  }
  std::vector<Vec2>* estimate_path = nullptr;  // where estimates are recorded
  std::vector<Vec2> true_path;
  int corrections = 0;  // optimisations seen

  RgbdFrame render() {
    return camera_.render(robot_.true_pose(), neck_, t_s_, frame_rng_);
  }
  void set_neck(double neck_rad) { neck_ = neck_rad; }
  [[nodiscard]] double neck() const { return neck_; }

  /// One SLAM update at the current time, and a capture when the SLAM wants one.
  fusion::FusionUpdate update() {
    fusion::FusionUpdate u = slam_.update(t_s_, robot_.odometry_pose(), neck_);
    if (u.wants_frame) {
      const double driving_neck = neck_;
      for (double angle : o_.capture_neck_angles_rad) {
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
      robot_.step(v, w, o_.control_period_s);
      ++steps_;
      t_s_ = static_cast<double>(steps_) * o_.control_period_s;
    }
    truth_.push_back({t_s_, robot_.true_pose()});
    update();
    return t_s_ - drive_start_s_ <= o_.max_drive_s;
  }

  void start_drive() { drive_start_s_ = t_s_; }

  /// Turn in place to `heading_rad` on `pose_of()`, then drive straight to `target` with a
  /// heading correction, braking to stop on it. The operator's (teach) or the navigation's
  /// (search) point-to-point motion.
  template <typename PoseOf>
  Status go_to(Vec2 target, PoseOf pose_of, double tolerance_m) {
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
    }
  }

  template <typename PoseOf>
  Status turn_to(double heading_rad, PoseOf pose_of) {
    start_drive();
    for (;;) {
      const double err = normalize_angle(heading_rad - pose_of().theta);
      if (std::abs(err) < 0.01) return Ok{};
      const double period = o_.control_period_s * o_.steps_per_update;
      const double w = std::clamp(2.0 * err, -o_.max_turn_rate_rad_per_s, o_.max_turn_rate_rad_per_s);
      const double w_capped = std::abs(w * period) > std::abs(err) ? err / period : w;
      if (!drive(0.0, w_capped)) return runtime_error("turn exceeded max_drive_s");
    }
  }

 private:
  const RgbdCamera& camera_;
  const TeachAndRepeatOptions& o_;
  DifferentialDriveRobot robot_;
  Rng frame_rng_;
  fusion::FusionSlam slam_;
  double neck_ = 0.0;
  std::int64_t steps_ = 0;
  double t_s_ = 0.0;
  double drive_start_s_ = 0.0;
  std::vector<StampedPose2> truth_;
};

}  // namespace

Result<TeachAndRepeatResult> run_teach_and_repeat(
    const RgbdCamera& camera, const TeachAndRepeatOptions& options, const Pose2& start,
    Vec2 goal_m, std::uint64_t seed, const std::function<void(const std::string&)>& progress) {
  if (auto e = validate(options)) return input_error("teach and repeat: " + *e);
  const Result<std::vector<Vec2>> route =
      plan_route(camera.world(), {start.x, start.y}, goal_m, options.clearance_m);
  if (!route) return route.error();
  auto say = [&](const std::string& text) {
    if (progress) progress(text);
  };

  TeachAndRepeatRun run;
  run.seed = seed;
  run.start = start;
  run.goal_m = goal_m;
  run.route_m = *route;
  run.taught_route_length_m = polyline_length_m(*route);

  Experiment x(camera, options, start, seed);
  fusion::FusionSlam& slam = x.slam();
  ProcessStateMachine process;  // thesis 4.3.4: LEARN while taught
  auto truth = [&] { return x.truth(); };
  auto estimate = [&] { return slam.estimate(); };

  // TEACH, Table 5.1 steps 1-6: driven along the route to the goal.
  say("teach: driving to the goal");
  x.estimate_path = &run.taught_path_m;
  for (std::size_t i = 1; i < route->size(); ++i) {
    if (Status s = x.go_to((*route)[i], truth, 0.02); !s) return s.error();
  }
  // Step 6: stopped in a firing field to acquire the goal image node: drive (by the map) into the
  // current cell's firing field and capture; turn by steps until the view makes a node.
  {
    const Vec2 centre = slam.map().cell(slam.map().current_cell()).centre_m;
    if (Status s = x.go_to(centre, estimate, 0.03); !s) return s.error();
    // The operator turns the robot round once and keeps the view that makes the best node: the
    // most coverage cells (8 x 6 over the image, as the matcher's check) with features that have
    // depth, then the most such features. A node that covers the image well is one the search
    // can confirm (6.2 item 4).
    const double heading0 = x.truth().theta;
    int best_k = -1;
    std::pair<int, int> best_score{-1, -1};
    for (int k = 0; k < 12; ++k) {
      if (Status s = x.turn_to(heading0 + k * std::numbers::pi / 6.0, truth); !s) return s.error();
      const fusion::NodeCreation view =
          fusion::create_image_node(x.render(), {}, options.slam.node);
      if (!view.ok()) continue;
      std::vector<std::uint8_t> covered(48, 0);
      for (const fusion::NodeFeature& f : view.node.features) {
        if (!f.has_depth) continue;
        const int cx = std::clamp(static_cast<int>(f.u_px * 8 / view.node.intrinsics.width_px), 0, 7);
        const int cy = std::clamp(static_cast<int>(f.v_px * 6 / view.node.intrinsics.height_px), 0, 5);
        covered[static_cast<std::size_t>(cy * 8 + cx)] = 1;
      }
      const std::pair<int, int> score{
          static_cast<int>(std::count(covered.begin(), covered.end(), 1)),
          view.features_with_depth};
      if (score > best_score) {
        best_score = score;
        best_k = k;
      }
    }
    bool stored = false;
    if (best_k >= 0) {
      if (Status s = x.turn_to(heading0 + best_k * std::numbers::pi / 6.0, truth); !s) {
        return s.error();
      }
      const fusion::FusionCapture c = slam.add_frame(x.render());
      if (c.stored) {
        stored = true;
        run.goal_node = c.node_id;
        run.goal_cell = slam.image_nodes()[c.node_id].cell;
        run.taught_goal_pose = x.truth();
      }
    }
    if (!stored) {
      return runtime_error("teach and repeat: no view at the goal passes the image-node checks "
                           "(no posters in sight?)");
    }
  }
  // Step 7: driven back to the start in reverse order; there it turns to face the route again.
  say("teach: driving back to the start");
  for (std::size_t i = route->size() - 1; i-- > 0;) {
    if (Status s = x.go_to((*route)[i], truth, 0.02); !s) return s.error();
  }
  if (Status s = x.turn_to(start.theta, truth); !s) return s.error();

  run.slam_after_teach = slam.statistics();
  // REPEAT, step 8: image-node search in the start cell, then navigate to the goal cell.
  x.estimate_path = &run.repeated_path_m;
  auto search = [&](std::size_t node_id) -> Status {
    ++run.search_trials;
    const std::size_t cell = slam.image_nodes()[node_id].cell;
    (void)process.handle(process_event::FindImageNode{
        node_id, slam.map().current_cell() == cell ||
                     std::hypot(slam.estimate().x - slam.map().cell(cell).centre_m.x,
                                slam.estimate().y - slam.map().cell(cell).centre_m.y) <
                         slam.map().options().cell_radius_m});
    bool confirmed = false;
    TeachAndRepeatRun::Search record;
    record.node = node_id;
    for (int drive = 0; drive < options.max_search_drives; ++drive) {
      const fusion::StoredImageNode& node = slam.image_nodes()[node_id];
      const Pose2 target = node.node.placement.T_map_robot;
      if (Status s = x.go_to({target.x, target.y}, estimate, 0.01); !s) return s;
      if (Status s = x.turn_to(target.theta, estimate); !s) return s;
      (void)process.handle(process_event::NodePoseReached{});
      x.set_neck(node.node.placement.neck_rad);
      (void)x.drive(0.0, 0.0);  // one update at rest with the neck turned
      (void)process.handle(process_event::NeckAligned{});
      ++run.search_captures;
      const fusion::NodeConfirmation c = slam.confirm_node(node_id, x.render());
      x.set_neck(options.neck_pan_rad);
      ++record.captures;
      record.last_reason = c.reason;
      if (!c.confirmed) continue;
      confirmed = true;
      record.offset_m = std::hypot(c.T_node_robot.x, c.T_node_robot.y);
      if (record.offset_m <= options.search_tolerance_m) break;
    }
    (void)process.handle(confirmed ? ProcessEvent{process_event::NodeConfirmed{}}
                                   : ProcessEvent{process_event::NodeNotConfirmed{}});
    if (confirmed) ++run.search_successes;
    record.confirmed = confirmed;
    const Pose2 node_truth = x.truth_at(slam.image_nodes()[node_id].node.t_s);
    record.true_offset_m = std::hypot(x.truth().x - node_truth.x, x.truth().y - node_truth.y);
    run.searches.push_back(record);
    return Ok{};
  };
  // The image-node search in the start cell (6.2 item 4): the stored node of the current cell with
  // the most features with depth.
  say("repeat: confirming a node of the start cell");
  {
    const std::vector<std::size_t> here = slam.nodes_in_cell(slam.map().current_cell());
    std::size_t best = 0;
    int best_features = -1;
    for (std::size_t id : here) {
      const int f = slam.image_nodes()[id].node.features_with_depth();
      if (f > best_features) {
        best_features = f;
        best = id;
      }
    }
    if (best_features >= 0) {
      if (Status s = search(best); !s) return s.error();
    }
  }

  say("repeat: navigating to the goal cell");
  run.start_cell = slam.map().current_cell();
  const double path_at_start = x.path_m();
  {
    (void)process.handle(process_event::GoToCell{run.goal_cell});
    bool planned = false;
    std::optional<PathFollower> follower;
    std::vector<std::size_t> cell_path;
    int seen_corrections = -1;
    CellPolylineOptions poly;
    poly.cell_radius_m = slam.map().options().cell_radius_m;
    x.start_drive();
    for (;;) {
      if (!follower || seen_corrections != x.corrections) {
        // (Re)plan over the learned cells from the current estimate: the wavefront as written
        // (thesis 4.3.5), then the non-zigzag polyline (6.2 item 3).
        seen_corrections = x.corrections;
        const CellGraph graph = slam.map().graph(fusion::CellAdjacency::kTraversed);
        const WavefrontField field = wavefront(graph, run.goal_cell);
        const Pose2 p = slam.estimate();
        const std::size_t here = graph.nearest({p.x, p.y});
        cell_path = wavefront_path(graph, field, here);
        if (cell_path.empty()) {
          (void)process.handle(process_event::NoPath{});
          return runtime_error("teach and repeat: the wavefront finds no path to the goal cell");
        }
        if (!planned) {
          run.shortest_cell_path_m = cell_path_length_m(graph, cell_path);
          planned = true;
        }
        follower.emplace(cell_path_polyline(graph, cell_path, {p.x, p.y},
                                            graph.centres_m[run.goal_cell], poly),
                         options.follower);
      }
      const VelocityCommand cmd = follower->command(slam.estimate());
      if (follower->arrived()) break;
      if (!x.drive(cmd.v_m_per_s, cmd.omega_rad_per_s)) {
        return runtime_error("teach and repeat: navigation exceeded max_drive_s");
      }
    }
    (void)process.handle(process_event::GoalCellReached{});
  }
  run.navigation_path_m = x.path_m() - path_at_start;
  run.path_ratio = run.shortest_cell_path_m > 0.0 ? run.navigation_path_m / run.shortest_cell_path_m
                                                  : 0.0;
  {
    // Reached the goal cell: the robot's true position lies within the inscribed circle of the
    // goal cell as taught (the cell's centre carried from the goal node's estimated pose to its
    // true pose).
    const Pose2 node_est = slam.image_nodes()[run.goal_node].node.placement.T_map_robot;
    const Vec2 c = slam.map().cell(run.goal_cell).centre_m;
    const Vec2 c_in_node = node_est.inverse() * c;
    const Vec2 c_true = run.taught_goal_pose * c_in_node;
    run.goal_cell_distance_m = std::hypot(x.truth().x - c_true.x, x.truth().y - c_true.y);
    run.reached_goal_cell = run.goal_cell_distance_m <= 0.5 * slam.map().options().cell_radius_m;
  }

  // Step 8, second half: the image-node search for the goal node.
  say("repeat: searching the goal node");
  if (Status s = search(run.goal_node); !s) return s.error();

  // Step 9: the final pose and the internal state.
  run.final_pose = x.truth();
  run.final_error_x_m = run.final_pose.x - run.taught_goal_pose.x;
  run.final_error_y_m = run.final_pose.y - run.taught_goal_pose.y;
  run.final_error_m = std::hypot(run.final_error_x_m, run.final_error_y_m);
  run.final_heading_error_rad = normalize_angle(run.final_pose.theta - run.taught_goal_pose.theta);
  run.odometry_error_at_goal_m =
      std::hypot(x.odometry().x - x.truth().x, x.odometry().y - x.truth().y);
  run.estimate_error_at_goal_m =
      std::hypot(slam.estimate().x - x.truth().x, slam.estimate().y - x.truth().y);

  // Drift correction: the pose graph vs odometry alone, against the truth at the same stamps.
  run.corrected_trajectory = slam.corrected_trajectory();
  {
    std::unordered_map<std::int64_t, Pose2> truth_at;
    const double period = options.control_period_s * options.steps_per_update;
    for (const StampedPose2& p : x.truth_log()) truth_at[std::llround(p.t_s / period)] = p.pose;
    std::vector<StampedPose2> est, odo, ref;
    const std::vector<StampedPose2> odometry = slam.odometry_trajectory();
    for (std::size_t i = 0; i < run.corrected_trajectory.size(); ++i) {
      const auto it = truth_at.find(std::llround(run.corrected_trajectory[i].t_s / period));
      if (it == truth_at.end()) continue;
      // Unique, increasing stamps for the association (several graph nodes can share an update).
      const double t = static_cast<double>(i);
      est.push_back({t, run.corrected_trajectory[i].pose});
      odo.push_back({t, odometry[i].pose});
      ref.push_back({t, it->second});
    }
    run.ate_corrected_m = ate_rmse(est, ref);
    run.ate_odometry_m = ate_rmse(odo, ref);
  }
  run.cells = slam.map().cell_count();
  run.image_nodes = slam.image_nodes().size();
  run.pose_nodes = slam.map().pose_nodes().size();
  run.slam = slam.statistics();
  run.duration_s = x.time_s();
  run.true_path_m = x.true_path;
  return TeachAndRepeatResult{std::move(run), std::move(slam)};
}

}  // namespace tessera
