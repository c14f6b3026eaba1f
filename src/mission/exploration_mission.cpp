#include "tessera/mission/exploration_mission.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tessera/eval/exploration_score.hpp"
#include "tessera/explore/frontier_set.hpp"
#include "tessera/explore/path_search.hpp"

namespace tessera {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxRobots = 64;
constexpr std::int64_t kSafetyStepsPerFreeCell = 50;
constexpr std::int64_t kMaxIdleBackoffSteps = 32;
constexpr std::uint8_t kMaxTargetChoices = 3;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// The free cell nearest the centroid of the largest 4-connected free component (ties: the first
/// component and the first cell in row-major order). Precondition: the world has a free cell.
Cell default_start(const World& world) {
  const GridGeometry& g = world.geometry();
  const World::FreeComponents components = world.free_components();
  const auto largest = std::max_element(components.sizes.begin(), components.sizes.end());
  TESSERA_ASSERT(largest != components.sizes.end());
  const auto best_label = static_cast<std::int32_t>(largest - components.sizes.begin());
  double sum_x = 0.0, sum_y = 0.0;  // sums of integers: exact
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (components.label[i] != best_label) continue;
    const Cell c = g.cell_of(i);
    sum_x += c.x;
    sum_y += c.y;
  }
  const double best_cx = sum_x / static_cast<double>(*largest);
  const double best_cy = sum_y / static_cast<double>(*largest);
  Cell best{};
  double best_d2 = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (components.label[i] != best_label) continue;
    const Cell c = g.cell_of(i);
    const double dx = c.x - best_cx, dy = c.y - best_cy;
    const double d2 = dx * dx + dy * dy;
    if (d2 < best_d2) {
      best_d2 = d2;
      best = c;
    }
  }
  return best;
}

}  // namespace

std::optional<std::string> validate(const ExplorationMissionOptions& o) {
  if (o.robots < 1 || o.robots > kMaxRobots) {
    return "robots must be in [1, " + std::to_string(kMaxRobots) + "], got " +
           std::to_string(o.robots);
  }
  if (!(o.low > 0.0 && o.low < 1.0)) return "low must be in (0, 1)";
  if (o.spread_radius_cells < 0) return "spread_radius_cells must be >= 0";
  if (o.max_steps < 0) return "max_steps must be >= 0 (0: no limit)";
  if (o.strategy != FrontierStrategy::kNearest && o.strategy != FrontierStrategy::kPriority) {
    return "strategy must be nearest or priority";
  }
  if (o.sensor == RobotKind::kCell) {
    const CellSensorOptions& c = o.cell_sensor;
    if (!(c.p_free > 0.0 && c.p_free < 1.0 && c.p_occupied > 0.0 && c.p_occupied < 1.0)) {
      return "cell_sensor probabilities must be in (0, 1)";
    }
    if (!(c.p_free < o.low)) return "cell_sensor.p_free must be below low, or no cell is ever open";
    if (!(c.p_occupied >= o.low)) return "cell_sensor.p_occupied must be >= low";
  } else if (o.sensor == RobotKind::kLidar) {
    if (auto p = validate(o.lidar)) return "lidar: " + *p;
    if (auto p = validate(o.scan_insert.model)) return "scan_insert.model: " + *p;
    if (!(o.scan_insert.free_margin_m >= 0.0)) return "scan_insert.free_margin_m must be >= 0";
    if (!(o.scan_insert.model.p_clamp_min < o.low)) {
      return "scan_insert.model.p_clamp_min must be below low, or no cell is ever open";
    }
    if (!(o.scan_insert.model.p_clamp_max >= o.low)) {
      return "scan_insert.model.p_clamp_max must be >= low";
    }
  } else {
    return "sensor must be cell or lidar";
  }
  return std::nullopt;
}

Result<std::vector<Cell>> exploration_starts(const World& world,
                                             const ExplorationMissionOptions& options) {
  if (world.free_count() == 0) return input_error("world has no free cell");
  Cell first{};
  if (options.start.has_value()) {
    first = *options.start;
    if (!world.geometry().contains(first)) {
      return input_error("start " + to_string(first) + " is outside the map");
    }
    if (world.solid(first)) {
      return input_error("start " + to_string(first) + " is inside an obstacle");
    }
  } else {
    first = default_start(world);
  }
  // Further robots: the next free cells in BFS order (N, E, S, W) from the first start.
  std::vector<Cell> starts{first};
  const auto wanted = static_cast<std::size_t>(std::max(options.robots, 1));
  const GridGeometry& g = world.geometry();
  std::vector<std::uint8_t> seen(g.size(), 0);
  seen[g.index_of(first)] = 1;
  std::vector<Cell> queue{first};
  for (std::size_t head = 0; head < queue.size() && starts.size() < wanted; ++head) {
    for (const Cell d : kNeighbors4) {
      const Cell n = queue[head] + d;
      if (world.solid(n) || seen[g.index_of(n)] != 0) continue;
      seen[g.index_of(n)] = 1;
      queue.push_back(n);
      if (starts.size() < wanted) starts.push_back(n);
    }
  }
  if (starts.size() < wanted) {
    return input_error("only " + std::to_string(starts.size()) + " free cells are reachable from " +
                       "start " + to_string(first) + ", too few for " +
                       std::to_string(options.robots) + " robots");
  }
  return starts;
}

