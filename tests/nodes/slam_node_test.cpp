#include "tessera/nodes/slam_node.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/scans_alone.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/in_process_transport.hpp"
#include "tessera/nodes/log_player.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera::nodes {
namespace {

using net::Qos;
using ::testing::HasSubstr;

// A 40-second simulated run in the built-in office, with its laser 10 cm ahead of the centre.
const LaserLog& office_log() {
  static const LaserLog log = [] {
    const World world = builtin_world("office", 0.05);
    LaserRunOptions o;
    o.max_duration_s = 40.0;
    o.laser_in_robot = Pose2{0.1, 0.0, 0.0};
    Result<SimulatedLaserRun> run = simulate_laser_run(world, o, 5);
    EXPECT_TRUE(run.ok());
    return run.ok() ? run->log : LaserLog{};
  }();
  return log;
}

TEST(SlamNode, ALogPlayedOverTopicsGivesTheOfflineTrajectory) {
  const LaserLog& log = office_log();
  ASSERT_GT(log.scans.size(), 300U);
  slam::LaserSlamOptions options;
  Result<slam::LaserSlamResult> offline = slam::run_laser_slam(log, options);
  ASSERT_TRUE(offline.ok());

  net::InProcessBus bus;
  auto player_side = bus.join();
  auto slam_side = bus.join();
  auto viewer = bus.join();
  auto player = LogPlayer::create(log, {.ns = "/r1"}, *player_side);
  ASSERT_TRUE(player.ok()) << player.error().message;
  auto node = SlamNode::create({.ns = "/r1", .map_frame = "r1/map"}, *slam_side);
  ASSERT_TRUE(node.ok()) << node.error().message;
  while (!(*player)->done()) {
    ASSERT_TRUE((*player)->publish_next().ok());
    ASSERT_TRUE((*node)->spin_once().ok());
  }
  Result<slam::LaserSlamResult> live = (*node)->finish();
  ASSERT_TRUE(live.ok()) << live.error().message;
  const SlamNodeStats& stats = (*node)->stats();
  EXPECT_EQ(stats.scans_received, log.scans.size());
  EXPECT_EQ(stats.scans_added, log.scans.size());
  EXPECT_EQ(stats.scans_dropped_invalid + stats.scans_dropped_no_pose, 0U);
  EXPECT_GE(stats.maps_published, 1U);
  ASSERT_EQ(live->trajectory.size(), offline->trajectory.size());
  double worst_m = 0.0;
  for (std::size_t i = 0; i < live->trajectory.size(); ++i) {
    EXPECT_NEAR(live->trajectory[i].t_s, offline->trajectory[i].t_s, 1e-6);
    worst_m =
        std::max(worst_m, std::hypot(live->trajectory[i].pose.x - offline->trajectory[i].pose.x,
                                     live->trajectory[i].pose.y - offline->trajectory[i].pose.y));
  }
  // The topics carry ranges as float32 and stamps as nanoseconds: the same run within a millimetre.
  EXPECT_LT(worst_m, 1e-3);

  // A viewer joining at the end gets the final map (transient local).
  std::vector<OccupancyGridMessage> maps;
  ASSERT_TRUE(viewer
                  ->subscribe({"/r1/map", std::string(kRos2OccupancyGrid), Qos::map()},
                              [&](std::span<const std::uint8_t> cdr) {
                                if (auto m = decode_cdr_occupancy_grid(cdr); m.ok()) {
                                  maps.push_back(*m);
                                }
                              })
                  .ok());
  viewer->poll();
  ASSERT_EQ(maps.size(), 1U);
  EXPECT_EQ(maps[0].header.frame_id, "r1/map");
  EXPECT_EQ(maps[0].width, static_cast<std::uint32_t>(live->map.geometry().width()));
}

// The office run's first 120 scans (12 s) as a robot without odometry sends them.
LaserLog scans_alone(const LaserLog& log) { return support::scans_alone_as_received(log, 120); }

// Plays `log` into a scans-alone SLAM node whose robot frame is `base_frame`; the trajectory, and
// how many odometry messages a listener on /r1/odom heard.
struct ScansAloneRun {
  Result<slam::LaserSlamResult> result = input_error("not run");
  SlamNodeStats stats;
  std::string odom_frame;
  std::size_t odometry_heard = 0;
  std::vector<std::string> tf_children;  // child frames of the /tf transforms published
};

ScansAloneRun play_scans_alone(const LaserLog& log, const std::string& base_frame) {
  net::InProcessBus bus;
  auto player_side = bus.join();
  auto slam_side = bus.join();
  auto listener = bus.join();
  ScansAloneRun run;
  EXPECT_TRUE(listener
                  ->subscribe({"/r1/odom", std::string(kRos2Odometry), Qos::sensor_data()},
                              [&](std::span<const std::uint8_t>) { ++run.odometry_heard; })
                  .ok());
  EXPECT_TRUE(listener
                  ->subscribe({"/tf", std::string(kRos2TfMessage), Qos::tf()},
                              [&](std::span<const std::uint8_t> cdr) {
                                Result<TfMessage> m = decode_tf_message(cdr, RosEncoding::kCdr);
                                if (!m.ok()) return;
                                for (const auto& t : m->transforms) {
                                  run.tf_children.push_back(t.child_frame_id);
                                }
                              })
                  .ok());
  auto player = LogPlayer::create(log, {.ns = "/r1"}, *player_side);
  EXPECT_TRUE(player.ok());
  SlamNodeOptions options{.ns = "/r1", .map_frame = "r1/map"};
  options.slam.use_odometry = false;
  options.base_frame = base_frame;
  auto node = SlamNode::create(options, *slam_side);
  EXPECT_TRUE(node.ok());
  if (!player.ok() || !node.ok()) return run;
  while (!(*player)->done()) {
    EXPECT_TRUE((*player)->publish_next().ok());
    EXPECT_TRUE((*node)->spin_once().ok());
    listener->poll();
  }
  run.result = (*node)->finish();
  listener->poll();
  run.stats = (*node)->stats();
  run.odom_frame = (*node)->odom_frame();
  return run;
}

double worst_offset_m(const std::vector<StampedPose2>& a, const std::vector<StampedPose2>& b) {
  double worst_m = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i) {
    worst_m = std::max(worst_m, std::hypot(a[i].pose.x - b[i].pose.x, a[i].pose.y - b[i].pose.y));
  }
  return worst_m;
}

