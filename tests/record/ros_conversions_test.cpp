// tessera's grids, paths, scans and cells as ROS 2 messages.
#include "tessera/record/ros_conversions.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "tessera/io/robot_bag.hpp"

namespace tessera {
namespace {

TEST(RosConversions, OccupancyGridIsRowMajorFromTheOriginWithUnknownAsMinusOne) {
  OccupancyGrid map(GridGeometry({-1.0, 2.0}, 0.5, 3, 2));
  map.set_probability({0, 0}, 0.0);  // free
  map.set_probability({2, 0}, 1.0);  // occupied
  map.set_probability({1, 1}, 0.7);
  const OccupancyGridMessage m = occupancy_grid_message(map, 5, "map");
  EXPECT_EQ(m.width, 3U);
  EXPECT_EQ(m.height, 2U);
  EXPECT_FLOAT_EQ(m.resolution_m, 0.5F);
  EXPECT_DOUBLE_EQ(m.origin.x_m, -1.0);
  EXPECT_DOUBLE_EQ(m.origin.y_m, 2.0);
  EXPECT_DOUBLE_EQ(m.origin.qw, 1.0);
  EXPECT_EQ(m.data, (std::vector<std::int8_t>{0, -1, 100, -1, 70, -1}));
  EXPECT_EQ(m.header.frame_id, "map");
  // A grid with no cells is a message with none (a grid may be 0 wide and still have rows).
  EXPECT_TRUE(occupancy_grid_message(OccupancyGrid(GridGeometry({0.0, 0.0}, 0.5, 0, 3)), 5, "map")
                  .data.empty());
}

// What a robot sends of its map: the known cells' box, each cell where it was in space, the same
// values as the whole map's message there.
TEST(RosConversions, AKnownBoxIsSentInPlace) {
  OccupancyGrid map(GridGeometry({-1.0, 2.0}, 0.5, 10, 8));
  map.set_probability({3, 2}, 0.2);
  map.set_probability({6, 5}, 0.9);
  const std::optional<CellBox> box = known_box(map);
  ASSERT_TRUE(box.has_value());
  const OccupancyGridMessage part = occupancy_grid_message(map, *box, 5, "r1/team");
  EXPECT_EQ(part.width, 4U);
  EXPECT_EQ(part.height, 4U);
  EXPECT_DOUBLE_EQ(part.origin.x_m, 0.5);
  EXPECT_DOUBLE_EQ(part.origin.y_m, 3.0);
  const OccupancyGridMessage whole = occupancy_grid_message(map, 5, "r1/team");
  for (std::uint32_t y = 0; y < part.height; ++y) {
    for (std::uint32_t x = 0; x < part.width; ++x) {
      EXPECT_EQ(part.data[y * 4 + x], whole.data[(y + 2) * 10 + x + 3]) << x << "," << y;
    }
  }
  EXPECT_EQ(part.data[0], 20);
  EXPECT_EQ(part.data[15], 90);
  EXPECT_EQ(part.data[5], -1);
}

TEST(RosConversions, PlanarPosesBecomeYawQuaternions) {
  const TransformStampedMessage t =
      planar_transform_stamped({1.0, 2.0, std::numbers::pi / 2}, 9, "map", "robot0/base_link");
  EXPECT_EQ(t.header.frame_id, "map");
  EXPECT_EQ(t.child_frame_id, "robot0/base_link");
  EXPECT_NEAR(t.transform.qz, std::sqrt(0.5), 1e-12);
  EXPECT_NEAR(t.transform.qw, std::sqrt(0.5), 1e-12);

  const std::vector<Pose2> poses{{0, 0, 0}, {1, 0, std::numbers::pi}};
  const std::vector<std::int64_t> stamps{0, 1'000'000'000};
  const PathMessage path = path_message(poses, stamps, 2'000'000'000, "map");
  ASSERT_EQ(path.poses.size(), 2U);
  EXPECT_EQ(path.poses[1].header.stamp_ns, 1'000'000'000);
  EXPECT_NEAR(path.poses[1].pose.qz, 1.0, 1e-12);
}

TEST(RosConversions, ScanKeepsItsAnglesAndRanges) {
  RangeScan scan;
  scan.angle_min_rad = -1.0;
  scan.angle_increment_rad = 0.5;
  scan.min_range_m = 0.1;
  scan.max_range_m = 10.0;
  scan.ranges_m = {1.0, 2.0, 11.0, 3.0, 4.0};
  const LaserScanMessage m = laser_scan_message(scan, 3, "robot0/laser");
  EXPECT_FLOAT_EQ(m.angle_max_rad, 1.0F);
  EXPECT_EQ(m.ranges_m, (std::vector<float>{1.0F, 2.0F, 11.0F, 3.0F, 4.0F}));
  EXPECT_FLOAT_EQ(m.range_max_m, 10.0F);
}

// A swept scan goes out with its time_increment; one whose beams were put counter-clockwise
// from a clockwise driver goes out clockwise again, its first beam at the stamp, and reads back
// as it was.
TEST(RosConversions, ASweptScanKeepsItsBeamTimes) {
  RangeScan scan;
  scan.angle_min_rad = -1.0;
  scan.angle_increment_rad = 0.5;
  scan.max_range_m = 10.0;
  scan.ranges_m = {1.0, 2.0, 3.0, 4.0, 5.0};
  scan.time_increment_s = 0.01;
  LaserScanMessage m = laser_scan_message(scan, 3, "laser");
  EXPECT_FLOAT_EQ(m.time_increment_s, 0.01F);
  EXPECT_FLOAT_EQ(m.angle_increment_rad, 0.5F);

  reverse_beams(scan);  // as range_scan_of keeps a clockwise driver's scan
  scan.angle_min_rad = -1.0;
  m = laser_scan_message(scan, 3, "laser");
  EXPECT_FLOAT_EQ(m.time_increment_s, 0.01F);
  EXPECT_FLOAT_EQ(m.angle_increment_rad, -0.5F);
  EXPECT_FLOAT_EQ(m.angle_min_rad, 1.0F);
  EXPECT_EQ(m.ranges_m, (std::vector<float>{1.0F, 2.0F, 3.0F, 4.0F, 5.0F}));
  int no_return = 0;
  const Result<RangeScan> back = range_scan_of(m, no_return);
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back->ranges_m, scan.ranges_m);
  EXPECT_NEAR(back->angle_min_rad, -1.0, 1e-6);
  EXPECT_NEAR(back->first_beam_s, 0.04, 1e-9);
  EXPECT_NEAR(back->time_increment_s, -0.01, 1e-9);
}

TEST(RosConversions, CellMarkerIsACubeListAtCellCentres) {
  const GridGeometry g({0.0, 0.0}, 0.1, 10, 10);
  const std::vector<Cell> cells{{0, 0}, {3, 4}};
  const MarkerMessage m = cell_marker(cells, g, 0, "map", "frontier", RosColor{1, 0, 0, 1});
  EXPECT_EQ(m.type, MarkerMessage::kCubeList);
  ASSERT_EQ(m.points.size(), 2U);
  EXPECT_NEAR(m.points[1].x_m, 0.35, 1e-12);
  EXPECT_NEAR(m.points[1].y_m, 0.45, 1e-12);
  EXPECT_DOUBLE_EQ(m.scale.x_m, 0.1);
}

}  // namespace
}  // namespace tessera