ScanInsertOptions effective_scan_insert(const ExplorationMissionOptions& o) {
  ScanInsertOptions s = o.scan_insert;
  // Noise is truncated at 3 sigma in the simulator; a margin just above it keeps every wall cell.
  if (o.free_margin_from_noise) s.free_margin_m = 3.0 * o.lidar.range_noise_stddev_m + 1e-4;
  return s;
}

ExplorationMission::ExplorationMission(const GridGeometry& geometry,
                                       const ExplorationMissionOptions& options,
                                       std::vector<Cell> starts)
    : options_(options),
      scan_insert_(effective_scan_insert(options)),
      starts_(std::move(starts)),
      map_(geometry),
      frontier_(map_, options.low),
      explorer_(
          FrontierExplorerOptions{
              .strategy = options.strategy,
              .low = options.low,
              .spread_radius_cells = options.spread_radius_cells,
          },
          options.robots),
      low_log_odds_(log_odds(options.low)),
      stood_in_(geometry.size(), 0),
      times_chosen_(geometry.size(), 0),
      robots_(starts_.size()),
      paths_(starts_.size()) {
  TESSERA_ASSERT(!validate(options).has_value());
  TESSERA_ASSERT(starts_.size() == static_cast<std::size_t>(options.robots));
  for (std::size_t r = 0; r < starts_.size(); ++r) {
    TESSERA_ASSERT(geometry.contains(starts_[r]));
    robots_[r].cell = starts_[r];
  }
}

const ExplorationMission::RobotState& ExplorationMission::robot_at(int r) const {
  TESSERA_ASSERT(0 <= r && r < options_.robots);
  return robots_[static_cast<std::size_t>(r)];
}

ExplorationMission::RobotState& ExplorationMission::robot_at(int r) {
  TESSERA_ASSERT(0 <= r && r < options_.robots);
  return robots_[static_cast<std::size_t>(r)];
}

void ExplorationMission::apply_touched() {
  const GridGeometry& g = map_.geometry();
  // A cell a robot has stood in stays free (see stood_in_).
  const double stood_in_p = options_.sensor == RobotKind::kCell ? options_.cell_sensor.p_free
                                                                : scan_insert_.model.p_clamp_min;
  for (const Cell c : touched_) {
    if (stood_in_[g.index_of(c)] != 0 && !map_.is_free_below(c, low_log_odds_)) {
      map_.set_probability(c, stood_in_p);
    }
  }
  frontier_.update(map_, touched_);
  changed_.insert(changed_.end(), touched_.begin(), touched_.end());
}

// Algo 9.1 lines 10-12: sense, and mark the grid with occupancy probabilities.
void ExplorationMission::insert(const Pose2& T_map_robot, const ExplorationReading& reading) {
  touched_.clear();
  if (const CellReading* cells = std::get_if<CellReading>(&reading)) {
    TESSERA_ASSERT(options_.sensor == RobotKind::kCell);
    insert_cell_reading(map_, *cells, options_.cell_sensor, &touched_);
  } else {
    TESSERA_ASSERT(options_.sensor == RobotKind::kLidar);
    insert_scan(map_, T_map_robot, std::get<RangeScan>(reading), scan_insert_, &touched_);
  }
  apply_touched();
}

void ExplorationMission::sense(int robot, const Pose2& T_map_robot,
                               const ExplorationReading& reading) {
  TESSERA_ASSERT(step_ == 0);
  const RobotState& s = robot_at(robot);
  stood_in_[map_.geometry().index_of(s.cell)] = 1;
  paths_[static_cast<std::size_t>(robot)].push_back(T_map_robot);
  insert(T_map_robot, reading);
}

