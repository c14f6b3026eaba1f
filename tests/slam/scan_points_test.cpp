#include "tessera/slam/scan_points.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace tessera::slam {
namespace {

RangeScan four_beams(std::vector<double> ranges) {
  RangeScan scan;
  scan.angle_min_rad = 0.0;
  scan.angle_increment_rad = std::numbers::pi / 2.0;
  scan.min_range_m = 0.05;
  scan.max_range_m = 10.0;
  scan.ranges_m = std::move(ranges);
  return scan;
}

// Beam 0 along x, beam 1 along y; the mounting pose moves and turns every point.
TEST(ScanToPoints, ReturnsLandInTheRobotFrameThroughTheMounting) {
  ScanPointsOptions o;
  o.missing_ray_length_m = 0.0;
  const ScanPoints p =
      scan_to_points(four_beams({1.0, 2.0, 3.0, 4.0}), {0.5, 0.0, std::numbers::pi / 2.0}, o);
  ASSERT_EQ(p.returns_m.size(), 4u);
  EXPECT_NEAR(p.origin_m.x, 0.5, 1e-12);
  EXPECT_NEAR(p.returns_m[0].x, 0.5, 1e-12);  // beam 0 points along the robot's y
  EXPECT_NEAR(p.returns_m[0].y, 1.0, 1e-12);
  EXPECT_NEAR(p.returns_m[1].x, 0.5 - 2.0, 1e-12);
  EXPECT_NEAR(p.returns_m[1].y, 0.0, 1e-12);
}

// No-return readings and returns beyond max_range_m become free-space rays of the missing-ray
// length; NaN and too-short readings are dropped.
TEST(ScanToPoints, NoReturnBecomesAFreeSpaceRayAndBadReadingsAreDropped) {
  ScanPointsOptions o;
  o.max_range_m = 5.0;
  o.missing_ray_length_m = 3.0;
  const ScanPoints p = scan_to_points(
      four_beams({10.0, 6.0, std::numeric_limits<double>::quiet_NaN(), 0.01}), {}, o);
  EXPECT_TRUE(p.returns_m.empty());
  ASSERT_EQ(p.misses_m.size(), 2u);
  EXPECT_NEAR(p.misses_m[0].x, 3.0, 1e-12);
  EXPECT_NEAR(p.misses_m[1].y, 3.0, 1e-12);
  o.missing_ray_length_m = 0.0;
  EXPECT_TRUE(scan_to_points(four_beams({10.0, 6.0, 1.0, 1.0}), {}, o).misses_m.empty());
}

TEST(VoxelFilter, KeepsTheFirstPointOfEachVoxelInInputOrder) {
  const std::vector<Vec2> points{
      {0.01, 0.01}, {0.02, 0.02}, {0.3, 0.0}, {-0.01, 0.0}, {0.31, 0.01}};
  const std::vector<Vec2> kept = voxel_filter(points, 0.1);
  ASSERT_EQ(kept.size(), 3u);
  EXPECT_EQ(kept[0], points[0]);
  EXPECT_EQ(kept[1], points[2]);
  EXPECT_EQ(kept[2], points[3]);  // x < 0 is its own voxel (floor, not truncation)
  EXPECT_EQ(voxel_filter(points, 0.0).size(), points.size());
}

TEST(AdaptiveVoxelFilter, KeepsAtLeastMinPointsWhenItCan) {
  std::vector<Vec2> line;
  for (int i = 0; i < 1000; ++i) line.push_back({0.001 * i, 0.0});  // 1 m of dense points
  AdaptiveVoxelFilterOptions o;
  o.max_length_m = 0.5;
  o.min_num_points = 100;
  const std::vector<Vec2> kept = adaptive_voxel_filter(line, o);
  EXPECT_GE(kept.size(), 100u);
  EXPECT_LT(kept.size(), 250u);  // close to the target, not the whole input
  o.min_num_points = 2000;       // more than there are: everything in range stays
  EXPECT_EQ(adaptive_voxel_filter(line, o).size(), line.size());
  o.max_range_m = 0.5;
  EXPECT_EQ(adaptive_voxel_filter(line, o).size(), 501u);
}

TEST(ScanPointsOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(ScanPointsOptions{}).has_value());
  ScanPointsOptions o;
  o.max_range_m = 0.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("max_range_m"));
}

// A spinning lidar on a robot that turns and drives toward a wall (the line x = 2 m of the frame
// the robot stands in at the stamp): beam i is taken i * dt later, from where the robot then is.
// Placed from the stamp's pose the wall comes out bent and 0.1-0.5 m off; placed beam by beam
// from the robot's velocity, every return lies on it.
TEST(ScanToPoints, ASweptScanIsPlacedBeamByBeamWhereTheRobotWas) {
  const Twist2 velocity{0.3, 0.0, 1.0};  // 0.3 m/s, 1 rad/s: 0.2 rad over a 0.2 s sweep
  const Pose2 T_robot_laser{0.05, 0.0, 0.0};
  RangeScan scan;
  scan.angle_min_rad = -1.0;
  scan.angle_increment_rad = 0.01;
  scan.max_range_m = 10.0;
  scan.time_increment_s = 0.001;
  for (int i = 0; i < 200; ++i) {
    // The laser's pose at the beam's time, and its beam's distance to the wall x = 2.
    const Pose2 T_stamp_laser = displacement(velocity, 0.001 * i) * T_robot_laser;
    const double angle = T_stamp_laser.theta + scan.angle_min_rad + 0.01 * i;
    scan.ranges_m.push_back((2.0 - T_stamp_laser.x) / std::cos(angle));
  }
  ScanPointsOptions o;
  const ScanPoints unwarped = scan_to_points(scan, T_robot_laser, o, velocity);
  const ScanPoints warped = scan_to_points(scan, T_robot_laser, o);
  ASSERT_EQ(unwarped.returns_m.size(), 200u);
  double worst_unwarped_m = 0.0, worst_warped_m = 0.0;
  for (std::size_t i = 0; i < 200; ++i) {
    worst_unwarped_m = std::max(worst_unwarped_m, std::abs(unwarped.returns_m[i].x - 2.0));
    worst_warped_m = std::max(worst_warped_m, std::abs(warped.returns_m[i].x - 2.0));
  }
  EXPECT_LT(worst_unwarped_m, 1e-9);
  EXPECT_GT(worst_warped_m, 0.3);
  EXPECT_NEAR(unwarped.origin_m.x, 0.05, 1e-12);  // the sensor origin stays the stamp's

  // The same through a StampedScan; and a scan whose beams have no times is taken at once.
  const StampedScan logged{0.0, {}, T_robot_laser, scan, velocity};
  EXPECT_EQ(scan_to_points(logged, o).returns_m[150].x, unwarped.returns_m[150].x);
  scan.time_increment_s = 0.0;
  EXPECT_EQ(scan_to_points(scan, T_robot_laser, o, velocity).returns_m[150].x,
            warped.returns_m[150].x);
}

}  // namespace
}  // namespace tessera::slam
