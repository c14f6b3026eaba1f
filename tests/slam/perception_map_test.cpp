#include "tessera/slam/perception_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "tessera/sensors/lidar.hpp"

namespace tessera::slam {
namespace {

/// A ternary grid as text, top row first: '.' -1, '#' +1, '?' 0.
std::vector<std::string> to_rows(const TernaryGrid& g) {
  std::vector<std::string> rows;
  for (int y = g.geometry().height() - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < g.geometry().width(); ++x) {
      const std::int8_t v = g.at({x, y});
      row += v < 0 ? '.' : (v > 0 ? '#' : '?');
    }
    rows.push_back(row);
  }
  return rows;
}

TEST(TernaryGrid, StartsUnknownAndCountsKnownCells) {
  TernaryGrid g(GridGeometry({0.0, 0.0}, 0.5, 3, 2));
  EXPECT_EQ(g.known_count(), 0u);
  EXPECT_EQ(g.values().size(), 6u);
  g.set({2, 1}, kTernaryOccupied);
  g.set({0, 0}, kTernaryFree);
  EXPECT_EQ(g.known_count(), 2u);
  EXPECT_EQ(g.at({2, 1}), 1);
  EXPECT_EQ(g.at({0, 0}), -1);
  EXPECT_EQ(g.values()[5], 1);  // row-major: index = y * width + x
}

TEST(TernaryValue, EncodesUnknownFreeAndOccupiedAsTheLectureDoes) {
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, 4, 1));
  map.set_probability({1, 0}, 0.1);
  map.set_probability({2, 0}, 0.9);
  map.set_probability({3, 0}, 0.6);
  EXPECT_EQ(ternary_value(map, {0, 0}), kTernaryUnknown);
  EXPECT_EQ(ternary_value(map, {1, 0}), kTernaryFree);
  EXPECT_EQ(ternary_value(map, {2, 0}), kTernaryOccupied);
  // The threshold decides: 0.6 is an obstacle at 0.5, open at the lecture's 0.7.
  EXPECT_EQ(ternary_value(map, {3, 0}, 0.5), kTernaryOccupied);
  EXPECT_EQ(ternary_value(map, {3, 0}, 0.7), kTernaryFree);
}

TEST(RobotWindow, PutsTheRobotAtTheCentreOfItsCell) {
  // The lecture's 8x5 maps: 5 cells ahead, 2 behind, 2 to each side.
  const GridGeometry w = robot_window(0.3, 2, 5, 2);
  EXPECT_EQ(w.width(), 8);
  EXPECT_EQ(w.height(), 5);
  const Vec2 centre = w.center_of({2, 2});
  EXPECT_NEAR(centre.x, 0.0, 1e-12);
  EXPECT_NEAR(centre.y, 0.0, 1e-12);
  EXPECT_EQ(w.cell_at({1.4, 0.0}), (Cell{7, 2}));   // ahead is +x
  EXPECT_EQ(w.cell_at({0.0, 0.6}), (Cell{2, 4}));   // left is +y
  EXPECT_EQ(w.cell_at({1.64, 0.0}), (Cell{7, 2}));  // 5.5 cells ahead of the centre
  EXPECT_FALSE(w.cell_at({1.66, 0.0}).has_value());
}

TEST(RobotWindow, CoversTheSensorRangeOnEverySide) {
  const GridGeometry w = robot_window(0.3, 1.5);
  EXPECT_EQ(w.width(), 11);
  EXPECT_EQ(w.height(), 11);
  const GridGeometry v = robot_window(0.3, 1.51);
  EXPECT_EQ(v.width(), 13);
}

TEST(PerceptionFromCells, CentreIsFreeAndNeighboursFollowTheReading) {
  CellReading r;
  r.center = {4, 7};
  r.inside_map.fill(true);
  r.occupied[0] = true;     // North
  r.occupied[5] = true;     // South-West
  r.inside_map[2] = false;  // East not reported
  const TernaryGrid p = perception_from_cells(r, 0.3);
  EXPECT_THAT(to_rows(p), ::testing::ElementsAre(".#.",  //
                                                 "..?",  //
                                                 "#.."));
  EXPECT_EQ(p.geometry().cell_at({0.0, 0.0}), (Cell{1, 1}));
}

