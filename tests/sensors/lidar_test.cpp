#include "tessera/sensors/lidar.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <ostream>
#include <vector>

#include "support/cell_print.hpp"

namespace tessera {

namespace {

TEST(LidarOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(LidarOptions{}).has_value());
  const auto problem = [](auto mutate) {
    LidarOptions o;
    mutate(o);
    const auto p = validate(o);
    return p.value_or("");
  };
  EXPECT_THAT(problem([](LidarOptions& o) { o.beams = 0; }), ::testing::HasSubstr("beams"));
  EXPECT_THAT(problem([](LidarOptions& o) { o.fov_rad = 0.0; }), ::testing::HasSubstr("fov_rad"));
  EXPECT_THAT(problem([](LidarOptions& o) { o.fov_rad = 7.0; }), ::testing::HasSubstr("fov_rad"));
  EXPECT_THAT(problem([](LidarOptions& o) { o.min_range_m = -1.0; }),
              ::testing::HasSubstr("min_range_m"));
  EXPECT_THAT(problem([](LidarOptions& o) { o.max_range_m = 0.0; }),
              ::testing::HasSubstr("max_range_m"));
  EXPECT_THAT(problem([](LidarOptions& o) { o.range_noise_stddev_m = -0.1; }),
              ::testing::HasSubstr("range_noise_stddev_m"));
}

TEST(EmptyScan, FullCircleSpacesBeamsWithoutRepeatingTheFirst) {
  const RangeScan scan = empty_scan(LidarOptions{});
  ASSERT_EQ(scan.ranges_m.size(), 360u);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad, -std::numbers::pi);
  EXPECT_DOUBLE_EQ(scan.angle_increment_rad, 2.0 * std::numbers::pi / 360.0);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad + 180 * scan.angle_increment_rad, 0.0);
  EXPECT_EQ(scan.max_range_m, 8.0);
  EXPECT_TRUE(
      std::all_of(scan.ranges_m.begin(), scan.ranges_m.end(), [](double r) { return r == 8.0; }));
}

TEST(EmptyScan, PartialFieldOfViewPutsBeamsOnBothEdges) {
  LidarOptions o;
  o.beams = 181;
  o.fov_rad = std::numbers::pi;
  o.min_range_m = 0.1;
  const RangeScan scan = empty_scan(o);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad, -0.5 * std::numbers::pi);
  EXPECT_DOUBLE_EQ(scan.angle_min_rad + 180 * scan.angle_increment_rad, 0.5 * std::numbers::pi);
  EXPECT_EQ(scan.min_range_m, 0.1);
  o.beams = 1;
  EXPECT_EQ(empty_scan(o).angle_min_rad, 0.0);
}

// A 10 x 6 grid of 0.5 m cells. The sensor sits at the centre of cell (2, 3), (1.25, 1.75).
const GridGeometry kGeometry({0.0, 0.0}, 0.5, 10, 6);

RangeScan one_beam(double range_m, double max_range_m = 8.0) {
  RangeScan scan;
  scan.max_range_m = max_range_m;
  scan.ranges_m = {range_m};
  return scan;
}

TEST(InsertScan, WallHitIsOccupiedAndCellsBeforeItFree) {
  OccupancyGrid map(kGeometry);
  // Beam along +x; a wall whose face is at x = 3.5 (cell 7): range 2.25.
  const Pose2 T_map_sensor{1.25, 1.75, 0.0};
  for (int i = 0; i < 5; ++i) insert_scan(map, T_map_sensor, one_beam(2.25), {}, nullptr);
  for (int x = 2; x <= 6; ++x) EXPECT_EQ(map.state({x, 3}), CellState::kFree) << x;
  EXPECT_EQ(map.state({7, 3}), CellState::kOccupied);
  EXPECT_EQ(map.state({8, 3}), CellState::kUnknown);  // behind the wall: never seen
  EXPECT_EQ(map.state({1, 3}), CellState::kUnknown);  // behind the sensor
  EXPECT_EQ(map.known_count(), 6u);
}

TEST(InsertScan, OneUpdateAddsExactlyTheModelsLogOdds) {
  OccupancyGrid map(kGeometry);
  const ScanInsertOptions options;
  insert_scan(map, {1.25, 1.75, 0.0}, one_beam(2.25), options, nullptr);
  EXPECT_FLOAT_EQ(map.log_odds_at({4, 3}), log_odds(options.model.p_miss));
  EXPECT_FLOAT_EQ(map.log_odds_at({7, 3}), log_odds(options.model.p_hit));
}

