#include "tessera/mission/exploration_mission.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tessera {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;

/// A world drawn as text, top row first ('#' solid, anything else free); 0.25 m cells.
World ascii_world(const std::vector<std::string>& rows_top_first, double resolution_m = 0.25) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first.front().size());
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(w * h));
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const int y = h - 1 - row;
      solid[static_cast<std::size_t>(y * w + x)] =
          rows_top_first[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)] == '#' ? 1 : 0;
    }
  }
  return World(GridGeometry({-1.0, -2.0}, resolution_m, w, h), std::move(solid), "test");
}

// Two rooms joined by a door, a pillar, a closet behind a one-cell door and a dead-end corridor;
// 6.5 m x 4.5 m.
World rooms() {
  return ascii_world({
      "##########################",
      "#.........#..............#",
      "#.........#..............#",
      "#...##....#......###.....#",
      "#...##....#......###.....#",
      "#.........#..............#",
      "#..............#######...#",
      "#.........#....#.....#...#",
      "#.........#....#.....#...#",
      "#.........#....#.........#",
      "######.####....#######...#",
      "#.........#..............#",
      "#.........#..............#",
      "#.........#.......#......#",
      "#.................#......#",
      "#.........#.......#......#",
      "#.........#.......#.......",
      "##########################",
  });
}

// One-cell-wide corridors with turns and dead ends, where the cell robot must go everywhere.
World labyrinth() {
  return ascii_world({
      "#############",
      "#.....#.....#",
      "#.###.#.###.#",
      "#.#...#...#.#",
      "#.#.#####.#.#",
      "#...#...#...#",
      "###.#.#.#.###",
      "#.....#.....#",
      "#############",
  });
}

/// The same floor plan with every cell split into k x k cells.
World refined(const World& coarse, int k) {
  const GridGeometry& g = coarse.geometry();
  const GridGeometry fine(g.origin(), g.resolution_m() / k, g.width() * k, g.height() * k);
  std::vector<std::uint8_t> solid(fine.size());
  for (std::size_t i = 0; i < fine.size(); ++i) {
    const Cell c = fine.cell_of(i);
    solid[i] = coarse.solid({c.x / k, c.y / k}) ? 1 : 0;
  }
  return World(fine, std::move(solid), coarse.name());
}

/// An ideal lidar unless a test says otherwise: no range noise and no noise margin, so every hit
/// lands in the wall cell and every crossed cell gets a miss. With noise, insert_scan keeps errors
/// on the safe side (free cells in front of walls or door jambs may end up occupied), which can
/// leave a few free cells uncovered or close a one-cell door; NoisyLidarOnAFinerGrid... covers it.
ExplorationMissionOptions options_for(FrontierStrategy strategy, int robots, RobotKind sensor) {
  ExplorationMissionOptions o;
  o.strategy = strategy;
  o.robots = robots;
  o.sensor = sensor;
  o.seed = 7;
  o.lidar.range_noise_stddev_m = 0.0;
  o.free_margin_from_noise = false;
  o.scan_insert.free_margin_m = 0.0;
  return o;
}

std::string describe(const ExplorationMissionOptions& o) {
  return std::string(to_string(o.strategy)) + ", " + std::to_string(o.robots) + " robot(s), " +
         (o.sensor == RobotKind::kCell ? "cell" : "lidar");
}

/// Bit-identical maps: the same known cells with the same log-odds.
void expect_same_map(const OccupancyGrid& a, const OccupancyGrid& b) {
  const GridGeometry& g = a.geometry();
  ASSERT_EQ(g.size(), b.geometry().size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    ASSERT_EQ(a.known(c), b.known(c)) << to_string(c);
    ASSERT_EQ(a.log_odds_at(c), b.log_odds_at(c)) << to_string(c);
  }
}

/// Bit-identical paths, pose by pose.
void expect_same_paths(const std::vector<std::vector<Pose2>>& a,
                       const std::vector<std::vector<Pose2>>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t r = 0; r < a.size(); ++r) {
    ASSERT_EQ(a[r].size(), b[r].size()) << "robot " << r;
    for (std::size_t k = 0; k < a[r].size(); ++k) {
      EXPECT_EQ(a[r][k].x, b[r][k].x);
      EXPECT_EQ(a[r][k].y, b[r][k].y);
      EXPECT_EQ(a[r][k].theta, b[r][k].theta);
    }
  }
}

