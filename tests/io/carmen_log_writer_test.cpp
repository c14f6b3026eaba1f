#include "tessera/io/carmen_log_writer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "io_test_util.hpp"
#include "tessera/io/carmen_log.hpp"

namespace tessera {
namespace {

using io_test::TempDir;
using ::testing::HasSubstr;
using ::testing::StartsWith;

constexpr double kPi = std::numbers::pi;

/// A scan of `beams` beams from `angle_min_rad`, `increment_rad` apart, ranges 1.0, 1.1, ...
StampedScan scan(double t_s, const Pose2& odometry, int beams, double angle_min_rad,
                 double increment_rad, double max_range_m = 30.0) {
  StampedScan s;
  s.t_s = t_s;
  s.odometry = odometry;
  s.laser_in_robot = Pose2{0.12, -0.03, 0.0};
  s.scan.angle_min_rad = angle_min_rad;
  s.scan.angle_increment_rad = increment_rad;
  s.scan.max_range_m = max_range_m;
  for (int i = 0; i < beams; ++i) s.scan.ranges_m.push_back(1.0 + 0.1 * i);
  return s;
}

void expect_same_scan(const StampedScan& read, const StampedScan& written) {
  EXPECT_NEAR(read.t_s, written.t_s, 1e-6);
  EXPECT_NEAR(read.odometry.x, written.odometry.x, 1e-6);
  EXPECT_NEAR(read.odometry.y, written.odometry.y, 1e-6);
  EXPECT_NEAR(read.odometry.theta, written.odometry.theta, 1e-6);
  EXPECT_NEAR(read.laser_in_robot.x, written.laser_in_robot.x, 1e-5);
  EXPECT_NEAR(read.laser_in_robot.y, written.laser_in_robot.y, 1e-5);
  EXPECT_NEAR(read.laser_in_robot.theta, written.laser_in_robot.theta, 1e-5);
  EXPECT_NEAR(read.scan.angle_min_rad, written.scan.angle_min_rad, 1e-9);
  EXPECT_NEAR(read.scan.angle_increment_rad, written.scan.angle_increment_rad, 1e-9);
  ASSERT_EQ(read.scan.ranges_m.size(), written.scan.ranges_m.size());
  for (std::size_t i = 0; i < read.scan.ranges_m.size(); ++i) {
    EXPECT_NEAR(read.scan.ranges_m[i], written.scan.ranges_m[i], 1e-6) << "beam " << i;
  }
}

TEST(CarmenLogWriter, ASickScanIsWrittenAsFlaserAndReadBack) {
  TempDir dir;
  LaserLog log;
  // 181 beams 1 degree apart from the robot's right: CARMEN's old-format layout.
  log.scans.push_back(scan(0.0, Pose2{1.0, 2.0, 0.3}, 181, -kPi / 2.0, kPi / 180.0));
  log.scans.push_back(scan(0.2, Pose2{1.5, 2.1, -3.0}, 181, -kPi / 2.0, kPi / 180.0));
  log.odometry = {{0.0, Pose2{1.0, 2.0, 0.3}}, {0.1, Pose2{1.2, 2.0, 0.3}}};
  const auto path = dir / "run.log";
  ASSERT_TRUE(write_carmen_log(path, log).ok());
  const std::string text = io_test::read_bytes(path);
  EXPECT_THAT(text, HasSubstr("\nFLASER 181 "));
  EXPECT_THAT(text, ::testing::Not(HasSubstr("ROBOTLASER1")));
  // The ODOM of 0.1 s sits between the two scans, as a robot logs it.
  EXPECT_LT(text.find("FLASER"), text.find("ODOM 1.2"));
  EXPECT_LT(text.find("ODOM 1.2"), text.rfind("FLASER"));

  const Result<LaserLog> read = read_carmen_log(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read->scans.size(), 2u);
  for (std::size_t i = 0; i < 2; ++i) expect_same_scan(read->scans[i], log.scans[i]);
  ASSERT_EQ(read->odometry.size(), 2u);
  EXPECT_NEAR(read->odometry[1].pose.x, 1.2, 1e-6);
  EXPECT_NEAR(read->odometry[1].t_s, 0.1, 1e-6);
}

TEST(CarmenLogWriter, AValueOfHundredsOfDigitsIsWrittenWhole) {
  TempDir dir;
  LaserLog log;
  log.scans.push_back(scan(0.0, Pose2{1e300, -2.0, 0.0}, 181, -kPi / 2.0, kPi / 180.0));
  const auto path = dir / "far.log";
  ASSERT_TRUE(write_carmen_log(path, log).ok());
  const Result<LaserLog> read = read_carmen_log(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  EXPECT_DOUBLE_EQ(read->scans[0].odometry.x, 1e300);
  EXPECT_NEAR(read->scans[0].odometry.y, -2.0, 1e-6);
}

TEST(CarmenLogWriter, AnyOtherBeamLayoutIsWrittenAsRobotlaserWithItsGeometry) {
  TempDir dir;
  LaserLog log;
  // A 360-degree lidar of 360 beams from -pi: FLASER cannot say so.
  StampedScan s = scan(4.5, Pose2{-1.0, 0.5, 1.0}, 360, -kPi, 2.0 * kPi / 360.0, 12.0);
  s.scan.ranges_m[7] = 12.0;  // no return
  log.scans.push_back(s);
  const auto path = dir / "lidar.clf";
  ASSERT_TRUE(write_carmen_log(path, log).ok());
  EXPECT_THAT(io_test::read_bytes(path), HasSubstr("\nROBOTLASER1 0 "));
  const Result<LaserLog> read = read_carmen_log(path);
  ASSERT_TRUE(read.ok()) << read.error().message;
  ASSERT_EQ(read->scans.size(), 1u);
  expect_same_scan(read->scans[0], s);
  EXPECT_NEAR(read->scans[0].scan.max_range_m, 12.0, 1e-6);
  EXPECT_GE(read->scans[0].scan.ranges_m[7], read->scans[0].scan.max_range_m);
}

TEST(CarmenLogWriter, AScanThatCannotBeWrittenIsAUsageErrorAndTheOldFileStays) {
  TempDir dir;
  const auto path = dir / "run.log";
  io_test::write_bytes(path, "previous contents\n");
  LaserLog log;
  log.scans.push_back(scan(0.0, Pose2{}, 181, -kPi / 2.0, kPi / 180.0));
  log.scans.push_back(scan(0.2, Pose2{}, 181, -kPi / 2.0, kPi / 180.0));
  log.scans[1].scan.ranges_m[3] = std::numeric_limits<double>::quiet_NaN();
  Status s = write_carmen_log(path, log);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::kUsage);
  EXPECT_THAT(s.error().message, StartsWith(path.string() + ": scan 1 has a range"));
  EXPECT_EQ(io_test::read_bytes(path), "previous contents\n");

  log.scans[1].scan.ranges_m.clear();
  s = write_carmen_log(path, log);
  ASSERT_FALSE(s.ok());
  EXPECT_THAT(s.error().message, HasSubstr("scan 1 has no beams"));
}

TEST(CarmenLogWriter, AFolderThatDoesNotExistIsARuntimeErrorNamingThePath) {
  TempDir dir;
  LaserLog log;
  log.scans.push_back(scan(0.0, Pose2{}, 181, -kPi / 2.0, kPi / 180.0));
  const auto path = dir / "missing" / "run.log";
  const Status s = write_carmen_log(path, log);
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(s.error().message, HasSubstr(path.string()));
}

}  // namespace
}  // namespace tessera