TEST(InsertScan, ReturnExactlyOnACellBorderLandsInTheWallCellWhateverTheDirection) {
  // Facing -x from (4.25, 1.75): a wall cell (1, 3) spans x in [0.5, 1); its face is at x = 1.0,
  // range 3.25. The return point is exactly on the border of cells 1 and 2.
  OccupancyGrid map(kGeometry);
  insert_scan(map, {4.25, 1.75, -std::numbers::pi}, one_beam(3.25), {}, nullptr);
  EXPECT_EQ(map.state({1, 3}), CellState::kOccupied);
  EXPECT_EQ(map.state({2, 3}), CellState::kFree);
  // Facing +y from (1.25, 0.25): wall row 4 starts at y = 2.0, range 1.75.
  OccupancyGrid up(kGeometry);
  insert_scan(up, {1.25, 0.25, 0.5 * std::numbers::pi}, one_beam(1.75), {}, nullptr);
  EXPECT_EQ(up.state({2, 4}), CellState::kOccupied);
  EXPECT_EQ(up.state({2, 3}), CellState::kFree);
}

TEST(InsertScan, ABeamThroughAnExactCornerClearsNeitherCellItOnlyTouches) {
  // From the centre of (0, 0) at 45 degrees the beam passes exactly through the corners of the
  // diagonal cells. The cells beside each corner, e.g. (1, 0) and (0, 1), are touched at one point:
  // one of them may be a wall the beam squeezed past, so neither may get a miss.
  OccupancyGrid map(kGeometry);
  insert_scan(map, {0.25, 0.25, 0.25 * std::numbers::pi}, one_beam(2.5), {}, nullptr);
  for (int i = 0; i < 4; ++i) {
    EXPECT_EQ(map.state({i, i}), CellState::kFree) << i;
    EXPECT_EQ(map.state({i + 1, i}), CellState::kUnknown) << i;
    EXPECT_EQ(map.state({i, i + 1}), CellState::kUnknown) << i;
  }
}

TEST(InsertScan, ShortAndLongReadingsNearTheWallMoveOnlyTheHitNotTheMisses) {
  // The wall face is at x = 3.5 (cell (7, 3) spans [3.5, 4.0)); the true range is 2.25.
  // Slightly long, 2.27: the return still lies in (7, 3), which gets the hit and no miss.
  OccupancyGrid map(kGeometry);
  insert_scan(map, {1.25, 1.75, 0.0}, one_beam(2.27), {}, nullptr);
  EXPECT_FLOAT_EQ(map.log_odds_at({7, 3}), log_odds(0.7));
  EXPECT_EQ(map.state({6, 3}), CellState::kFree);
  // Slightly short, 2.23: the hit is looked up free_margin_m beyond the return, so it still goes
  // to the wall cell (7, 3) and the free cell (6, 3) in front of the wall stays free.
  OccupancyGrid short_map(kGeometry);
  insert_scan(short_map, {1.25, 1.75, 0.0}, one_beam(2.23), {}, nullptr);
  EXPECT_EQ(short_map.state({7, 3}), CellState::kOccupied);
  EXPECT_EQ(short_map.state({6, 3}), CellState::kFree);
  // Long, 2.30: nothing behind the wall is cleared; (8, 3) is not even entered before 2.75.
  OccupancyGrid long_map(kGeometry);
  insert_scan(long_map, {1.25, 1.75, 0.0}, one_beam(2.30), {}, nullptr);
  EXPECT_EQ(long_map.state({7, 3}), CellState::kOccupied);
  EXPECT_EQ(long_map.state({8, 3}), CellState::kUnknown);
}

TEST(InsertScan, OnlyAReadingLongerThanTheCellPlusMarginClearsTheWallCell) {
  // The wall cell (7, 3) spans [3.5, 4.0): a reading that still ends inside it never gives it a
  // miss; one 0.6 m too long ends in (8, 3), and (7, 3), entered 0.6 m before the range, is
  // cleared.
  OccupancyGrid map(kGeometry);
  ScanInsertOptions options;
  options.free_margin_m = 0.03;
  insert_scan(map, {1.25, 1.75, 0.0}, one_beam(2.25 + 0.4), options, nullptr);
  EXPECT_FLOAT_EQ(map.log_odds_at({7, 3}), log_odds(options.model.p_hit));
  insert_scan(map, {1.25, 1.75, 0.0}, one_beam(2.25 + 0.6), options, nullptr);
  EXPECT_FLOAT_EQ(map.log_odds_at({7, 3}),
                  log_odds(options.model.p_hit) + log_odds(options.model.p_miss));
}