// `log` mapped offline from its scans alone and played into a scans-alone node whose robot frame
// is `base_frame`: every scan mapped, the same trajectory, and /tf's map -> `robot_frame`.
void expect_mapped_as_offline(const LaserLog& log, const std::string& base_frame,
                              const std::string& robot_frame) {
  slam::LaserSlamOptions options;
  options.use_odometry = false;
  Result<slam::LaserSlamResult> offline = slam::run_laser_slam(log, options);
  ASSERT_TRUE(offline.ok());

  const ScansAloneRun live = play_scans_alone(log, base_frame);
  ASSERT_TRUE(live.result.ok()) << live.result.error().message;
  EXPECT_EQ(live.stats.scans_added, log.scans.size());
  EXPECT_EQ(live.stats.scans_dropped_no_pose, 0U);
  EXPECT_EQ(live.stats.odometry_received, 0U);
  EXPECT_EQ(live.odometry_heard, 0U);  // the player sends none for a log without odometry
  EXPECT_EQ(live.odom_frame, robot_frame);
  ASSERT_FALSE(live.tf_children.empty());
  EXPECT_EQ(live.tf_children.back(), robot_frame);
  ASSERT_EQ(live.result->trajectory.size(), offline->trajectory.size());
  EXPECT_LT(worst_offset_m(live.result->trajectory, offline->trajectory), 1e-6);
}

// A robot without odometry publishes its scans and the laser's place on base_link: the node maps
// them as the offline pipeline maps the same scans alone, and /tf carries map -> base_link.
TEST(SlamNode, WithoutOdometryScansAloneAreMappedAsOffline) {
  expect_mapped_as_offline(scans_alone(office_log()), "r1/base_link", "r1/base_link");
}

