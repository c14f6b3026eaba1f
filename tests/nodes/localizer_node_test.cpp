#include "tessera/nodes/localizer_node.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "support/map_at_truth.hpp"
#include "support/scans_alone.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/in_process_transport.hpp"
#include "tessera/nodes/log_player.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"
#include "tessera/slam/scan_matched_odometry.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;

SimulatedLaserRun office_run(std::uint64_t seed, double duration_s) {
  LaserRunOptions o;
  o.max_duration_s = duration_s;
  o.laser_in_robot = Pose2{0.1, 0.0, 0.0};
  o.odometry.heading_drift_rad_per_m = 0.02;
  Result<SimulatedLaserRun> run = simulate_laser_run(builtin_world("office", 0.05), o, seed);
  EXPECT_TRUE(run.ok());
  return std::move(run).value();
}

// The office mapped by a first robot: its scans at its true poses (a perfect session).
slam::ProbabilityGrid office_map() { return support::map_at_truth(office_run(3, 0.0)); }

// Every scan of `player` into `node`, one at a time, then the node's finish; `listener` hears
// what the node published as it goes.
void play_all(LogPlayer& player, LocalizerNode& node, net::Transport& listener) {
  while (!player.done()) {
    ASSERT_TRUE(player.publish_next().ok());
    ASSERT_TRUE(node.spin_once().ok());
    listener.poll();
  }
  ASSERT_TRUE(node.finish().ok());
  listener.poll();
}