/// A scan of `beams` beams over a full circle that sees a straight wall at x = wall_m in the
/// sensor frame and nothing else within max_range_m.
RangeScan wall_scan(double wall_m, double max_range_m, int beams) {
  LidarOptions o;
  o.beams = beams;
  o.max_range_m = max_range_m;
  RangeScan scan = empty_scan(o);
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double a = scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
    const double c = std::cos(a);
    if (c > 1e-9 && wall_m / c < max_range_m) scan.ranges_m[i] = wall_m / c;
  }
  return scan;
}

TEST(PerceptionFromScan, MarksTheWallOccupiedTheSpaceBeforeItFreeAndTheRestUnknown) {
  // Cells of 1 m, the robot at the centre of window cell (3, 3), which spans x in [-0.5, 0.5]; a
  // wall 2.5 m ahead, on the border between window columns 5 and 6, so the wall cells are column 6.
  // Range 3 m.
  const GridGeometry window = robot_window(1.0, 3, 3, 3);
  const TernaryGrid p = perception_from_scan(wall_scan(2.5, 3.0, 720), window);
  EXPECT_EQ(p.at({3, 3}), kTernaryFree);  // the robot's own cell
  EXPECT_EQ(p.at({4, 3}), kTernaryFree);
  EXPECT_EQ(p.at({5, 3}), kTernaryFree);
  EXPECT_EQ(p.at({6, 3}), kTernaryOccupied);
  EXPECT_EQ(p.at({6, 2}), kTernaryOccupied);
  EXPECT_EQ(p.at({6, 4}), kTernaryOccupied);
  // Free cells behind the robot, within range.
  EXPECT_EQ(p.at({1, 3}), kTernaryFree);
  // The window's corners are more than 3 m away: no beam reached them.
  EXPECT_EQ(p.at({0, 0}), kTernaryUnknown);
  EXPECT_EQ(p.at({0, 6}), kTernaryUnknown);
}

TEST(PerceptionFromScan, SensorMountedAheadOfTheRobotSeesTheWallOneCellFurther) {
  const RangeScan scan = wall_scan(2.5, 3.0, 720);
  const GridGeometry window = robot_window(1.0, 1, 5, 1);  // robot in column 1
  // Sensor at the robot's centre: the wall is 2.5 m ahead, column 4.
  const TernaryGrid centred = perception_from_scan(scan, window);
  EXPECT_EQ(centred.at({3, 1}), kTernaryFree);
  EXPECT_EQ(centred.at({4, 1}), kTernaryOccupied);
  EXPECT_EQ(centred.at({5, 1}), kTernaryUnknown);  // behind the wall
  // Sensor 1 m ahead of the centre: the same scan puts the wall 3.5 m ahead, column 5.
  const TernaryGrid ahead = perception_from_scan(scan, window, {1.0, 0.0, 0.0});
  EXPECT_EQ(ahead.at({4, 1}), kTernaryFree);
  EXPECT_EQ(ahead.at({5, 1}), kTernaryOccupied);
  EXPECT_EQ(ahead.at({6, 1}), kTernaryUnknown);
}

TEST(PerceptionFromScan, WallDepthSetsHowManyCellsBehindAReturnAreObstacle) {
  const RangeScan scan = wall_scan(2.5, 6.0, 720);
  const GridGeometry window = robot_window(1.0, 0, 6, 0);  // one row, robot in column 0
  PerceptionOptions two_cells;
  two_cells.wall_depth_cells = 2.0;
  const TernaryGrid one = perception_from_scan(scan, window);
  const TernaryGrid two = perception_from_scan(scan, window, {}, two_cells);
  EXPECT_EQ(one.at({3, 0}), kTernaryOccupied);
  EXPECT_EQ(one.at({4, 0}), kTernaryUnknown);
  EXPECT_EQ(two.at({3, 0}), kTernaryOccupied);
  EXPECT_EQ(two.at({4, 0}), kTernaryOccupied);
  EXPECT_EQ(two.at({5, 0}), kTernaryUnknown);
  EXPECT_THAT(validate(PerceptionOptions{0.0}).value_or(""),
              ::testing::HasSubstr("wall_depth_cells"));
  EXPECT_FALSE(validate(PerceptionOptions{}).has_value());
}

