// Frontier maintenance and whole explorations on the largest shared floor plan (nav2 warehouse,
// 1006 x 1674 cells at 0.03 m).
//
//   FrontierUpdate/Incremental  FrontierSet::update with the cells one lidar step touched
//   FrontierUpdate/Full         compute_frontier over the whole map (Algo 9.1 as written)
//   FrontierUpdate/WholeRun     both, averaged over every step of a lidar exploration's first
//                               3000 steps at full resolution (the figure docs/ records)
//   Explore/Warehouse           a whole exploration: lidar robot(s), nearest frontier, 0.1 m cells
//
// "steps" is how far into a lidar exploration (full resolution, 8 m range) the measured step is:
// 1 is the second scan of the run, which still reveals most of its disc (atypical); 20 and 300
// are ordinary steps. The requirement: incremental >= 20x faster than full per ordinary step
// (counter "speedup_vs_full", wall time of both measured in the same process).
// The data folder is TESSERA_DATA_DIR, default ../shared/data beside the project.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "tessera/explore/frontier.hpp"
#include "tessera/explore/frontier_set.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/mission/exploration_mission.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/simulator.hpp"
#include "tessera/sim/world.hpp"
#include "tessera/io/data_dir.hpp"

namespace tessera {
namespace {

const std::filesystem::path kWarehouse = "maps/ros_map_server/nav2_warehouse/warehouse.yaml";

/// The warehouse as ground truth at its own resolution; nullopt (with the reason) if it is missing.
const std::optional<World>& warehouse(std::string* why_not) {
  static std::string error;
  static const std::optional<World> world = []() -> std::optional<World> {
    Result<LoadedMap> loaded = load_map(data_dir() / kWarehouse);
    if (!loaded) {
      error = loaded.error().message;
      return std::nullopt;
    }
    return World::from_map(loaded->map, 0.5, "warehouse");
  }();
  if (!world && why_not != nullptr) *why_not = error;
  return world;
}

ExplorationMissionOptions lidar_nearest(int robots) {
  ExplorationMissionOptions o;
  o.strategy = FrontierStrategy::kNearest;
  o.sensor = RobotKind::kLidar;
  o.robots = robots;
  o.seed = 1;
  return o;
}

/// A realistic step of a lidar exploration on the full-resolution warehouse: the map after
/// `steps_before` exploration steps (before), the map after one more move and scan (after), and the
/// cells that scan touched.
struct StepFixture {
  OccupancyGrid before;
  OccupancyGrid after;
  std::vector<Cell> touched;
};

std::optional<StepFixture> make_step(const World& world, std::int64_t steps_before) {
  ExplorationMissionOptions o = lidar_nearest(1);
  o.max_steps = steps_before;
  Result<ExplorationResult> run = run_exploration(world, o);
  if (!run) return std::nullopt;
  StepFixture f{run->map, run->map, {}};
  // One more step: move to a free neighbour (the robot's next cell is as good as any) and scan.
  const Pose2 last = run->paths.front().back();
  const Cell here = world.geometry().cell_at_unchecked(last.translation());
  Simulator sim(world, 99);
  if (!sim.add_robot(here, RobotSpec{RobotKind::kLidar, o.lidar})) return std::nullopt;
  for (const Cell d : kNeighbors4) {
    if (sim.move_to_adjacent(0, here + d).moved) break;
  }
  insert_scan(f.after, sim.pose(0), sim.scan(0), o.scan_insert, &f.touched);
  return f;
}

const StepFixture* step_fixture(benchmark::State& state) {
  std::string why;
  const std::optional<World>& world = warehouse(&why);
  if (!world) {
    state.SkipWithError(("warehouse map: " + why + " (set TESSERA_DATA_DIR)").c_str());
    return nullptr;
  }
  static std::map<std::int64_t, std::optional<StepFixture>> fixtures;  // by steps_before
  auto it = fixtures.find(state.range(0));
  if (it == fixtures.end())
    it = fixtures.emplace(state.range(0), make_step(*world, state.range(0))).first;
  const std::optional<StepFixture>& fixture = it->second;
  if (!fixture) {
    state.SkipWithError("could not set up the exploration step");
    return nullptr;
  }
  return &*fixture;
}

double seconds_per_full_recompute(const OccupancyGrid& map) {
  constexpr int kRuns = 5;
  const auto t0 = std::chrono::steady_clock::now();
  std::size_t n = 0;
  for (int i = 0; i < kRuns; ++i) n += compute_frontier(map).size();
  benchmark::DoNotOptimize(n);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() / kRuns;
}

// Each iteration applies the step forwards and backwards (the same cells change back), so both
// directions are real updates; the time per update is half an iteration.
void BM_FrontierUpdateIncremental(benchmark::State& state) {
  const StepFixture* f = step_fixture(state);
  if (f == nullptr) return;
  FrontierSet set(f->before);
  const std::size_t frontier_before = set.size();
  const auto t0 = std::chrono::steady_clock::now();
  for (auto _ : state) {
    set.update(f->after, f->touched);
    set.update(f->before, f->touched);
    benchmark::DoNotOptimize(set.size());
  }
  const double per_update_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() /
      (2.0 * static_cast<double>(state.iterations()));
  state.SetItemsProcessed(2 * state.iterations());
  state.counters["cells"] = static_cast<double>(f->before.geometry().size());
  state.counters["touched"] = static_cast<double>(f->touched.size());
  state.counters["frontier"] = static_cast<double>(frontier_before);
  state.counters["us_per_update"] = per_update_s * 1e6;
  state.counters["speedup_vs_full"] = seconds_per_full_recompute(f->after) / per_update_s;
}
BENCHMARK(BM_FrontierUpdateIncremental)
    ->Name("FrontierUpdate/Incremental")
    ->ArgName("steps")
    ->Arg(1)
    ->Arg(20)
    ->Arg(300)
    ->Unit(benchmark::kMicrosecond);

void BM_FrontierUpdateFull(benchmark::State& state) {
  const StepFixture* f = step_fixture(state);
  if (f == nullptr) return;
  for (auto _ : state) {
    std::vector<Cell> frontier = compute_frontier(f->after);
    benchmark::DoNotOptimize(frontier.data());
  }
  state.counters["cells"] = static_cast<double>(f->after.geometry().size());
}
BENCHMARK(BM_FrontierUpdateFull)
    ->Name("FrontierUpdate/Full")
    ->ArgName("steps")
    ->Arg(1)
    ->Arg(20)
    ->Arg(300)
    ->Unit(benchmark::kMicrosecond);

// Every step of a whole exploration, not a chosen one: a lidar robot's path over the
// full-resolution warehouse is replayed scan by scan, and each step's touched cells go through
// FrontierSet::update (timed at every step) while compute_frontier is timed on the same map every
// 25th step. The counters are the mean per step of each, over the same run.
void BM_FrontierUpdateWholeRun(benchmark::State& state) {
  std::string why;
  const std::optional<World>& world = warehouse(&why);
  if (!world) {
    state.SkipWithError(("warehouse map: " + why + " (set TESSERA_DATA_DIR)").c_str());
    return;
  }
  ExplorationMissionOptions o = lidar_nearest(1);
  o.max_steps = state.range(0);
  Result<ExplorationResult> run = run_exploration(*world, o);
  if (!run) {
    state.SkipWithError(run.error().message.c_str());
    return;
  }
  const std::vector<Pose2>& path = run->paths.front();
  using Clock = std::chrono::steady_clock;
  for (auto _ : state) {
    Simulator sim(*world, o.seed);
    if (!sim.add_robot(world->geometry().cell_at_unchecked(path.front().translation()),
                       RobotSpec{RobotKind::kLidar, o.lidar})) {
      state.SkipWithError("cannot place the robot");
      return;
    }
    OccupancyGrid map(world->geometry());
    FrontierSet set(map);
    std::vector<Cell> touched;
    double incremental_s = 0.0, full_s = 0.0;
    std::int64_t steps = 0, full_runs = 0;
    std::size_t touched_total = 0;
    for (std::size_t k = 0; k < path.size(); ++k) {
      if (k > 0) {
        const Cell next = world->geometry().cell_at_unchecked(path[k].translation());
        if (!sim.move_to_adjacent(0, next).moved) continue;
      }
      touched.clear();
      insert_scan(map, sim.pose(0), sim.scan(0), o.scan_insert, &touched);
      const auto t0 = Clock::now();
      set.update(map, touched);
      incremental_s += std::chrono::duration<double>(Clock::now() - t0).count();
      touched_total += touched.size();
      ++steps;
      if (k % 25 == 0) {
        const auto t1 = Clock::now();
        std::vector<Cell> full = compute_frontier(map);
        full_s += std::chrono::duration<double>(Clock::now() - t1).count();
        benchmark::DoNotOptimize(full.data());
        ++full_runs;
        if (full.size() != set.size()) {
          state.SkipWithError("incremental frontier differs from the full recomputation");
          return;
        }
      }
    }
    const double inc_per_step =
        incremental_s / static_cast<double>(std::max<std::int64_t>(steps, 1));
    const double full_per_step = full_s / static_cast<double>(std::max<std::int64_t>(full_runs, 1));
    state.counters["cells"] = static_cast<double>(world->geometry().size());
    state.counters["steps"] = static_cast<double>(steps);
    state.counters["touched_per_step"] =
        static_cast<double>(touched_total) / static_cast<double>(std::max<std::int64_t>(steps, 1));
    state.counters["incremental_us_per_step"] = inc_per_step * 1e6;
    state.counters["full_us_per_step"] = full_per_step * 1e6;
    state.counters["speedup_vs_full"] = full_per_step / inc_per_step;
  }
}
BENCHMARK(BM_FrontierUpdateWholeRun)
    ->Name("FrontierUpdate/WholeRun")
    ->ArgName("max_steps")
    ->Arg(3000)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

// A whole exploration of the warehouse resampled to 0.1 m, lidar robot(s), nearest frontier.
void BM_ExploreWarehouse(benchmark::State& state) {
  std::string why;
  const std::optional<World>& fine = warehouse(&why);
  if (!fine) {
    state.SkipWithError(("warehouse map: " + why + " (set TESSERA_DATA_DIR)").c_str());
    return;
  }
  static const World world = fine->resampled(0.1);
  const ExplorationMissionOptions o = lidar_nearest(static_cast<int>(state.range(0)));
  std::optional<ExplorationResult> last;
  double wall_s = 0.0;
  for (auto _ : state) {
    const auto t0 = std::chrono::steady_clock::now();
    Result<ExplorationResult> r = run_exploration(world, o);
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (!r) {
      state.SkipWithError(r.error().message.c_str());
      return;
    }
    last = std::move(r).value();
  }
  const ExplorationMetrics& m = last->metrics;
  const double runs = static_cast<double>(state.iterations());
  state.counters["cells"] = static_cast<double>(world.geometry().size());
  state.counters["reachable_free"] = static_cast<double>(last->reachable_free_cells);
  state.counters["steps"] = static_cast<double>(m.steps);
  state.counters["coverage"] = m.coverage;
  state.counters["path_m"] = m.path_length_m;
  state.counters["planning_s"] = last->planning_time_s;
  state.counters["us_per_step"] =
      wall_s / runs / static_cast<double>(std::max<std::int64_t>(m.steps, 1)) * 1e6;
}
BENCHMARK(BM_ExploreWarehouse)
    ->Name("Explore/Warehouse")
    ->ArgName("robots")
    ->Arg(1)
    ->Arg(4)
    ->Iterations(1)
    ->Unit(benchmark::kSecond);

}  // namespace
}  // namespace tessera

BENCHMARK_MAIN();