bool ExplorationMission::needs_plan(int r) const {
  const RobotState& s = robot_at(r);
  if (!s.plan.has_value()) return true;  // idle: cheap unless the map or the claims changed
  const Cell target = s.plan->target;
  if (s.cell == target) return true;
  if (!frontier_.contains(target) || explorer_.blacklisted(target)) return true;
  return !map_.is_free_below(s.plan->path[s.next], low_log_odds_);
}

void ExplorationMission::replan(int r) {
  RobotState& s = robot_at(r);
  const Cell here = s.cell;
  for (;;) {
    std::optional<FrontierPlan> p = explorer_.plan(map_, frontier_, r, here);
    // The robot has already sensed where it stands (at its start and after every move): a
    // frontier cell under it cannot be resolved by going there.
    if (p.has_value() && p->target == here) {
      explorer_.blacklist(here);
      continue;
    }
    // A noisy reading can flip a cell at a wall between free and occupied; each time it turns
    // free it is a frontier again (the wall behind it is never seen) and used to draw the robot
    // back. A cell chosen as a target more than kMaxTargetChoices times is given up on.
    if (p.has_value() &&
        ++times_chosen_[map_.geometry().index_of(p->target)] > kMaxTargetChoices) {
      explorer_.blacklist(p->target);
      continue;
    }
    s.plan = std::move(p);
    s.next = 1;
    if (s.plan.has_value()) {
      s.backoff_steps = 0;
    } else {
      s.backoff_steps = std::min<std::int64_t>(std::max<std::int64_t>(1, 2 * s.backoff_steps),
                                               kMaxIdleBackoffSteps);
      s.retry_step = step_ + s.backoff_steps;
    }
    return;
  }
}

/// Replans the robots that need it; true when some robot has a plan.
bool ExplorationMission::plan_all() {
  bool any_plan = false;
  for (int r = 0; r < options_.robots; ++r) {
    const RobotState& s = robot_at(r);
    const bool idle_waiting = !s.plan.has_value() && step_ < s.retry_step;
    if (!idle_waiting && needs_plan(r)) replan(r);
    any_plan = any_plan || s.plan.has_value();
  }
  if (any_plan) return true;
  // Before stopping, every robot looks again; FrontierExplorer answers at once for a robot whose
  // failed search saw the current map and claims.
  for (int r = 0; r < options_.robots; ++r) {
    replan(r);
    any_plan = any_plan || robot_at(r).plan.has_value();
  }
  return any_plan;
}

const std::vector<ExplorationMove>& ExplorationMission::decide() {
  moves_this_step_.clear();
  changed_.clear();
  if (finished()) return moves_this_step_;
  const Clock::time_point t_plan = Clock::now();
  const bool any_plan = plan_all();
  planning_time_s_ += seconds_since(t_plan);
  if (!any_plan) {
    stop_reason_ = kStopNoReachableFrontier;
  } else if (options_.max_steps > 0 && step_ >= options_.max_steps) {
    stop_reason_ = kStopStepLimit;
  }
  if (finished()) return moves_this_step_;
  for (int r = 0; r < options_.robots; ++r) {
    const RobotState& s = robot_at(r);
    if (s.plan.has_value()) moves_this_step_.push_back({r, s.plan->path[s.next]});
  }
  return moves_this_step_;
}

void ExplorationMission::moved(int robot, const Pose2& T_map_robot, double distance_m,
                               const ExplorationReading& reading) {
  RobotState& s = robot_at(robot);
  TESSERA_ASSERT(s.plan.has_value());
  const Cell from = s.cell;
  const Cell to = s.plan->path[s.next];
  ++s.next;
  s.cell = to;
  distance_m_ += distance_m;
  ++moves_;
  const Cell direction = to - from;
  if (s.last_step.has_value() && *s.last_step != direction) ++turns_;
  s.last_step = direction;
  paths_[static_cast<std::size_t>(robot)].push_back(T_map_robot);
  stood_in_[map_.geometry().index_of(to)] = 1;
  insert(T_map_robot, reading);
  if (to == s.plan->target && frontier_.contains(to)) explorer_.blacklist(to);
}

// A refused move: the robot bumped into the cell, which the map now holds as an obstacle.
void ExplorationMission::refused(int robot) {
  RobotState& s = robot_at(robot);
  TESSERA_ASSERT(s.plan.has_value());
  const Cell to = s.plan->path[s.next];
  ++refused_moves_;
  map_.set_probability(to, options_.sensor == RobotKind::kCell ? options_.cell_sensor.p_occupied
                                                               : scan_insert_.model.p_clamp_max);
  touched_.assign(1, to);
  apply_touched();
  s.plan.reset();
  explorer_.release(robot);
}

void ExplorationMission::end_step() {
  TESSERA_ASSERT(!finished());
  ++step_;
}