TEST(PerceptionFromScan, InvalidReadingsAndBearingsOutsideTheFieldOfViewStayUnknown) {
  // A forward-looking lidar of 90 degrees that sees nothing within 3 m, except that its middle
  // beam (straight ahead) is invalid.
  LidarOptions o;
  o.beams = 91;
  o.fov_rad = 0.5 * std::numbers::pi;
  o.min_range_m = 0.1;
  o.max_range_m = 3.0;
  RangeScan scan = empty_scan(o);
  scan.ranges_m[45] = 0.05;  // below min range: invalid
  const TernaryGrid p = perception_from_scan(scan, robot_window(1.0, 2, 2, 2));
  EXPECT_EQ(p.at({2, 2}), kTernaryFree);     // the sensor's own cell
  EXPECT_EQ(p.at({3, 2}), kTernaryUnknown);  // straight ahead: the invalid beam
  EXPECT_EQ(p.at({4, 3}), kTernaryFree);     // 26.6 degrees left, 2.2 m: free
  EXPECT_EQ(p.at({3, 4}), kTernaryUnknown);  // 63.4 degrees left: outside the field of view
  EXPECT_EQ(p.at({1, 2}), kTernaryUnknown);  // behind
}

TEST(ExpectedMap, ReadsTheMapCellUnderEachWindowCentre) {
  // A 6 x 6 map of 1 m cells: obstacles along column 4, row y = 5 unknown, the rest free.
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, 6, 6));
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 6; ++x) map.set_probability({x, y}, x == 4 ? 0.9 : 0.1);
  }
  const GridGeometry window = robot_window(1.0, 1, 2, 1);  // 4 x 3
  // Robot at the centre of cell (2, 2) heading +x: the window covers x 1..4, y 1..3.
  EXPECT_THAT(to_rows(expected_map(map, window, {2.5, 2.5, 0.0})),
              ::testing::ElementsAre("...#", "...#", "...#"));
  // Robot at the centre of cell (3, 2) heading +y: ahead is up and its right is +x. Window row y
  // is map column 3 - (y - 1), so the obstacle column 4 is window row 0 (on the right); window
  // column x is map row 2 + (x - 1), rows 1..4, all known.
  EXPECT_THAT(to_rows(expected_map(map, window, {3.5, 2.5, 0.5 * std::numbers::pi})),
              ::testing::ElementsAre("....", "....", "####"));
  // Near the map's edge: window cells beyond it are 0.
  EXPECT_THAT(to_rows(expected_map(map, window, {0.5, 3.5, 0.5 * std::numbers::pi})),
              ::testing::ElementsAre("????", "...?", "...?"));
}

TEST(ExpectedMap, RotationIsAboutTheRobotNotTheWindowCorner) {
  // One obstacle cell 2 m ahead of the robot; turning the robot by pi keeps it 2 m away, now
  // behind.
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, 7, 3));
  map.set_probability({5, 1}, 0.9);
  const GridGeometry window = robot_window(1.0, 2, 2, 1);
  const TernaryGrid ahead = expected_map(map, window, {3.5, 1.5, 0.0});
  const TernaryGrid behind = expected_map(map, window, {3.5, 1.5, -std::numbers::pi});
  EXPECT_EQ(ahead.at({4, 1}), kTernaryOccupied);
  EXPECT_EQ(ahead.known_count(), 1u);
  EXPECT_EQ(behind.at({0, 1}), kTernaryOccupied);
  EXPECT_EQ(behind.known_count(), 1u);
}

}  // namespace
}  // namespace tessera::slam
