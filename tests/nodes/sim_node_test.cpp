#include "tessera/nodes/sim_node.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/text_world.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/in_process_transport.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;
using ::testing::HasSubstr;

// A 6 m x 4 m room of 0.1 m cells, walls all round.
World room() {
  std::vector<std::string> rows(40, "#" + std::string(58, '.') + "#");
  rows.front() = rows.back() = std::string(60, '#');
  return support::text_world(rows, 0.1);
}

SimNodeOptions one_robot_at(double x_m, double y_m) {
  SimNodeOptions o;
  o.starts = {Pose2{x_m, y_m, 0.0}};
  return o;
}

// A second participant that listens to the simulator and commands it.
struct Listener {
  explicit Listener(net::InProcessBus& bus) : t(bus.join()) {}

  void listen(const std::string& topic, std::string_view type, const Qos& qos,
              std::vector<std::vector<std::uint8_t>>& into) {
    ASSERT_TRUE(
        t->subscribe({topic, std::string(type), qos}, [&into](std::span<const std::uint8_t> cdr) {
           into.emplace_back(cdr.begin(), cdr.end());
         }).ok());
  }
  net::Transport::WriterId commands(const std::string& topic) {
    return *t->advertise({topic, std::string(kRos2Twist), Qos::reliable(10)});
  }
  void drive(net::Transport::WriterId w, double v, double omega) {
    TwistMessage twist;
    twist.linear_x_mps = v;
    twist.angular_z_radps = omega;
    ASSERT_TRUE(t->publish(w, encode_cdr(twist)).ok());
  }
  std::unique_ptr<net::Transport> t;
};

TEST(SimNode, PublishesEachTopicAtItsRateOnSimulatedTime) {
  const World world = room();
  net::InProcessBus bus;
  auto sim_side = bus.join();
  Listener l(bus);
  std::vector<std::vector<std::uint8_t>> scans, odoms, clocks, tfs, statics, truths;
  l.listen("/r1/scan", kRos2LaserScan, Qos::sensor_data(), scans);
  l.listen("/r1/odom", kRos2Odometry, Qos{Qos::Reliability::kBestEffort, {}, 100}, odoms);
  l.listen("/clock", kRos2Clock, Qos{Qos::Reliability::kBestEffort, {}, 1000}, clocks);
  l.listen("/tf", kRos2TfMessage, Qos::tf(), tfs);
  l.listen("/sim/r1/ground_truth", kRos2Odometry, Qos::reliable(100), truths);
  auto sim = SimNode::create(world, one_robot_at(3.0, 2.0), 7, *sim_side);
  ASSERT_TRUE(sim.ok()) << sim.error().message;
  l.listen("/tf_static", kRos2TfMessage, Qos::tf_static(), statics);  // joins late: transient local
  for (int i = 0; i < 100; ++i) {                                     // one second
    ASSERT_TRUE((*sim)->step().ok());
    l.t->poll();
  }
  EXPECT_NEAR((*sim)->time_s(), 1.0, 1e-9);
  EXPECT_EQ(scans.size(), 10U);  // 10 Hz, the first at t = 0
  EXPECT_EQ(odoms.size(), 50U);
  EXPECT_EQ(truths.size(), 50U);
  EXPECT_EQ(tfs.size(), 50U);
  EXPECT_EQ(clocks.size(), 100U);
  ASSERT_EQ(statics.size(), 1U);

  const auto scan = decode_laser_scan(scans.back(), RosEncoding::kCdr);
  ASSERT_TRUE(scan.ok());
  EXPECT_EQ(scan->header.frame_id, "r1/laser");
  EXPECT_EQ(scan->header.stamp_ns, 900'000'000);
  ASSERT_EQ(scan->ranges_m.size(), 360U);
  // Beam 0 looks along +x from (3, 2): the wall's inner face at x = 5.9 m, 2.9 m away.
  EXPECT_NEAR(scan->ranges_m[0], 2.9, 0.05);
  const auto clock = decode_cdr_clock(clocks.back());
  ASSERT_TRUE(clock.ok());
  EXPECT_EQ(clock->clock_ns, 990'000'000);
  const auto odom = decode_odometry(odoms.front(), RosEncoding::kCdr);
  ASSERT_TRUE(odom.ok());
  EXPECT_EQ(odom->header.frame_id, "r1/odom");
  EXPECT_EQ(odom->child_frame_id, "r1/base_link");
  EXPECT_DOUBLE_EQ(odom->pose.x_m, 0.0);  // REP-105: odom starts at the robot's start pose
  const auto tf_static = decode_tf_message(statics.front(), RosEncoding::kCdr);
  ASSERT_TRUE(tf_static.ok());
  ASSERT_EQ(tf_static->transforms.size(), 1U);
  EXPECT_EQ(tf_static->transforms[0].header.frame_id, "r1/base_link");
  EXPECT_EQ(tf_static->transforms[0].child_frame_id, "r1/laser");
}