void expect_complete(const World& world, const ExplorationMissionOptions& o) {
  const Result<ExplorationResult> r = run_exploration(world, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  const ExplorationMetrics& m = r->metrics;
  EXPECT_EQ(m.stop_reason, kStopNoReachableFrontier) << describe(o);
  EXPECT_DOUBLE_EQ(m.coverage, 1.0) << describe(o);
  EXPECT_EQ(r->accuracy.occupied_as_empty, 0u) << describe(o);
  EXPECT_EQ(r->refused_moves, 0) << describe(o);
  EXPECT_TRUE(r->unreachable_frontier.empty()) << describe(o);
  EXPECT_EQ(m.robots, o.robots);
  EXPECT_EQ(r->paths.size(), static_cast<std::size_t>(o.robots));
  EXPECT_EQ(r->reachable_free_cells, world.free_count());
  EXPECT_EQ(m.coverage_over_time.size(), static_cast<std::size_t>(m.steps) + 1);
  EXPECT_TRUE(m.steps_to_90.has_value() && m.steps_to_99.has_value()) << describe(o);
  std::size_t moves = 0;
  for (const auto& path : r->paths) moves += path.size() - 1;
  EXPECT_EQ(static_cast<std::int64_t>(moves), m.path_length_cells);
  EXPECT_NEAR(m.path_length_m, static_cast<double>(moves) * world.geometry().resolution_m(), 1e-9);
}

TEST(ExplorationMission, EveryTeamSizeStrategyAndSensorExploresAllReachableFreeCells) {
  const World world = rooms();
  for (const RobotKind sensor : {RobotKind::kCell, RobotKind::kLidar}) {
    for (const FrontierStrategy strategy :
         {FrontierStrategy::kNearest, FrontierStrategy::kPriority}) {
      for (const int robots : {1, 2, 4})
        expect_complete(world, options_for(strategy, robots, sensor));
    }
  }
}

TEST(ExplorationMission, CellRobotsExploreEveryCorridorOfALabyrinth) {
  const World world = labyrinth();
  for (const FrontierStrategy strategy :
       {FrontierStrategy::kNearest, FrontierStrategy::kPriority}) {
    for (const int robots : {1, 2, 4}) {
      expect_complete(world, options_for(strategy, robots, RobotKind::kCell));
    }
  }
}

TEST(ExplorationMission, NoisyLidarOnAFinerGridEndsWithNoObstacleMappedAsFree) {
  // 5 cm cells, range noise 1 cm (the default). Free cells in front of walls may end up occupied
  // (empty_as_occupied: errors on the safe side), so coverage stays a little below 1.
  const World world = refined(rooms(), 5);
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 2, RobotKind::kLidar);
  o.lidar.range_noise_stddev_m = 0.01;
  o.scan_insert.free_margin_m = 0.03;
  const Result<ExplorationResult> r = run_exploration(world, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->metrics.stop_reason, kStopNoReachableFrontier);
  EXPECT_EQ(r->accuracy.occupied_as_empty, 0u);
  EXPECT_GT(r->metrics.coverage, 0.99);
  EXPECT_TRUE(r->unreachable_frontier.empty());
}

TEST(ExplorationMission, SameSeedGivesTheSameRun) {
  const World world = rooms();
  ExplorationMissionOptions o = options_for(FrontierStrategy::kPriority, 2, RobotKind::kLidar);
  o.lidar.range_noise_stddev_m = 0.01;  // the seed drives the noise
  o.scan_insert.free_margin_m = 0.03;
  o.seed = 12345;
  const Result<ExplorationResult> a = run_exploration(world, o);
  const Result<ExplorationResult> b = run_exploration(world, o);
  ASSERT_TRUE(a.ok() && b.ok());
  expect_same_paths(a->paths, b->paths);
  expect_same_map(a->map, b->map);
  EXPECT_EQ(a->metrics.steps, b->metrics.steps);
  EXPECT_EQ(a->metrics.turns, b->metrics.turns);
  EXPECT_EQ(a->frontier_left, b->frontier_left);
}

TEST(ExplorationMission, FrontierSeenButUnreachableIsReportedAndTheRunStillEnds) {
  // The cell robot senses diagonally: at the corridor's end (3,3) it sees the free cell (4,2)
  // through a diagonal gap, but (4,3) and (3,2) are solid, so no 4-connected path leads there.
  const World world = ascii_world({
      "########",
      "#...####",
      "####..##",
      "####...#",
      "########",
  });
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 1, RobotKind::kCell);
  o.start = Cell{1, 3};
  const Result<ExplorationResult> r = run_exploration(world, o);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->metrics.stop_reason, kStopNoReachableFrontier);
  EXPECT_EQ(r->reachable_free_cells, 3u);
  EXPECT_DOUBLE_EQ(r->metrics.coverage, 1.0);
  EXPECT_THAT(r->frontier_left, ElementsAre(Cell{4, 2}));
  EXPECT_THAT(r->unreachable_frontier, ElementsAre(Cell{4, 2}));
  EXPECT_EQ(r->metrics.steps, 2);
}