// A bare laser (no base_link, no tf at all): the laser's own frame is the robot.
TEST(SlamNode, WithoutOdometryOrBaseFrameTheLaserIsTheRobot) {
  LaserLog log = scans_alone(office_log());
  for (StampedScan& s : log.scans) s.laser_in_robot = Pose2{};
  expect_mapped_as_offline(log, "", "r1/laser");

  // The same scans into a node that waits for odometry: none is mapped, and it says why.
  net::InProcessBus bus;
  auto player_side = bus.join();
  auto slam_side = bus.join();
  auto player = LogPlayer::create(log, {}, *player_side);
  auto node = SlamNode::create({}, *slam_side);
  ASSERT_TRUE(player.ok() && node.ok());
  for (int i = 0; i < 20; ++i) {
    ASSERT_TRUE((*player)->publish_next().ok());
    ASSERT_EQ(*(*node)->spin_once(), 0);
  }
  const auto none = (*node)->finish();
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().kind, ErrorKind::kInput);
  EXPECT_THAT(none.error().message, HasSubstr("20 scans and no odometry"));
}

TEST(SlamNode, BadMessagesAreDroppedAndCounted) {
  net::InProcessBus bus;
  auto sender = bus.join();
  auto slam_side = bus.join();
  auto node = SlamNode::create({}, *slam_side);
  ASSERT_TRUE(node.ok());
  const auto scan_w = sender->advertise({"/scan", std::string(kRos2LaserScan), Qos::sensor_data()});
  const auto odom_w = sender->advertise({"/odom", std::string(kRos2Odometry), Qos::sensor_data()});
  ASSERT_TRUE(scan_w.ok() && odom_w.ok());
  const std::vector<std::uint8_t> garbage{0, 1, 0, 0, 9, 9};
  ASSERT_TRUE(sender->publish(*scan_w, garbage).ok());
  LaserScanMessage flat;  // angle_increment 0: no beam layout
  flat.header.frame_id = "base_link";
  flat.range_max_m = 10.0F;
  flat.ranges_m = {1.0F, 2.0F};
  ASSERT_TRUE(sender->publish(*scan_w, encode_cdr(flat)).ok());
  OdometryMessage nan_odom;
  nan_odom.pose.x_m = std::nan("");
  ASSERT_TRUE(sender->publish(*odom_w, encode_cdr(nan_odom)).ok());
  ASSERT_TRUE(sender->publish(*odom_w, garbage).ok());
  LaserScanMessage broken;  // every reading NaN or negative: nothing to map
  broken.header.frame_id = "base_link";
  broken.angle_increment_rad = 0.01F;
  broken.range_max_m = 10.0F;
  broken.ranges_m = {std::nanf(""), -1.0F, std::nanf("")};
  ASSERT_TRUE(sender->publish(*scan_w, encode_cdr(broken)).ok());
  LaserScanMessage some = broken;  // two usable readings, one no-return (+inf), two erroneous
  some.ranges_m = {2.0F, std::nanf(""), INFINITY, -0.5F, 3.0F};
  ASSERT_TRUE(sender->publish(*scan_w, encode_cdr(some)).ok());
  ASSERT_TRUE((*node)->spin_once().ok());
  EXPECT_EQ((*node)->stats().scans_received, 4U);
  EXPECT_EQ((*node)->stats().scans_dropped_invalid, 3U);
  EXPECT_EQ((*node)->stats().readings_dropped_invalid, 5U);
  EXPECT_EQ((*node)->stats().odometry_dropped_invalid, 2U);
  EXPECT_FALSE((*node)->started());
  const auto nothing = (*node)->finish();
  ASSERT_FALSE(nothing.ok());
  EXPECT_THAT(nothing.error().message, HasSubstr("no scan with odometry arrived"));
}

