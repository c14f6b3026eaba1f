// What placing a teammate costs a robot (issue 14, decision 0023): matching a teammate's map
// against its own (team::match_maps) and merging a teammate's map that is turned against the
// team grid (MapMerger::merged on a grid it is not aligned with). The maps: two robots' scans of
// the built-in office's corridor and hall from four places each (as tests/team/map_match_test),
// cut to their known cells (about 15 x 10 m, 0.05 m cells), as SLAM publishes them.
#include <benchmark/benchmark.h>

#include <vector>

#include "tessera/core/rng.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/lidar_scan.hpp"
#include "tessera/team/map_match.hpp"
#include "tessera/team/map_merge.hpp"

namespace tessera {
namespace {

OccupancyGrid seen_map(const World& world, const Pose2& T_world_start,
                       const std::vector<Pose2>& poses_world, std::uint64_t seed) {
  OccupancyGrid map(GridGeometry({-20.0, -20.0}, 0.05, 800, 800));
  Rng rng(seed);
  const LidarOptions lidar;
  for (int pass = 0; pass < 3; ++pass) {
    for (const Pose2& p : poses_world) {
      insert_scan(map, T_world_start.inverse() * p, simulate_lidar_scan(world, p, lidar, rng), {},
                  nullptr);
    }
  }
  return known_part(map);
}

struct Maps {
  OccupancyGrid a, b;
  Pose2 T_a_b;  // the truth
};

const Maps& maps() {
  static const Maps m = [] {
    const World office = builtin_world("office", 0.05);
    const Pose2 start_a{1.5, 7.1, 0.0}, start_b{8.0, 4.0, 2.0};
    return Maps{
        seen_map(office, start_a, {start_a, {4.5, 7.1, 0.3}, {4.5, 4.5, 1.0}, {2.0, 4.5, 0.0}}, 1),
        seen_map(office, start_b, {start_b, {7.0, 7.1, 0.0}, {4.5, 7.1, 2.0}, {4.5, 4.5, 0.5}}, 2),
        start_a.inverse() * start_b};
  }();
  return m;
}

void BM_MatchMaps(benchmark::State& state) {
  const Maps& m = maps();
  for (auto _ : state) {
    auto match = team::match_maps(m.a, m.b);
    benchmark::DoNotOptimize(match);
  }
}
BENCHMARK(BM_MatchMaps)->Unit(benchmark::kMillisecond);

// The planning grid of robot a with b's map turned by 2 rad in it, as a robot merges a placed
// teammate every time a map comes.
void BM_MergeTurnedTeammate(benchmark::State& state) {
  const Maps& m = maps();
  team::MapMerger merger(0.05);
  (void)merger.update("a", occupancy_grid_message(m.a, 0, "map"), Pose2{});
  (void)merger.update("b", occupancy_grid_message(m.b, 0, "map"), m.T_a_b);
  const GridGeometry g = merger.extent(1.0);
  for (auto _ : state) {
    OccupancyGrid merged = merger.merged(g);
    benchmark::DoNotOptimize(merged);
  }
  state.counters["cells"] = static_cast<double>(g.size());
}
BENCHMARK(BM_MergeTurnedTeammate)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace tessera

BENCHMARK_MAIN();