TEST(InsertScan, NoReturnBeamClearsUpToMaxRangeButMarksNothing) {
  OccupancyGrid map(kGeometry);
  const Pose2 T_map_sensor{0.25, 1.75, 0.0};
  insert_scan(map, T_map_sensor, one_beam(3.0, /*max_range_m=*/3.0), {}, nullptr);
  // Cells entered at least 0.03 before 3.0 m: up to x = 3.22, cells 0..6.
  for (int x = 0; x <= 6; ++x) EXPECT_EQ(map.state({x, 3}), CellState::kFree) << x;
  EXPECT_EQ(map.state({7, 3}), CellState::kUnknown);
  EXPECT_EQ(map.known_count(), 7u);
  // Anything beyond max range also counts as no return.
  OccupancyGrid beyond(kGeometry);
  insert_scan(beyond, T_map_sensor, one_beam(std::numeric_limits<double>::infinity(), 3.0), {},
              nullptr);
  EXPECT_EQ(beyond.known_count(), 7u);
}

TEST(InsertScan, InvalidReadingsAreSkipped) {
  OccupancyGrid map(kGeometry);
  RangeScan scan = one_beam(std::numeric_limits<double>::quiet_NaN());
  scan.min_range_m = 0.2;
  scan.ranges_m.push_back(0.1);  // below min range
  insert_scan(map, {1.25, 1.75, 0.0}, scan, {}, nullptr);
  EXPECT_EQ(map.known_count(), 0u);
}

TEST(InsertScan, CellsOutsideTheMapAreIgnored) {
  OccupancyGrid map(kGeometry);
  std::vector<Cell> touched;
  // From outside the map, through it, and out again; the return lies outside.
  insert_scan(map, {-2.0, 1.75, 0.0}, one_beam(9.0, 20.0), {}, &touched);
  EXPECT_EQ(map.known_count(), 10u);
  for (const Cell c : touched) EXPECT_TRUE(kGeometry.contains(c));
  EXPECT_EQ(touched.size(), 10u);
}

TEST(InsertScan, TouchedListsOnlyCellsThatChangedOrBecameKnown) {
  OccupancyGrid map(kGeometry);
  std::vector<Cell> touched;
  const Pose2 T_map_sensor{1.25, 1.75, 0.0};
  insert_scan(map, T_map_sensor, one_beam(2.25), {}, &touched);
  EXPECT_THAT(touched, ::testing::ElementsAre(Cell{2, 3}, Cell{3, 3}, Cell{4, 3}, Cell{5, 3},
                                              Cell{6, 3}, Cell{7, 3}));
  // Saturate: after enough updates every cell sits at its clamp and nothing changes any more.
  for (int i = 0; i < 50; ++i) insert_scan(map, T_map_sensor, one_beam(2.25), {}, nullptr);
  touched.clear();
  insert_scan(map, T_map_sensor, one_beam(2.25), {}, &touched);
  EXPECT_TRUE(touched.empty());
}

TEST(InsertScan, FullScanFromTheMiddleOfAnOpenMapClearsARing) {
  // 360 no-return beams of 1 m from the centre of a 4 x 4 m map of 0.1 m cells: every cell whose
  // centre is within 0.9 m is free, nothing is occupied, nothing beyond 1.05 m is known.
  const GridGeometry g({0.0, 0.0}, 0.1, 40, 40);
  OccupancyGrid map(g);
  LidarOptions lidar;
  lidar.max_range_m = 1.0;
  insert_scan(map, {2.0, 2.0, 0.3}, empty_scan(lidar), {}, nullptr);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    const double d = (g.center_of(c) - Vec2{2.0, 2.0}).norm();
    EXPECT_NE(map.state(c), CellState::kOccupied);
    if (d < 0.9) {
      EXPECT_EQ(map.state(c), CellState::kFree) << c.x << ", " << c.y;
    }
    if (d > 1.05) {
      EXPECT_EQ(map.state(c), CellState::kUnknown) << c.x << ", " << c.y;
    }
  }
}

}  // namespace
}  // namespace tessera