// A SLAM node on an in-process bus and a sender of hand-made scans and odometry.
class SlamNodeInputs : public ::testing::Test {
 protected:
  void SetUp() override {
    auto created = SlamNode::create({}, *slam_side_);
    ASSERT_TRUE(created.ok());
    node = std::move(*created);
    scan_w_ = *sender_->advertise({"/scan", std::string(kRos2LaserScan), Qos::sensor_data()});
    odom_w_ = *sender_->advertise({"/odom", std::string(kRos2Odometry), Qos::sensor_data()});
  }
  // The first scan of the office run, taken at t_ns in `frame`.
  void scan_at(std::int64_t t_ns, const std::string& frame = "base_link") {
    const auto cdr = encode_cdr(laser_scan_message(office_log().scans[0].scan, t_ns, frame));
    ASSERT_TRUE(sender_->publish(scan_w_, cdr).ok());
  }
  // Odometry at t_ns: the robot at x_m along the odometry frame's x axis.
  void odom_at(std::int64_t t_ns, double x_m = 0.0) {
    OdometryMessage odom;
    odom.header = {t_ns, "odom"};
    odom.child_frame_id = "base_link";
    odom.pose = planar_transform(x_m, 0.0, 0.0);
    ASSERT_TRUE(sender_->publish(odom_w_, encode_cdr(odom)).ok());
  }
  [[nodiscard]] int spin() { return *node->spin_once(); }
  // x of each mapped scan relative to the first, from the final trajectory.
  [[nodiscard]] std::vector<double> mapped_x() {
    const auto result = node->finish();
    EXPECT_TRUE(result.ok());
    std::vector<double> x;
    if (!result.ok()) return x;
    for (const StampedPose2& p : result->trajectory)
      x.push_back(p.pose.x - result->trajectory[0].pose.x);
    return x;
  }

  net::InProcessBus bus_;
  std::unique_ptr<net::Transport> sender_ = bus_.join();
  std::unique_ptr<net::Transport> slam_side_ = bus_.join();
  std::unique_ptr<SlamNode> node;
  net::Transport::WriterId scan_w_ = 0, odom_w_ = 0;
};

TEST_F(SlamNodeInputs, AScanWaitsForItsOdometryAndItsLaserTransform) {
  const auto tf_w =
      sender_->advertise({"/tf_static", std::string(kRos2TfMessage), Qos::tf_static()});
  const std::int64_t t0 = 1'000'000'000;
  scan_at(t0, "laser");
  ASSERT_EQ(spin(), 0);  // no odometry yet
  odom_at(t0);
  ASSERT_EQ(spin(), 0);  // odometry, but no base_link -> laser yet
  TfMessage statics;
  statics.transforms.push_back(
      planar_transform_stamped(Pose2{0.1, 0, 0}, t0, "base_link", "laser"));
  ASSERT_TRUE(sender_->publish(*tf_w, encode_cdr(statics)).ok());
  EXPECT_EQ(spin(), 1);
  EXPECT_TRUE(node->started());
}

TEST(SlamNode, WithoutOdometryAScanWaitsForItsLaserTransformOnly) {
  net::InProcessBus bus;
  auto sender = bus.join();
  auto slam_side = bus.join();
  SlamNodeOptions options;
  options.slam.use_odometry = false;
  options.base_frame = "base_link";
  auto node = SlamNode::create(options, *slam_side);
  ASSERT_TRUE(node.ok());
  const auto scan_w = sender->advertise({"/scan", std::string(kRos2LaserScan), Qos::sensor_data()});
  const auto tf_w =
      sender->advertise({"/tf_static", std::string(kRos2TfMessage), Qos::tf_static()});
  ASSERT_TRUE(scan_w.ok() && tf_w.ok());
  const std::int64_t t0 = 1'000'000'000;
  ASSERT_TRUE(sender
                  ->publish(*scan_w,
                            encode_cdr(laser_scan_message(office_log().scans[0].scan, t0, "laser")))
                  .ok());
  EXPECT_EQ(*(*node)->spin_once(), 0);  // no base_link -> laser yet
  TfMessage statics;
  statics.transforms.push_back(
      planar_transform_stamped(Pose2{0.1, 0, 0}, t0, "base_link", "laser"));
  ASSERT_TRUE(sender->publish(*tf_w, encode_cdr(statics)).ok());
  EXPECT_EQ(*(*node)->spin_once(), 1);  // no odometry needed
  const auto result = (*node)->finish();
  ASSERT_TRUE(result.ok());
  EXPECT_FALSE((*node)->latest_odometry().has_value());
}

