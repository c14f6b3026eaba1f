// ScanInput: a spinning lidar's scan waits for the odometry past its last beam, and comes with
// the robot's velocity over its sweep, as the bag reader gives it (io/robot_bag.hpp).
#include "tessera/nodes/scan_input.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/in_process_transport.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;

TEST(ScanInput, ASweptScanWaitsForTheOdometryPastItsLastBeamAndCarriesTheVelocity) {
  net::InProcessBus bus;
  auto sender = bus.join();
  auto receiver = bus.join();
  auto input = ScanInput::create("", {}, *receiver);
  ASSERT_TRUE(input.ok()) << input.error().message;
  const auto scan_w = sender->advertise({"/scan", std::string(kRos2LaserScan), Qos::sensor_data()});
  const auto odom_w = sender->advertise({"/odom", std::string(kRos2Odometry), Qos::sensor_data()});
  ASSERT_TRUE(scan_w.ok() && odom_w.ok());
  const auto next = [&] {
    receiver->poll();
    return (*input)->next(false);
  };
  // The robot drives 0.5 m/s and turns 1 rad/s; odometry every 50 ms (read along the chord between
  // messages: 1e-3 of slack).
  const auto odom_at = [&](std::int64_t t_ns) {
    const double t_s = 1e-9 * static_cast<double>(t_ns);
    OdometryMessage odom;
    odom.header = {t_ns, "odom"};
    odom.child_frame_id = "laser";  // the laser is the robot: no transform to wait for
    const Pose2 T_odom_robot = displacement({0.5, 0.0, 1.0}, t_s);
    odom.pose = planar_transform(T_odom_robot.x, T_odom_robot.y, T_odom_robot.theta);
    ASSERT_TRUE(sender->publish(*odom_w, encode_cdr(odom)).ok());
  };
  RangeScan scan;
  scan.angle_min_rad = -3.1;
  scan.angle_increment_rad = 0.1;
  scan.max_range_m = 10.0;
  scan.ranges_m = std::vector<double>(61, 2.0);
  scan.time_increment_s = 0.2 / 61.0;
  const std::int64_t t0 = 1'000'000'000;
  for (std::int64_t t = t0; t <= t0 + 100'000'000; t += 50'000'000) odom_at(t);
  ASSERT_TRUE(sender->publish(*scan_w, encode_cdr(laser_scan_message(scan, t0, "laser"))).ok());
  // Odometry at the stamp is in, but not yet past the last beam (0.197 s later).
  EXPECT_FALSE(next().has_value());
  for (std::int64_t t = t0 + 150'000'000; t <= t0 + 200'000'000; t += 50'000'000) odom_at(t);
  const std::optional<ReadyScan> ready = next();
  ASSERT_TRUE(ready.has_value());
  EXPECT_NEAR(ready->scan.scan.time_increment_s, 0.2 / 61.0, 1e-9);
  const Twist2& v = ready->scan.robot_velocity;
  EXPECT_NEAR(v.omega_rad_per_s, 1.0, 1e-6);
  EXPECT_NEAR(v.vx_m_per_s, 0.5, 1e-3);
  EXPECT_NEAR(v.vy_m_per_s, 0.0, 1e-3);
  // A scan taken at once needs the odometry of its stamp only, and has no velocity.
  scan.time_increment_s = 0.0;
  const std::int64_t t1 = t0 + 200'000'000;
  ASSERT_TRUE(sender->publish(*scan_w, encode_cdr(laser_scan_message(scan, t1, "laser"))).ok());
  const std::optional<ReadyScan> at_once = next();
  ASSERT_TRUE(at_once.has_value());
  EXPECT_TRUE(at_once->scan.robot_velocity.is_zero());
}

}  // namespace
}  // namespace tessera::nodes
