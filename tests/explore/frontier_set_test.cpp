#include "tessera/explore/frontier_set.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "explore/ascii_map.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/cell_sensor.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

World random_world(Rng& rng, double resolution_m) {
  const int w = rng.uniform_int(6, 36);
  const int h = rng.uniform_int(6, 36);
  const double density = rng.uniform(0.05, 0.4);
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(w * h));
  for (auto& s : solid) s = rng.uniform(0.0, 1.0) < density ? 1 : 0;
  return World(GridGeometry({-1.0, 2.0}, resolution_m, w, h), std::move(solid));
}

Cell random_cell(Rng& rng, const GridGeometry& g) {
  return {rng.uniform_int(0, g.width() - 1), rng.uniform_int(0, g.height() - 1)};
}

CellReading read_cells(const World& world, Cell center) {
  CellReading r;
  r.center = center;
  for (std::size_t k = 0; k < kNeighbors8.size(); ++k) {
    const Cell n = center + kNeighbors8[k];
    r.inside_map[k] = world.geometry().contains(n);
    r.occupied[k] = r.inside_map[k] && world.solid(n);
  }
  return r;
}

RangeScan simulate_scan(const World& world, const Pose2& T_world_sensor, const LidarOptions& lidar,
                        Rng& rng) {
  RangeScan scan = empty_scan(lidar);
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double angle = T_world_sensor.theta + scan.angle_min_rad +
                         static_cast<double>(i) * scan.angle_increment_rad;
    const double r = world.cast_ray(T_world_sensor.translation(), angle, lidar.max_range_m);
    scan.ranges_m[i] = r >= lidar.max_range_m ? r : r + rng.gaussian(lidar.range_noise_stddev_m);
  }
  return scan;
}

TEST(FrontierSet, StartsEqualToFullComputation) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  const FrontierSet set(map);
  EXPECT_THAT(set.cells(), ElementsAre(Cell{2, 2}, Cell{3, 2}, Cell{1, 3}));
  EXPECT_EQ(set.size(), 3u);
  EXPECT_TRUE(set.contains({1, 3}));
  EXPECT_FALSE(set.contains({3, 3}));
  EXPECT_FALSE(set.contains({-1, 3}));  // outside the map
}

TEST(FrontierSet, SensingAtAFrontierCellMovesTheFrontier) {
  // The lecture's iteration: the robot moves to a frontier cell, senses the unknown neighbours and
  // only cells around it change status.
  OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  FrontierSet set(map);
  std::vector<Cell> touched;
  CellReading reading;
  reading.center = {1, 3};
  reading.inside_map.fill(true);
  // kNeighbors8 order N, NE, E, SE, S, SW, W, NW: obstacles above and to the lower left.
  reading.occupied = {true, true, false, false, false, true, false, true};
  insert_cell_reading(map, reading, CellSensorOptions{}, &touched);
  set.update(map, touched);
  EXPECT_EQ(set.cells(), compute_frontier(map));
  EXPECT_FALSE(set.contains({1, 3}));
  EXPECT_TRUE(set.contains({1, 2}));  // newly open, unknown (1,1) below it
}

TEST(FrontierSet, TouchedCellsThatKeepTheirStateDoNotBumpTheRevision) {
  OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  FrontierSet set(map);
  const std::uint64_t r0 = set.revision();
  map.set_probability({3, 3}, 0.2);                                  // still open
  const std::vector<Cell> touched{{3, 3}, {3, 3}, {-5, 2}, {9, 9}};  // repeats and outside cells
  set.update(map, touched);
  EXPECT_EQ(set.revision(), r0);
  map.set_probability({3, 2}, 0.95);  // a frontier cell turns out to hold an obstacle
  const std::vector<Cell> touched2{{3, 2}};
  set.update(map, touched2);
  EXPECT_GT(set.revision(), r0);
  EXPECT_THAT(set.cells(), ElementsAre(Cell{2, 2}, Cell{1, 3}));
}

TEST(FrontierSet, ForgettingACellCreatesFrontierAroundIt) {
  OccupancyGrid map = test::ascii_map({
      "...",
      "...",
      "...",
  });
  FrontierSet set(map);
  EXPECT_THAT(set.cells(), IsEmpty());
  map.set_unknown({1, 1});
  const std::vector<Cell> touched{{1, 1}};
  set.update(map, touched);
  EXPECT_THAT(set.cells(), ElementsAre(Cell{1, 0}, Cell{0, 1}, Cell{2, 1}, Cell{1, 2}));
}

// Property: after every update, incremental == full recomputation, over seeded random worlds and
// random sequences of cell-sensor readings, lidar scans and direct cell writes.
TEST(FrontierSet, IncrementalUpdatesEqualFullRecomputationOnRandomWorlds) {
  Rng rng(20240611);
  LidarOptions lidar;
  lidar.beams = 72;
  lidar.max_range_m = 3.0;
  lidar.range_noise_stddev_m = 0.05;
  ScanInsertOptions insert;
  insert.free_margin_m = 0.0;  // let noise flip cells both ways: more state changes to check
  for (int trial = 0; trial < 100; ++trial) {
    const double low = rng.uniform(0.2, 0.8);
    const World world = random_world(rng, 0.25);
    const GridGeometry& g = world.geometry();
    OccupancyGrid map(g);
    FrontierSet set(map, low);
    ASSERT_THAT(set.cells(), IsEmpty());
    std::vector<Cell> touched;
    for (int step = 0; step < 80; ++step) {
      touched.clear();
      const Cell c = random_cell(rng, g);
      switch (rng.uniform_int(0, 3)) {
        case 0:
          insert_cell_reading(map, read_cells(world, c), CellSensorOptions{}, &touched);
          break;
        case 1: {
          const Pose2 T_world_sensor{g.center_of(c).x, g.center_of(c).y, rng.uniform(-3.0, 3.0)};
          insert_scan(map, T_world_sensor, simulate_scan(world, T_world_sensor, lidar, rng), insert,
                      &touched);
          break;
        }
        case 2:
          map.set_probability(c, rng.uniform(0.0, 1.0));
          touched.push_back(c);
          break;
        default:
          map.set_unknown(c);
          touched.push_back(c);
          break;
      }
      set.update(map, touched);
      ASSERT_EQ(set.cells(), compute_frontier(map, low)) << "trial " << trial << " step " << step;
      ASSERT_EQ(set.size(), set.unordered().size());
    }
  }
}

TEST(FrontierSet, ResetAdoptsANewGeometry) {
  FrontierSet set(test::ascii_map({"?."}));
  EXPECT_THAT(set.cells(), ElementsAre(Cell{1, 0}));
  const OccupancyGrid bigger = test::ascii_map(test::labyrinth_rows());
  set.reset(bigger);
  EXPECT_EQ(set.cells(), compute_frontier(bigger));
}

}  // namespace
}  // namespace tessera
