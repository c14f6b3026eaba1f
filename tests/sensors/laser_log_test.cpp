// A log with its odometry set aside (--no-odometry): nothing of it is left, not even the velocity
// it gave a scan's sweep.
#include "tessera/sensors/laser_log.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

TEST(LaserLog, WithoutOdometryNothingTheOdometryGaveIsLeft) {
  LaserLog log;
  StampedScan s;
  s.t_s = 1.0;
  s.odometry = {1.0, 2.0, 0.5};
  s.scan.ranges_m = {1.0, 2.0};
  s.scan.time_increment_s = 0.1;
  s.robot_velocity = {0.3, 0.0, 1.0};
  log.scans = {s, s};
  log.odometry = {{1.0, s.odometry}};
  without_odometry(log);
  EXPECT_FALSE(log.has_odometry);
  EXPECT_TRUE(log.odometry.empty());
  for (const StampedScan& kept : log.scans) {
    EXPECT_EQ(kept.odometry.x, 0.0);
    EXPECT_EQ(kept.odometry.theta, 0.0);
    EXPECT_TRUE(kept.robot_velocity.is_zero());
    EXPECT_EQ(kept.scan.time_increment_s, 0.1);  // the beams' times are the laser's own
    EXPECT_EQ(kept.scan.ranges_m.size(), 2u);
  }
}

}  // namespace
}  // namespace tessera