TEST(SimNode, DrivesAsCommandedAndStopsWhenCommandsStop) {
  const World world = room();
  net::InProcessBus bus;
  auto sim_side = bus.join();
  Listener l(bus);
  const auto cmd = l.commands("/r1/cmd_vel");
  auto sim = SimNode::create(world, one_robot_at(1.0, 2.0), 7, *sim_side);
  ASSERT_TRUE(sim.ok());
  for (int i = 0; i < 200; ++i) {  // 2 s at 0.5 m/s
    l.drive(cmd, 0.5, 0.0);
    ASSERT_TRUE((*sim)->step().ok());
  }
  const Pose2 moved = (*sim)->true_pose(0);
  EXPECT_NEAR(moved.x, 2.0, 0.01);
  EXPECT_NEAR(moved.y, 2.0, 1e-9);
  // Odometry reports the motion with its drift (1 % scale error by default), from the start.
  EXPECT_NEAR((*sim)->odometry_pose(0).x, 1.0, 0.05);
  EXPECT_GT(std::abs((*sim)->odometry_pose(0).x - 1.0), 1e-6);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE((*sim)->step().ok());  // no more commands
  // It coasts on the last command until the timeout (0.5 s), then stands.
  EXPECT_NEAR((*sim)->true_pose(0).x, moved.x + 0.25, 0.01);
}

TEST(SimNode, AWallStopsTheRobot) {
  const World world = room();
  net::InProcessBus bus;
  auto sim_side = bus.join();
  Listener l(bus);
  const auto cmd = l.commands("/r1/cmd_vel");
  auto sim = SimNode::create(world, one_robot_at(5.0, 2.0), 7, *sim_side);
  ASSERT_TRUE(sim.ok());
  for (int i = 0; i < 500; ++i) {
    l.drive(cmd, 0.7, 0.0);
    ASSERT_TRUE((*sim)->step().ok());
  }
  // The wall's face is at x = 5.9 m; the disc of 0.15 m stops before it.
  EXPECT_LE((*sim)->true_pose(0).x, 5.9 - 0.15 + 1e-9);
  EXPECT_GT((*sim)->true_pose(0).x, 5.6);
  EXPECT_GT((*sim)->stalls(0), 0U);
  // Against the wall, odometry reports the robot standing, although it is still commanded.
  std::vector<std::vector<std::uint8_t>> odoms;
  l.listen("/r1/odom", kRos2Odometry, Qos::sensor_data(), odoms);
  for (int i = 0; i < 10; ++i) {
    l.drive(cmd, 0.7, 0.0);
    ASSERT_TRUE((*sim)->step().ok());
    l.t->poll();
  }
  ASSERT_FALSE(odoms.empty());
  const auto odom = decode_odometry(odoms.back(), RosEncoding::kCdr);
  ASSERT_TRUE(odom.ok());
  EXPECT_EQ(odom->twist.linear_x_mps, 0.0);
}

TEST(SimNode, MalformedCommandsAreDroppedAndCounted) {
  const World world = room();
  net::InProcessBus bus;
  auto sim_side = bus.join();
  Listener l(bus);
  const auto cmd = l.commands("/r1/cmd_vel");
  auto sim = SimNode::create(world, one_robot_at(3.0, 2.0), 7, *sim_side);
  ASSERT_TRUE(sim.ok());
  const std::vector<std::uint8_t> garbage{0, 1, 0, 0, 1, 2, 3};
  ASSERT_TRUE(l.t->publish(cmd, garbage).ok());
  l.drive(cmd, std::nan(""), 0.0);
  ASSERT_TRUE((*sim)->step().ok());
  ASSERT_TRUE((*sim)->step().ok());
  EXPECT_EQ((*sim)->dropped_commands(), 2U);
  EXPECT_DOUBLE_EQ((*sim)->true_pose(0).x, 3.0);
}

TEST(SimNode, RefusesAStartInAWallAndBadOptions) {
  const World world = room();
  net::InProcessBus bus;
  auto t = bus.join();
  const auto in_wall = SimNode::create(world, one_robot_at(0.05, 2.0), 7, *t);
  ASSERT_FALSE(in_wall.ok());
  EXPECT_EQ(in_wall.error().kind, ErrorKind::kInput);
  EXPECT_THAT(in_wall.error().message, HasSubstr("start of r1 at (0.05"));
  SimNodeOptions bad = one_robot_at(3.0, 2.0);
  bad.scan_rate_hz = 0.0;
  const auto invalid = SimNode::create(world, bad, 7, *t);
  ASSERT_FALSE(invalid.ok());
  EXPECT_THAT(invalid.error().message, HasSubstr("scan_rate_hz must be > 0"));
  EXPECT_FALSE(SimNode::create(world, SimNodeOptions{}, 7, *t).ok());
}

TEST(SimNode, TheSameSeedGivesTheSameScans) {
  const World world = room();
  auto scans_of = [&](std::uint64_t seed) {
    net::InProcessBus bus;
    auto sim_side = bus.join();
    Listener l(bus);
    std::vector<std::vector<std::uint8_t>> scans;
    l.listen("/r2/scan", kRos2LaserScan, Qos::sensor_data(), scans);
    SimNodeOptions o = one_robot_at(3.0, 2.0);
    o.starts.push_back(Pose2{2.0, 1.0, 1.0});
    auto sim = SimNode::create(world, o, seed, *sim_side);
    EXPECT_TRUE(sim.ok());
    for (int i = 0; i < 30; ++i) {
      EXPECT_TRUE((*sim)->step().ok());
      l.t->poll();
    }
    return scans;
  };
  const auto a = scans_of(3);
  EXPECT_EQ(a.size(), 3U);
  EXPECT_EQ(a, scans_of(3));
  EXPECT_NE(a, scans_of(4));
}

}  // namespace
}  // namespace tessera::nodes