TEST_F(SlamNodeInputs, AScanStampedBeforeTheLastOneWaitsForItsOwnOdometry) {
  // Real logs' stamps go backwards now and then (265 times in the Intel raw log); DDS may deliver
  // such a scan before its odometry. It must not take the odometry around it from older messages.
  odom_at(2'000'000'000);
  scan_at(2'000'000'000);
  EXPECT_EQ(spin(), 1);
  scan_at(1'500'000'000);  // backwards, and before its odometry
  EXPECT_EQ(spin(), 0);
  odom_at(1'500'000'000);
  EXPECT_EQ(spin(), 1);
}

TEST_F(SlamNodeInputs, ScansArrivingTogetherWithBackwardStampsEachGetTheirOwnOdometry) {
  // DDS hands over whatever arrived since the last poll: here a scan at 10 s, then two stamped
  // 9.2 s and 9.4 s, with their odometry. Each must get the odometry of its own stamp, although
  // the one at 10 s is added first (an odometry buffer pruned up to it would have lost 9.2 s).
  for (const auto& [t_ns, x_m] : {std::pair<std::int64_t, double>{10'000'000'000, 0.0},
                                  {9'200'000'000, 0.8},
                                  {9'400'000'000, 0.4}}) {
    odom_at(t_ns, x_m);
    scan_at(t_ns);
  }
  EXPECT_EQ(spin(), 3);
  // The same scan seen from x = 0, 0.8 and 0.4 m: local matching keeps the odometry's offsets.
  const std::vector<double> x = mapped_x();
  ASSERT_EQ(x.size(), 3U);
  EXPECT_NEAR(x[1], 0.8, 0.1);
  EXPECT_NEAR(x[2], 0.4, 0.1);
}

TEST_F(SlamNodeInputs, AScanWaitingLongKeepsItsOdometry) {
  // SLAM can fall seconds behind the sensors: the odometry of a scan still waiting must survive
  // however much newer odometry arrives meanwhile.
  odom_at(1'000'000'000);
  scan_at(1'000'000'000);
  ASSERT_EQ(spin(), 1);
  // A scan at 2 s without its odometry, then 30 s of odometry at 10 Hz from 2 s on (x = 0.5 m at
  // 2 s); the scan is still waiting when the last of it arrives.
  scan_at(2'000'000'000);
  for (int i = 0; i <= 300; ++i) odom_at(2'000'000'000 + i * 100'000'000LL, 0.5 + 0.01 * i);
  EXPECT_EQ(spin(), 1);
  const std::vector<double> x = mapped_x();
  ASSERT_EQ(x.size(), 2U);
  EXPECT_NEAR(x[1], 0.5, 0.1);
}

TEST(SlamNode, InvalidOptionsAndNamespacesAreRefused) {
  net::InProcessBus bus;
  auto t = bus.join();
  SlamNodeOptions bad;
  bad.map_period_wall_s = 0.0;
  EXPECT_EQ(SlamNode::create(bad, *t).error().kind, ErrorKind::kUsage);
  EXPECT_EQ(SlamNode::create({.ns = "/r 1"}, *t).error().kind, ErrorKind::kInput);
  SlamNodeOptions base_with_odometry;
  base_with_odometry.base_frame = "base_link";  // only for scans alone
  EXPECT_EQ(SlamNode::create(base_with_odometry, *t).error().kind, ErrorKind::kUsage);
  LaserLog empty;
  EXPECT_FALSE(LogPlayer::create(empty, {}, *t).ok());
}

}  // namespace
}  // namespace tessera::nodes