TEST(ExplorationMission, LongRunsKeepABoundedEvenlySpacedCoverageSeries) {
  // An open 160 x 160 hall: the cell robot needs more steps than the series keeps.
  std::vector<std::string> rows(160, std::string(160, '.'));
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 1, RobotKind::kCell);
  o.max_steps = 9000;
  const Result<ExplorationResult> r = run_exploration(ascii_world(rows), o);
  ASSERT_TRUE(r.ok());
  const auto& series = r->metrics.coverage_over_time;
  ASSERT_EQ(r->metrics.steps, 9000);
  EXPECT_LE(series.size(), 8193u);
  EXPECT_GT(series.size(), 4000u);
  EXPECT_EQ(series.front().step, 0);
  EXPECT_EQ(series.back().step, 9000);
  const std::int64_t stride = series[1].step - series[0].step;
  EXPECT_EQ(stride, 2);
  for (std::size_t k = 1; k + 1 < series.size(); ++k) {
    ASSERT_EQ(series[k].step, static_cast<std::int64_t>(k) * stride);
  }
  EXPECT_TRUE(r->metrics.steps_to_90.has_value() || r->metrics.coverage < 0.9);
}

TEST(ExplorationMission, StepLimitStopsTheRun) {
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 1, RobotKind::kCell);
  o.max_steps = 5;
  const Result<ExplorationResult> r = run_exploration(rooms(), o);
  ASSERT_TRUE(r.ok());
  EXPECT_EQ(r->metrics.stop_reason, kStopStepLimit);
  EXPECT_EQ(r->metrics.steps, 5);
  EXPECT_LT(r->metrics.coverage, 1.0);
}

TEST(ExplorationMission, DefaultStartIsNearTheCentreOfTheLargestFreeComponent) {
  // Left component 3 cells; right component 10 cells with centroid (5, 2.5): (5,2) and (5,3) are
  // equally near, row-major order picks (5,2).
  const World world = ascii_world({
      "##########",
      "#.#.....##",
      "#.#.....##",
      "#.########",
      "##########",
  });
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 3, RobotKind::kCell);
  const Result<std::vector<Cell>> starts = exploration_starts(world, o);
  ASSERT_TRUE(starts.ok()) << starts.error().message;
  // Then BFS order N, E, S, W from (5,2): N (5,3), E (6,2), W (4,2).
  EXPECT_THAT(*starts, ElementsAre(Cell{5, 2}, Cell{5, 3}, Cell{6, 2}));
}

TEST(ExplorationMission, BadStartsAreInputErrors) {
  const World world = rooms();
  ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 1, RobotKind::kCell);
  o.start = Cell{-1, 3};
  Result<ExplorationResult> r = run_exploration(world, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message, "start (-1, 3) is outside the map");
  o.start = Cell{0, 0};
  r = run_exploration(world, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message, "start (0, 0) is inside an obstacle");

  const World solid = ascii_world({"###", "###"});
  o.start.reset();
  r = run_exploration(solid, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_EQ(r.error().message, "world has no free cell");

  const World tiny = ascii_world({"#####", "#..##", "#####"});
  o.robots = 3;
  r = run_exploration(tiny, o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, HasSubstr("too few for 3 robots"));
}

TEST(ExplorationMission, InvalidOptionsAreUsageErrors) {
  ExplorationMissionOptions o;
  EXPECT_FALSE(validate(o).has_value());
  o.robots = 0;
  EXPECT_TRUE(validate(o).has_value());
  o = {};
  o.cell_sensor.p_free = 0.6;  // never below low: nothing would ever be open
  EXPECT_TRUE(validate(o).has_value());
  o = {};
  o.max_steps = -1;
  const Result<ExplorationResult> r = run_exploration(rooms(), o);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kUsage);
}

TEST(ExplorationMission, ProgressIsOptionalAndDoesNotChangeTheRun) {
  const World world = labyrinth();
  const ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 1, RobotKind::kCell);
  const Result<ExplorationResult> a =
      run_exploration(world, o, [](const ExplorationProgress& p) { EXPECT_GE(p.step, 1); });
  const Result<ExplorationResult> b = run_exploration(world, o);
  ASSERT_TRUE(a.ok() && b.ok());
  EXPECT_EQ(a->metrics.steps, b->metrics.steps);
  expect_same_map(a->map, b->map);
  expect_same_paths(a->paths, b->paths);
  EXPECT_EQ(a->frontier_left, b->frontier_left);
}

