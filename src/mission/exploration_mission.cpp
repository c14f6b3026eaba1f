#include "tessera/mission/exploration_mission.hpp"

#include <algorithm>
#include <chrono>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "tessera/eval/coverage.hpp"
#include "tessera/explore/frontier_set.hpp"
#include "tessera/explore/path_search.hpp"

namespace tessera {
namespace {

using Clock = std::chrono::steady_clock;

constexpr int kMaxRobots = 64;
constexpr std::int64_t kSafetyStepsPerFreeCell = 50;
constexpr std::int64_t kMaxIdleBackoffSteps = 32;
constexpr std::size_t kMaxSeriesSamples = 8192;
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

Result<ExplorationResult> run_exploration(
    const World& world, const ExplorationMissionOptions& o,
    const std::function<void(const ExplorationProgress&)>& progress) {
  if (auto problem = validate(o)) return usage_error("exploration options: " + *problem);
  Result<std::vector<Cell>> starts = exploration_starts(world, o);
  if (!starts) return starts.error();

  ExplorationResult out;
  out.starts = std::move(starts).value();
  out.free_cells = world.free_count();
  const GridGeometry& geometry = world.geometry();
  const int robot_count = o.robots;
  const auto robots_n = static_cast<std::size_t>(robot_count);

  Simulator sim(world, o.seed);
  RobotSpec spec;
  spec.kind = o.sensor;
  spec.lidar = o.lidar;
  for (const Cell s : out.starts) {
    if (Result<int> id = sim.add_robot(s, spec); !id) return id.error();
  }

  out.map = OccupancyGrid(geometry);
  OccupancyGrid& map = out.map;
  FrontierSet frontier(map, o.low);
  CoverageTracker coverage(world.reachable_from(out.starts.front()));
  out.reachable_free_cells = coverage.reachable_cells();
  FrontierExplorerOptions explorer_options;
  explorer_options.strategy = o.strategy;
  explorer_options.low = o.low;
  explorer_options.spread_radius_cells = o.spread_radius_cells;
  FrontierExplorer explorer(explorer_options, robot_count);
  const float low_log_odds = log_odds(o.low);

  std::vector<Cell> touched;
  // Cells a robot has stood in: free for certain (BOBMapping 3.1: "a cell the robot has stood in
  // can never become occupied"). A grazing lidar return can otherwise darken the one-cell passage a
  // robot came through and shut it in.
  std::vector<std::uint8_t> stood_in(geometry.size(), 0);
  const double stood_in_p =
      o.sensor == RobotKind::kCell ? o.cell_sensor.p_free : o.scan_insert.model.p_clamp_min;
  const auto keep_stood_in_cells_free = [&] {
    for (const Cell c : touched) {
      if (stood_in[geometry.index_of(c)] != 0 && !map.is_free_below(c, low_log_odds)) {
        map.set_probability(c, stood_in_p);
      }
    }
  };
  const auto apply_touched = [&] {
    keep_stood_in_cells_free();
    frontier.update(map, touched);
    coverage.update(map, touched);
  };
  // Algo 9.1 lines 10-12: sense, and mark the grid with occupancy probabilities.
  const auto sense = [&](int r) {
    stood_in[geometry.index_of(sim.cell(r))] = 1;
    touched.clear();
    if (o.sensor == RobotKind::kCell) {
      insert_cell_reading(map, sim.sense_cells(r), o.cell_sensor, &touched);
    } else {
      const RangeScan scan = sim.scan(r);
      insert_scan(map, sim.pose(r), scan, o.scan_insert, &touched);
    }
    apply_touched();
  };
  // A refused move: the robot bumped into the cell, which the map now holds as an obstacle.
  const auto bump = [&](Cell c) {
    map.set_probability(c, o.sensor == RobotKind::kCell ? o.cell_sensor.p_occupied
                                                        : o.scan_insert.model.p_clamp_max);
    touched.assign(1, c);
    apply_touched();
  };

  struct RobotState {
    std::optional<FrontierPlan> plan;
    std::size_t next = 1;           // index into plan->path of the next cell to enter
    std::optional<Cell> last_step;  // direction of the previous move, for counting turns
    // An idle robot (its last plan failed) retries at this step; the wait doubles with each failure
    // while other robots are busy, so idle robots do not search their whole free component every
    // step. When no robot has a plan, every idle robot retries at once (see the loop).
    std::int64_t retry_step = 0;
    std::int64_t backoff_steps = 0;
  };
  std::vector<RobotState> state(robots_n);
  out.paths.resize(robots_n);
  for (int r = 0; r < robot_count; ++r) {
    out.paths[static_cast<std::size_t>(r)].push_back(sim.pose(r));
    sense(r);
  }

  std::int64_t step = 0;
  std::vector<std::uint8_t> times_chosen(geometry.size(), 0);
  const auto needs_plan = [&](int r) {
    const RobotState& s = state[static_cast<std::size_t>(r)];
    if (!s.plan.has_value()) return true;  // idle: cheap unless the map or the claims changed
    const Cell target = s.plan->target;
    if (sim.cell(r) == target) return true;
    if (!frontier.contains(target) || explorer.blacklisted(target)) return true;
    return !map.is_free_below(s.plan->path[s.next], low_log_odds);
  };
  const auto replan = [&](int r) {
    RobotState& s = state[static_cast<std::size_t>(r)];
    const Cell here = sim.cell(r);
    for (;;) {
      std::optional<FrontierPlan> p = explorer.plan(map, frontier, r, here);
      // The robot has already sensed where it stands (at its start and after every move): a
      // frontier cell under it cannot be resolved by going there.
      if (p.has_value() && p->target == here) {
        explorer.blacklist(here);
        continue;
      }
      // A noisy reading can flip a cell at a wall between free and occupied; each time it turns
      // free it is a frontier again (the wall behind it is never seen) and used to draw the robot
      // back. A cell chosen as a target more than kMaxTargetChoices times is given up on.
      if (p.has_value() && ++times_chosen[geometry.index_of(p->target)] > kMaxTargetChoices) {
        explorer.blacklist(p->target);
        continue;
      }
      s.plan = std::move(p);
      s.next = 1;
      if (s.plan.has_value()) {
        s.backoff_steps = 0;
      } else {
        s.backoff_steps = std::min<std::int64_t>(std::max<std::int64_t>(1, 2 * s.backoff_steps),
                                                 kMaxIdleBackoffSteps);
        s.retry_step = step + s.backoff_steps;
      }
      return;
    }
  };

  ExplorationMetrics& m = out.metrics;
  m.robots = robot_count;
  double path_m = 0.0;
  add_sample(m, {0, 0.0, coverage.coverage()});
  std::int64_t series_stride = 1;
  const std::int64_t max_steps =
      o.max_steps > 0 ? o.max_steps
                      : kSafetyStepsPerFreeCell *
                            static_cast<std::int64_t>(std::max<std::size_t>(out.free_cells, 1));
  Clock::time_point last_progress = Clock::now();

  for (;;) {
    const Clock::time_point t_plan = Clock::now();
    bool any_plan = false;
    for (int r = 0; r < robot_count; ++r) {
      const RobotState& s = state[static_cast<std::size_t>(r)];
      const bool idle_waiting = !s.plan.has_value() && step < s.retry_step;
      if (!idle_waiting && needs_plan(r)) replan(r);
      any_plan = any_plan || s.plan.has_value();
    }
    if (!any_plan) {
      // Before stopping, every robot looks again; FrontierExplorer answers at once for a robot
      // whose failed search saw the current map and claims.
      for (int r = 0; r < robot_count; ++r) {
        replan(r);
        any_plan = any_plan || state[static_cast<std::size_t>(r)].plan.has_value();
      }
    }
    out.planning_time_s += seconds_since(t_plan);
    if (!any_plan) {
      m.stop_reason = kStopNoReachableFrontier;
      break;
    }
    if (step >= max_steps) {
      m.stop_reason = kStopStepLimit;
      break;
    }

    for (int r = 0; r < robot_count; ++r) {
      RobotState& s = state[static_cast<std::size_t>(r)];
      if (!s.plan.has_value()) continue;
      const Cell from = sim.cell(r);
      const Cell to = s.plan->path[s.next];
      const MoveOutcome moved = sim.move_to_adjacent(r, to);
      if (!moved.moved) {
        ++out.refused_moves;
        bump(to);
        s.plan.reset();
        explorer.release(r);
        continue;
      }
      ++s.next;
      path_m += moved.distance_m;
      ++m.path_length_cells;
      const Cell direction = to - from;
      if (s.last_step.has_value() && *s.last_step != direction) ++m.turns;
      s.last_step = direction;
      out.paths[static_cast<std::size_t>(r)].push_back(sim.pose(r));
      sense(r);
      if (to == s.plan->target && frontier.contains(to)) explorer.blacklist(to);
    }
    ++step;
    const CoverageSample sample{step, path_m, coverage.coverage()};
    record_milestones(m, sample);
    if (step % series_stride == 0) {
      m.coverage_over_time.push_back(sample);
      if (m.coverage_over_time.size() > kMaxSeriesSamples) {
        // Keep the samples on multiples of twice the stride (step 0 included).
        series_stride *= 2;
        std::erase_if(m.coverage_over_time,
                      [&](const CoverageSample& x) { return x.step % series_stride != 0; });
      }
    }
    if (progress) {
      const Clock::time_point now = Clock::now();
      if (now - last_progress >= std::chrono::milliseconds(500)) {
        last_progress = now;
        progress(ExplorationProgress{step, coverage.coverage(), frontier.size()});
      }
    }
  }

  m.steps = step;
  m.path_length_m = path_m;
  if (m.coverage_over_time.back().step != step) {
    m.coverage_over_time.push_back({step, path_m, coverage.coverage()});
  }
  out.accuracy = compare_to_truth(map, TruthGrid(world.geometry(), world.solid_cells()));
  out.frontier_left = frontier.cells();
  out.blacklisted_targets = explorer.blacklisted_cells();
  // Frontier cells no robot can reach through known free cells. One full search per connected group
  // of robots.
  FreeSpaceBfs bfs;
  std::vector<std::uint8_t> reached(geometry.size(), 0);
  for (int r = 0; r < robot_count; ++r) {
    const Cell c = sim.cell(r);
    if (reached[geometry.index_of(c)] != 0) continue;
    bfs.start(map, c, o.low);
    while (const std::optional<Cell> v = bfs.next()) reached[geometry.index_of(*v)] = 1;
  }
  for (const Cell c : out.frontier_left) {
    if (reached[geometry.index_of(c)] == 0) out.unreachable_frontier.push_back(c);
  }
  return out;
}

}  // namespace tessera