// Another robot's run played over topics into the node with no initial pose: it is found, then
// tracked, and every pose it publishes is the offline localizer's for the same scan, with the
// covariance on ROS's x, y and yaw (widened when not confident); scans with no pose publish
// nothing, and a planner that joins late still gets the map.
TEST(LocalizerNode, FindsAndTracksARobotFromTopicsAsTheOfflineLocalizerDoes) {
  const SimulatedLaserRun run = office_run(21, 30.0);
  const slam::ProbabilityGrid map = office_map();
  const OccupancyGrid picture = map.to_occupancy_grid(2);
  slam::Localizer offline(map, slam::LocalizerOptions{});
  std::vector<slam::LocalizedScan> expected;
  for (const StampedScan& scan : run.log.scans) expected.push_back(offline.add_scan(scan));

  net::InProcessBus bus;
  auto player_side = bus.join();
  auto node_side = bus.join();
  auto listener = bus.join();
  std::vector<PoseWithCovarianceStampedMessage> poses;
  ASSERT_TRUE(listener
                  ->subscribe({"/r1/pose", std::string(kRos2PoseWithCovarianceStamped),
                               Qos::reliable(10000)},
                              [&](std::span<const std::uint8_t> cdr) {
                                auto m = decode_cdr_pose_with_covariance_stamped(cdr);
                                ASSERT_TRUE(m.ok());
                                poses.push_back(*m);
                              })
                  .ok());
  auto player = LogPlayer::create(run.log, {.ns = "/r1"}, *player_side);
  ASSERT_TRUE(player.ok());
  auto node = LocalizerNode::create(map, picture, {.ns = "/r1", .map_frame = "map"}, *node_side);
  ASSERT_TRUE(node.ok()) << node.error().message;
  play_all(**player, **node, *listener);

  const LocalizerNodeStats& stats = (*node)->stats();
  EXPECT_EQ(stats.scans_received, run.log.scans.size());
  EXPECT_EQ(stats.scans_localized + stats.scans_lost, run.log.scans.size());
  EXPECT_GT(stats.scans_lost, 0U);  // before the global search has its view
  EXPECT_GT(stats.scans_localized, run.log.scans.size() * 8 / 10);
  ASSERT_EQ(poses.size(), stats.scans_localized);
  const std::vector<slam::LocalizedScan>& live = (*node)->scans();
  ASSERT_EQ(live.size(), expected.size());
  std::size_t published = 0;
  for (std::size_t i = 0; i < live.size(); ++i) {
    ASSERT_EQ(live[i].state, expected[i].state) << "scan " << i;
    if (live[i].state == slam::LocalizationState::kLost) continue;
    // Ranges travel as float32: the same pose within a millimetre.
    EXPECT_NEAR(live[i].T_map_robot.x, expected[i].T_map_robot.x, 1e-3);
    EXPECT_NEAR(live[i].T_map_robot.y, expected[i].T_map_robot.y, 1e-3);
    const PoseWithCovarianceStampedMessage& m = poses[published++];
    const double unsure_m2 = live[i].confident ? 0.0 : 0.25;
    const double unsure_rad2 = live[i].confident ? 0.0 : 0.04;
    EXPECT_EQ(m.header.frame_id, "map");
    EXPECT_EQ(m.header.stamp_ns, to_ns(run.log.scans[i].t_s));
    EXPECT_NEAR(m.pose.x_m, live[i].T_map_robot.x, 1e-9);
    EXPECT_NEAR(m.pose.y_m, live[i].T_map_robot.y, 1e-9);
    EXPECT_DOUBLE_EQ(m.covariance[0], live[i].covariance(0, 0) + unsure_m2);
    EXPECT_DOUBLE_EQ(m.covariance[7], live[i].covariance(1, 1) + unsure_m2);
    EXPECT_DOUBLE_EQ(m.covariance[35], live[i].covariance(2, 2) + unsure_rad2);
    EXPECT_DOUBLE_EQ(m.covariance[5], live[i].covariance(0, 2));
    EXPECT_EQ(m.covariance[14], 0.0);  // z: a planar robot says nothing of it
  }
  // Tracked poses stay on the robot's true path.
  for (std::size_t i = live.size() / 2; i < live.size(); ++i) {
    if (!live[i].confident) continue;
    EXPECT_LT(std::hypot(live[i].T_map_robot.x - run.truth[i].pose.x,
                         live[i].T_map_robot.y - run.truth[i].pose.y),
              0.1)
        << "scan " << i;
  }

  // A planner joining now gets the frozen map (transient local).
  std::vector<OccupancyGridMessage> maps;
  auto late = bus.join();
  ASSERT_TRUE(late->subscribe({"/r1/map", std::string(kRos2OccupancyGrid), Qos::map()},
                              [&](std::span<const std::uint8_t> cdr) {
                                if (auto m = decode_cdr_occupancy_grid(cdr); m.ok()) {
                                  maps.push_back(*m);
                                }
                              })
                  .ok());
  late->poll();
  ASSERT_EQ(maps.size(), 1U);
  EXPECT_EQ(maps[0].width, static_cast<std::uint32_t>(picture.geometry().width()));
}