// The step machine: start_exploration, then step_exploration until the mission is finished, is
// run_exploration, whatever the sensor and the team.
TEST(ExplorationMission, SteppingToTheEndGivesTheRunToEndResult) {
  const World world = rooms();
  for (const RobotKind sensor : {RobotKind::kCell, RobotKind::kLidar}) {
    for (const int robots : {1, 3}) {
      ExplorationMissionOptions o = options_for(FrontierStrategy::kPriority, robots, sensor);
      o.lidar.range_noise_stddev_m = 0.01;
      o.free_margin_from_noise = true;
      SCOPED_TRACE(describe(o));
      const Result<ExplorationResult> whole = run_exploration(world, o);
      Result<SimulatedExploration> run = start_exploration(world, o);
      ASSERT_TRUE(whole.ok() && run.ok());
      std::int64_t calls = 0;
      while (!run->mission.finished()) {
        step_exploration(*run);
        ++calls;
      }
      const ExplorationMission& m = run->mission;
      EXPECT_EQ(calls, m.steps() + 1);  // the last call finds nothing left to do
      EXPECT_EQ(m.steps(), whole->metrics.steps);
      EXPECT_EQ(std::string(m.stop_reason()), whole->metrics.stop_reason);
      EXPECT_EQ(m.moves(), whole->metrics.path_length_cells);
      EXPECT_EQ(m.turns(), whole->metrics.turns);
      EXPECT_EQ(m.distance_m(), whole->metrics.path_length_m);
      EXPECT_EQ(m.frontier().cells(), whole->frontier_left);
      EXPECT_EQ(m.blacklisted_targets(), whole->blacklisted_targets);
      expect_same_map(m.map(), whole->map);
      expect_same_paths(m.paths(), whole->paths);
      // Once finished, a step changes nothing.
      step_exploration(*run);
      EXPECT_EQ(m.steps(), whole->metrics.steps);
      EXPECT_TRUE(run->mission.decide().empty());
    }
  }
}

TEST(ExplorationMission, AccessorsAgreeWithEachOtherMidRun) {
  const World world = rooms();
  const ExplorationMissionOptions o = options_for(FrontierStrategy::kNearest, 2, RobotKind::kCell);
  Result<SimulatedExploration> run = start_exploration(world, o);
  ASSERT_TRUE(run.ok());
  const ExplorationMission& m = run->mission;
  const GridGeometry& g = world.geometry();
  for (std::int64_t k = 1; k <= 40; ++k) {
    step_exploration(*run);
    ASSERT_FALSE(m.finished());
    EXPECT_EQ(m.steps(), k);
    std::int64_t moves = 0;
    for (int r = 0; r < m.robots(); ++r) {
      const std::vector<Pose2>& path = m.paths()[static_cast<std::size_t>(r)];
      moves += static_cast<std::int64_t>(path.size()) - 1;
      EXPECT_LE(static_cast<std::int64_t>(path.size()), k + 1);
      // The robot stands where its last reported pose is, in a cell the map holds free, and the
      // simulator agrees.
      EXPECT_EQ(g.cell_at_unchecked(path.back().translation()), m.cell(r));
      EXPECT_EQ(m.cell(r), run->sim.cell(r));
      EXPECT_TRUE(m.map().is_free_below(m.cell(r), log_odds(o.low)));
    }
    EXPECT_EQ(moves, m.moves());
    EXPECT_NEAR(m.distance_m(), static_cast<double>(moves) * g.resolution_m(), 1e-9);
    EXPECT_FALSE(m.changed_cells().empty());  // every step senses somewhere
    for (const Cell c : m.frontier().unordered()) EXPECT_TRUE(m.map().known(c));
  }
}

// The robots' side needs no world: readings and move outcomes made by hand drive it. A refused
// move puts an obstacle in the map where the robot bumped, and the robot plans around it.
TEST(ExplorationMission, ReadingsAndBumpsFromOutsideDriveTheRobotsSide) {
  const GridGeometry g({0.0, 0.0}, 1.0, 5, 1);
  ExplorationMissionOptions o;
  ExplorationMission m(g, o, {Cell{2, 0}});
  CellReading all_free;
  all_free.center = Cell{2, 0};
  for (std::size_t k = 0; k < 8; ++k) {
    const Cell n = all_free.center + kNeighbors8[k];
    all_free.inside_map[k] = g.contains(n);
  }
  m.sense(0, Pose2{2.5, 0.5, 0.0}, all_free);
  EXPECT_TRUE(m.map().is_free_below(Cell{1, 0}, log_odds(o.low)));
  EXPECT_TRUE(m.map().is_free_below(Cell{3, 0}, log_odds(o.low)));
  const std::vector<ExplorationMove> first = m.decide();
  ASSERT_EQ(first.size(), 1u);
  const Cell bumped = first[0].to;
  m.refused(0);
  m.end_step();
  EXPECT_EQ(m.refused_moves(), 1);
  EXPECT_FALSE(m.map().is_free_below(bumped, log_odds(o.low)));
  EXPECT_EQ(m.cell(0), (Cell{2, 0}));
  const std::vector<ExplorationMove> second = m.decide();
  ASSERT_EQ(second.size(), 1u);
  EXPECT_NE(second[0].to, bumped);
  EXPECT_EQ(manhattan(second[0].to, (Cell{2, 0})), 1);
}

}  // namespace
}  // namespace tessera