std::vector<Cell> ExplorationMission::unreachable_frontier() const {
  const GridGeometry& g = map_.geometry();
  FreeSpaceBfs bfs;
  std::vector<std::uint8_t> reached(g.size(), 0);
  for (const RobotState& s : robots_) {
    if (reached[g.index_of(s.cell)] != 0) continue;
    bfs.start(map_, s.cell, options_.low);
    while (const std::optional<Cell> v = bfs.next()) reached[g.index_of(*v)] = 1;
  }
  std::vector<Cell> out;
  for (const Cell c : frontier_.cells()) {
    if (reached[g.index_of(c)] == 0) out.push_back(c);
  }
  return out;
}

namespace {

ExplorationReading read_sensor(Simulator& sim, int robot, RobotKind kind) {
  if (kind == RobotKind::kCell) return sim.sense_cells(robot);
  return sim.scan(robot);
}

}  // namespace

Result<SimulatedExploration> start_exploration(const World& world,
                                               const ExplorationMissionOptions& options) {
  if (auto problem = validate(options)) return usage_error("exploration options: " + *problem);
  Result<std::vector<Cell>> starts = exploration_starts(world, options);
  if (!starts) return starts.error();
  ExplorationMissionOptions robot_side = options;
  if (robot_side.max_steps == 0) {
    robot_side.max_steps =
        kSafetyStepsPerFreeCell * static_cast<std::int64_t>(std::max<std::size_t>(
                                      world.free_count(), 1));
  }
  SimulatedExploration run{Simulator(world, options.seed),
                           ExplorationMission(world.geometry(), robot_side, *starts)};
  RobotSpec spec;
  spec.kind = options.sensor;
  spec.lidar = options.lidar;
  for (const Cell s : *starts) {
    if (Result<int> id = run.sim.add_robot(s, spec); !id) return id.error();
  }
  for (int r = 0; r < options.robots; ++r) {
    run.mission.sense(r, run.sim.pose(r), read_sensor(run.sim, r, options.sensor));
  }
  return run;
}

void step_exploration(SimulatedExploration& run) {
  const RobotKind kind = run.mission.options().sensor;
  for (const ExplorationMove& m : run.mission.decide()) {
    const MoveOutcome outcome = run.sim.move_to_adjacent(m.robot, m.to);
    if (outcome.moved) {
      run.mission.moved(m.robot, run.sim.pose(m.robot), outcome.distance_m,
                        read_sensor(run.sim, m.robot, kind));
    } else {
      run.mission.refused(m.robot);
    }
  }
  if (!run.mission.finished()) run.mission.end_step();
}

Result<ExplorationResult> run_exploration(
    const World& world, const ExplorationMissionOptions& options,
    const std::function<void(const ExplorationProgress&)>& progress,
    const std::function<void(const ExplorationMission&)>& on_step) {
  Result<SimulatedExploration> started = start_exploration(world, options);
  if (!started) return started.error();
  SimulatedExploration& run = *started;
  const ExplorationMission& mission = run.mission;
  // The truth's side: coverage of the reachable free cells after every step.
  ExplorationScorer scorer(world.reachable_from(mission.starts().front()), options.robots);
  const auto observe = [&] {
    scorer.observe(mission.steps(), mission.distance_m(), mission.map(), mission.changed_cells());
  };
  observe();
  if (on_step) on_step(mission);
  Clock::time_point last_progress = Clock::now();
  for (step_exploration(run); !mission.finished(); step_exploration(run)) {
    observe();
    if (on_step) on_step(mission);
    if (progress && Clock::now() - last_progress >= std::chrono::milliseconds(500)) {
      last_progress = Clock::now();
      progress(ExplorationProgress{mission.steps(), scorer.coverage(), mission.frontier().size()});
    }
  }
  if (on_step) on_step(mission);  // finished

  ExplorationResult out;
  out.metrics = scorer.finish(mission.steps(), mission.distance_m(), mission.moves(),
                              mission.turns(), mission.stop_reason());
  out.accuracy = compare_to_truth(mission.map(), TruthGrid(world.geometry(), world.solid_cells()));
  out.map = mission.map();
  out.paths = mission.paths();
  out.frontier_left = mission.frontier().cells();
  out.unreachable_frontier = mission.unreachable_frontier();
  out.blacklisted_targets = mission.blacklisted_targets();
  out.starts = mission.starts();
  out.free_cells = world.free_count();
  out.reachable_free_cells = scorer.reachable_cells();
  out.refused_moves = mission.refused_moves();
  out.planning_time_s = mission.planning_time_s();
  return out;
}

}  // namespace tessera