// A robot without odometry (scans and the laser's place on base_link only): the node follows it
// between scans by odometry made from its scans, as `localize` does offline with an input that has
// none, and publishes map -> base_link.
TEST(LocalizerNode, WithoutOdometryTheRobotIsFollowedByItsScans) {
  const SimulatedLaserRun truth_run = office_run(21, 15.0);
  const LaserLog log = support::scans_alone_as_received(truth_run.log, 150);
  const slam::ProbabilityGrid map = office_map();
  const OccupancyGrid picture = map.to_occupancy_grid(2);
  Result<LaserLog> with_odometry = slam::with_scan_matched_odometry(log);
  ASSERT_TRUE(with_odometry.ok()) << with_odometry.error().message;
  slam::Localizer offline(map, slam::LocalizerOptions{});
  std::vector<slam::LocalizedScan> expected;
  for (const StampedScan& scan : with_odometry->scans) expected.push_back(offline.add_scan(scan));

  net::InProcessBus bus;
  auto player_side = bus.join();
  auto node_side = bus.join();
  auto listener = bus.join();
  std::vector<std::string> tf_children;
  ASSERT_TRUE(listener
                  ->subscribe({"/tf", std::string(kRos2TfMessage), Qos::tf()},
                              [&](std::span<const std::uint8_t> cdr) {
                                Result<TfMessage> m = decode_tf_message(cdr, RosEncoding::kCdr);
                                if (!m.ok()) return;
                                for (const auto& t : m->transforms) {
                                  tf_children.push_back(t.child_frame_id);
                                }
                              })
                  .ok());
  auto player = LogPlayer::create(log, {.ns = "/r1"}, *player_side);
  ASSERT_TRUE(player.ok());
  LocalizerNodeOptions options{.ns = "/r1"};
  options.odometry_from_scans = true;
  options.base_frame = "r1/base_link";
  auto node = LocalizerNode::create(map, picture, options, *node_side);
  ASSERT_TRUE(node.ok()) << node.error().message;
  play_all(**player, **node, *listener);

  const LocalizerNodeStats& stats = (*node)->stats();
  EXPECT_EQ(stats.scans_received, log.scans.size());
  EXPECT_EQ(stats.odometry_received, 0U);
  EXPECT_GT(stats.scans_localized, log.scans.size() * 8 / 10);
  ASSERT_FALSE(tf_children.empty());
  EXPECT_EQ(tf_children.back(), "r1/base_link");
  const std::vector<slam::LocalizedScan>& live = (*node)->scans();
  ASSERT_EQ(live.size(), expected.size());
  for (std::size_t i = 0; i < live.size(); ++i) {
    ASSERT_EQ(live[i].state, expected[i].state) << "scan " << i;
    if (live[i].state == slam::LocalizationState::kLost) continue;
    EXPECT_NEAR(live[i].T_map_robot.x, expected[i].T_map_robot.x, 1e-6);
    EXPECT_NEAR(live[i].T_map_robot.y, expected[i].T_map_robot.y, 1e-6);
  }
  for (std::size_t i = live.size() / 2; i < live.size(); ++i) {
    if (!live[i].confident) continue;
    EXPECT_LT(std::hypot(live[i].T_map_robot.x - truth_run.truth[i].pose.x,
                         live[i].T_map_robot.y - truth_run.truth[i].pose.y),
              0.1)
        << "scan " << i;
  }
}

TEST(LocalizerNode, AnInitialPoseIsTrackedFromTheFirstScanAndBadOptionsAreRefused) {
  const SimulatedLaserRun run = office_run(22, 5.0);
  const slam::ProbabilityGrid map = office_map();
  const OccupancyGrid picture = map.to_occupancy_grid(2);
  net::InProcessBus bus;
  auto player_side = bus.join();
  auto node_side = bus.join();
  auto player = LogPlayer::create(run.log, {}, *player_side);
  ASSERT_TRUE(player.ok());
  auto node =
      LocalizerNode::create(map, picture, {.initial_pose = run.truth.front().pose}, *node_side);
  ASSERT_TRUE(node.ok()) << node.error().message;
  while (!(*player)->done()) {
    ASSERT_TRUE((*player)->publish_next().ok());
    ASSERT_TRUE((*node)->spin_once().ok());
  }
  ASSERT_TRUE((*node)->finish().ok());
  EXPECT_EQ((*node)->stats().scans_lost, 0U);
  EXPECT_EQ((*node)->stats().scans_localized, run.log.scans.size());

  slam::LocalizerOptions bad;
  bad.view_s = -1.0;
  auto refused = LocalizerNode::create(map, picture, {.localizer = bad}, *bus.join());
  ASSERT_FALSE(refused.ok());
  EXPECT_EQ(refused.error().kind, ErrorKind::kUsage);
  auto bad_ns = LocalizerNode::create(map, picture, {.ns = "/1 bad"}, *bus.join());
  ASSERT_FALSE(bad_ns.ok());
  EXPECT_EQ(bad_ns.error().kind, ErrorKind::kInput);
  LocalizerNodeOptions base_with_odometry;
  base_with_odometry.base_frame = "base_link";  // only for scans alone
  auto base = LocalizerNode::create(map, picture, base_with_odometry, *bus.join());
  ASSERT_FALSE(base.ok());
  EXPECT_EQ(base.error().kind, ErrorKind::kUsage);
}

}  // namespace
}  // namespace tessera::nodes
