// Bag -> LaserLog: the laser pose from the tf chain, odometry interpolated at the scan stamps,
// no-return readings, the topic choice rules; on synthetic bags and on the real Neato bags.
#include "tessera/io/robot_bag.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>

#include "support/data.hpp"
#include "support/synthetic_bag.hpp"
#include "support/temp_dir.hpp"
#include "tessera/core/pose_interpolation.hpp"
#include "tessera/io/tf_tree.hpp"

namespace tessera {
namespace {

using support::TempDir;
using ::testing::HasSubstr;

Result<RobotBag> convert(const support::SyntheticRun& run, RobotBagOptions options = {}) {
  TempDir dir;
  support::write_bytes(dir / "run.bag", support::write_ros1_bag(run.topics, run.messages, "lz4"));
  return read_robot_bag(dir / "run.bag", options);
}

TEST(RobotBag, LaserPoseComesFromTheStaticTfChain) {
  Result<RobotBag> r = convert(support::synthetic_run(RosEncoding::kRos1, 5, 36));
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->base_frame, "base_footprint");
  EXPECT_EQ(r->laser_frame, "base_laser_link");
  for (const StampedScan& s : r->log.scans) {
    EXPECT_NEAR(s.laser_in_robot.x, support::kSyntheticLaserX, 1e-12);
    EXPECT_NEAR(s.laser_in_robot.y, 0.0, 1e-12);
    EXPECT_NEAR(std::abs(s.laser_in_robot.theta), std::numbers::pi, 1e-12);
  }
}

// A bag whose laser is a MultiEchoLaserScan (as Cartographer's own bags record theirs) gives the
// log the same scans sent as LaserScan give, read by their first echoes.
TEST(RobotBag, AMultiEchoLaserScanIsReadByItsFirstEchoes) {
  const support::SyntheticRun plain = support::synthetic_run(RosEncoding::kRos1, 4, 36);
  support::SyntheticRun multi = plain;
  multi.topics[0].type = "sensor_msgs/MultiEchoLaserScan";
  for (support::MessageToWrite& m : multi.messages) {
    if (m.topic != 0) continue;
    Result<LaserScanMessage> scan = decode_laser_scan(m.data, RosEncoding::kRos1);
    ASSERT_TRUE(scan.ok()) << scan.error().message;
    m.data = support::encode_multi_echo_laser_scan(*scan, RosEncoding::kRos1);
  }
  Result<RobotBag> a = convert(plain);
  Result<RobotBag> b = convert(multi);
  ASSERT_TRUE(a.ok()) << a.error().message;
  ASSERT_TRUE(b.ok()) << b.error().message;
  EXPECT_EQ(b->scan_topic, "/scan");
  ASSERT_EQ(b->log.scans.size(), 4u);
  for (std::size_t k = 0; k < 4; ++k) {
    EXPECT_EQ(b->log.scans[k].scan.ranges_m, a->log.scans[k].scan.ranges_m) << k;
    EXPECT_EQ(b->log.scans[k].t_s, a->log.scans[k].t_s) << k;
  }
  EXPECT_EQ(b->no_return_readings, a->no_return_readings);
}

TEST(RobotBag, OdometryIsInterpolatedAtEachScanStamp) {
  Result<RobotBag> r = convert(support::synthetic_run(RosEncoding::kRos1, 8, 36));
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->log.scans.size(), 8u);
  EXPECT_EQ(r->log.odometry.size(), 16u);
  for (std::size_t k = 0; k < 8; ++k) {
    const double t = 0.1 * static_cast<double>(k) + 0.025;  // halfway between two odometry stamps
    const StampedScan& s = r->log.scans[k];
    EXPECT_NEAR(s.t_s, 1.7e9 + t, 1e-6);
    EXPECT_NEAR(s.odometry.x, 0.5 * t, 1e-9) << k;
    EXPECT_NEAR(s.odometry.theta, 0.2 * t, 1e-9) << k;
  }
}

TEST(RobotBag, OutOfRangeReadingsBecomeNoReturns) {
  Result<RobotBag> r = convert(support::synthetic_run(RosEncoding::kRos1, 2, 40));
  ASSERT_TRUE(r.ok()) << r.error().message;
  const RangeScan& scan = r->log.scans[1].scan;
  ASSERT_EQ(scan.ranges_m.size(), 40u);
  EXPECT_EQ(scan.max_range_m, 5.0);
  EXPECT_NEAR(scan.min_range_m, 0.02, 1e-7);
  EXPECT_EQ(scan.ranges_m[0], 5.0);  // inf
  EXPECT_NEAR(scan.ranges_m[1], support::synthetic_range(1, 1), 1e-6);
  EXPECT_EQ(r->no_return_readings, 2 * 4);
  EXPECT_NEAR(scan.angle_min_rad, -std::numbers::pi, 1e-6);
}

/// Five beams swept clockwise from 1 rad, 0.25 rad apart, ranges 1-5 m (10 m at most).
LaserScanMessage clockwise_scan() {
  LaserScanMessage m;
  m.angle_min_rad = 1.0F;
  m.angle_increment_rad = -0.25F;
  m.range_min_m = 0.1F;
  m.range_max_m = 10.0F;
  m.ranges_m = {1.0F, 2.0F, 3.0F, 4.0F, 5.0F};
  return m;
}

// Some drivers sweep clockwise: angle_increment < 0. The beams come back counter-clockwise, each
// still pointing where it pointed.
TEST(RobotBag, AClockwiseScanComesBackCounterClockwise) {
  LaserScanMessage m = clockwise_scan();
  m.ranges_m[2] = std::numeric_limits<float>::infinity();
  int no_return = 0;
  const Result<RangeScan> scan = range_scan_of(m, no_return);
  ASSERT_TRUE(scan.ok()) << scan.error().message;
  EXPECT_EQ(no_return, 1);
  EXPECT_NEAR(scan->angle_increment_rad, 0.25, 1e-12);
  EXPECT_NEAR(scan->angle_min_rad, 0.0, 1e-12);
  ASSERT_EQ(scan->ranges_m.size(), 5u);
  for (std::size_t b = 0; b < 5; ++b) {
    const double sent_at = 1.0 - 0.25 * static_cast<double>(b);
    const std::size_t i = 4 - b;
    EXPECT_NEAR(scan->angle_min_rad + scan->angle_increment_rad * static_cast<double>(i), sent_at,
                1e-12);
    EXPECT_EQ(scan->ranges_m[i], std::isfinite(m.ranges_m[b]) ? m.ranges_m[b] : 10.0);
  }
}

// A scan's beams are taken time_increment apart from its stamp (LaserScan's first beam); a
// clockwise scan put counter-clockwise keeps each beam's time. A time_increment that would make
// the sweep last over a second, or is not a number, is not believed.
TEST(RobotBag, EachBeamKeepsTheTimeTheDriverGaveIt) {
  LaserScanMessage m = clockwise_scan();
  m.time_increment_s = 0.01F;
  int no_return = 0;
  Result<RangeScan> scan = range_scan_of(m, no_return);
  ASSERT_TRUE(scan.ok()) << scan.error().message;
  for (std::size_t b = 0; b < 5; ++b) {  // sent as beam b, kept as beam 4 - b
    EXPECT_NEAR(beam_time_s(*scan, 4 - b), 0.01 * static_cast<double>(b), 1e-9);
    EXPECT_EQ(scan->ranges_m[4 - b], m.ranges_m[b]);
  }
  m.angle_increment_rad = 0.25F;
  scan = range_scan_of(m, no_return);
  EXPECT_EQ(scan->first_beam_s, 0.0);
  EXPECT_NEAR(scan->time_increment_s, 0.01, 1e-9);
  for (const float nonsense : {0.3F, std::numeric_limits<float>::quiet_NaN()}) {
    m.time_increment_s = nonsense;  // 0.3 s a beam: a 1.5 s sweep
    scan = range_scan_of(m, no_return);
    EXPECT_EQ(scan->time_increment_s, 0.0);
  }
}

TEST(RobotBag, DriverNoReadingConventionsAllBecomeNoReturns) {
  auto run = support::synthetic_run(RosEncoding::kCdr, 1, 10, /*with_tf=*/false);
  LaserScanMessage scan;
  scan.header = {support::kSyntheticStartNs, "base_footprint"};
  scan.angle_increment_rad = 0.1F;
  scan.range_min_m = 0.1F;
  scan.range_max_m = 4.0F;
  scan.ranges_m = {0.0F,  std::nanf(""), std::numeric_limits<float>::infinity(), 0.05F, 4.5F,
                   -1.0F, 2.0F};
  run.messages.back() = {0, scan.header.stamp_ns,
                         support::encode_laser_scan(scan, RosEncoding::kCdr)};
  TempDir dir;
  support::write_bytes(dir / "r.mcap", support::write_mcap(run.topics, run.messages, ""));
  Result<RobotBag> r = read_robot_bag(dir / "r.mcap");
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->log.scans[0].scan.ranges_m,
            (std::vector<double>{4.0, 4.0, 4.0, 4.0, 4.0, 4.0, 2.0}));
  // The scan is in the base frame itself: no tf needed, identity laser pose.
  EXPECT_EQ(r->log.scans[0].laser_in_robot.x, 0.0);
  EXPECT_EQ(r->log.scans[0].laser_in_robot.theta, 0.0);
}

TEST(RobotBag, McapWithRos1MessagesConvertsLikeTheRos1Bag) {
  const auto run = support::synthetic_run(RosEncoding::kRos1, 6, 36);
  TempDir dir;
  support::write_bytes(dir / "r.mcap",
                       support::write_mcap(run.topics, run.messages, "lz4", "ros1"));
  Result<RobotBag> from_mcap = read_robot_bag(dir / "r.mcap");
  Result<RobotBag> from_bag = convert(run);
  ASSERT_TRUE(from_mcap.ok()) << from_mcap.error().message;
  ASSERT_TRUE(from_bag.ok()) << from_bag.error().message;
  ASSERT_EQ(from_mcap->log.scans.size(), from_bag->log.scans.size());
  for (std::size_t i = 0; i < from_bag->log.scans.size(); ++i) {
    EXPECT_EQ(from_mcap->log.scans[i].t_s, from_bag->log.scans[i].t_s);
    EXPECT_EQ(from_mcap->log.scans[i].scan.ranges_m, from_bag->log.scans[i].scan.ranges_m);
    EXPECT_EQ(from_mcap->log.scans[i].odometry.x, from_bag->log.scans[i].odometry.x);
  }
}

TEST(RobotBag, BaseFrameOptionMovesOdometryAndLaserPoseToThatFrame) {
  RobotBagOptions options;
  options.base_frame = "base_link";  // identical to base_footprint in the synthetic tf
  Result<RobotBag> r = convert(support::synthetic_run(RosEncoding::kRos1, 3, 36), options);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->base_frame, "base_link");
  EXPECT_NEAR(r->log.scans[2].laser_in_robot.x, support::kSyntheticLaserX, 1e-12);
  EXPECT_NEAR(r->log.scans[2].odometry.x, 0.5 * 0.225, 1e-9);
}

TEST(RobotBag, LaserFrameWithoutTfChainIsAnInputError) {
  auto run = support::synthetic_run(RosEncoding::kRos1, 3, 36, /*with_tf=*/false);
  Result<RobotBag> r = convert(run);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, HasSubstr("run.bag: /scan message 0: laser pose: no tf chain"));
}

TEST(RobotBag, SeveralScanTopicsNeedAChoiceNamingThem) {
  auto run = support::synthetic_run(RosEncoding::kRos1, 3, 36);
  run.topics.push_back({"/stable_scan", "sensor_msgs/LaserScan"});
  run.messages.push_back({4, run.messages.back().t_ns, run.messages.back().data});
  Result<RobotBag> r = convert(run);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kUsage);
  EXPECT_THAT(r.error().message, HasSubstr("(/scan, /stable_scan): choose one with --scan-topic"));
  RobotBagOptions options;
  options.scan_topic = "/stable_scan";
  Result<RobotBag> chosen = convert(run, options);
  ASSERT_TRUE(chosen.ok()) << chosen.error().message;
  EXPECT_EQ(chosen->log.scans.size(), 1u);
  options.scan_topic = "/odom";
  Result<RobotBag> wrong = convert(run, options);
  ASSERT_FALSE(wrong.ok());
  EXPECT_THAT(wrong.error().message, HasSubstr("/odom is a nav_msgs/Odometry topic"));
}

/// `run` without topic `index` and its messages (the later topics shift down).
support::SyntheticRun without_topic(support::SyntheticRun run, std::size_t index) {
  run.topics.erase(run.topics.begin() + static_cast<std::ptrdiff_t>(index));
  std::vector<support::MessageToWrite> kept;
  for (auto& m : run.messages) {
    if (m.topic == index) continue;
    kept.push_back({m.topic > index ? m.topic - 1 : m.topic, m.t_ns, m.data});
  }
  run.messages = kept;
  return run;
}

TEST(RobotBag, BagWithoutLaserScanIsAnInputError) {
  Result<RobotBag> r = convert(without_topic(support::synthetic_run(RosEncoding::kRos1, 3, 36), 0));
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(
      r.error().message,
      HasSubstr("run.bag: no sensor_msgs/LaserScan (or sensor_msgs/MultiEchoLaserScan) topic"));
}

// A laser mounted upside down (here turned by pi about its y axis: hung under a plate, facing
// backwards) sees the room mirrored: beam b at angle a points at pi - a in the robot frame, not at
// pi + a as the upright laser turned by pi does. The scan is read mirrored, so that its points land
// where the beams went.
TEST(RobotBag, AnUpsideDownLaserIsReadMirrored) {
  const support::SyntheticRun upright_run = support::synthetic_run(RosEncoding::kRos1, 5, 36);
  support::SyntheticRun flipped_run = upright_run;
  TfMessage statics;
  statics.transforms.push_back({{support::kSyntheticStartNs, "base_footprint"}, "base_link", {}});
  statics.transforms.push_back({{support::kSyntheticStartNs, "base_link"},
                                "base_laser_link",
                                {support::kSyntheticLaserX, 0.0, 0.2, 0.0, 1.0, 0.0, 0.0}});
  ASSERT_EQ(flipped_run.messages[0].topic, 3u);  // the /tf_static message
  flipped_run.messages[0].data = support::encode_tf_message(statics, RosEncoding::kRos1);
  Result<RobotBag> upright = convert(upright_run);
  Result<RobotBag> flipped = convert(flipped_run);
  ASSERT_TRUE(upright.ok()) << upright.error().message;
  ASSERT_TRUE(flipped.ok()) << flipped.error().message;
  ASSERT_EQ(flipped->log.scans.size(), upright->log.scans.size());
  for (std::size_t k = 0; k < upright->log.scans.size(); ++k) {
    const RangeScan& sent = upright->log.scans[k].scan;  // the ranges as the laser sent them
    const StampedScan& read = flipped->log.scans[k];
    EXPECT_NEAR(std::abs(read.laser_in_robot.theta), std::numbers::pi, 1e-12);
    const std::size_t n = sent.ranges_m.size();
    ASSERT_EQ(read.scan.ranges_m.size(), n);
    for (std::size_t b = 0; b < n; ++b) {
      const double a = sent.angle_min_rad + sent.angle_increment_rad * static_cast<double>(b);
      const double r = sent.ranges_m[b];
      const Vec2 went{support::kSyntheticLaserX + r * std::cos(std::numbers::pi - a),
                      r * std::sin(std::numbers::pi - a)};
      const std::size_t i = n - 1 - b;  // the beams come in reverse order
      const double angle =
          read.scan.angle_min_rad + read.scan.angle_increment_rad * static_cast<double>(i);
      const Vec2 landed = read.laser_in_robot * Vec2{read.scan.ranges_m[i] * std::cos(angle),
                                                     read.scan.ranges_m[i] * std::sin(angle)};
      EXPECT_NEAR(landed.x, went.x, 1e-6) << "scan " << k << " beam " << b;
      EXPECT_NEAR(landed.y, went.y, 1e-6) << "scan " << k << " beam " << b;
    }
  }
}

TEST(TfTree, APlanarLaserIsUpsideDownWhenItsZAxisPointsDown) {
  const double s = std::sin(0.5 * 0.17), c = std::cos(0.5 * 0.17);
  // {x, y, z, qx, qy, qz, qw}: upright, turned by pi, tilted by 10 degrees, rolled and pitched by
  // pi.
  EXPECT_FALSE(planar_laser({0.1, 0, 0, 0, 0, 0, 1}).upside_down);
  EXPECT_FALSE(planar_laser({0.1, 0, 0, 0, 0, 1, 0}).upside_down);
  EXPECT_FALSE(planar_laser({0.1, 0, 0, 0, s, 0, c}).upside_down);
  const PlanarLaser rolled = planar_laser({0.1, 0.2, 0.3, 1, 0, 0, 0});
  EXPECT_TRUE(rolled.upside_down);
  EXPECT_NEAR(rolled.T_base_laser.x, 0.1, 1e-12);
  EXPECT_NEAR(rolled.T_base_laser.y, 0.2, 1e-12);
  EXPECT_NEAR(rolled.T_base_laser.theta, 0.0, 1e-12);  // its x axis still points forward
  const PlanarLaser pitched = planar_laser({0, 0, 0, 0, 1, 0, 0});
  EXPECT_TRUE(pitched.upside_down);
  EXPECT_NEAR(std::abs(pitched.T_base_laser.theta), std::numbers::pi, 1e-12);
}

TEST(TfTree, DynamicEdgesInterpolateAndStaticOnesWinOverOlderStatics) {
  TfTree tf;
  tf.add({{0, "/odom"}, "base", {0, 0, 0, 0, 0, 0, 1}}, false);
  tf.add({{10, "odom"}, "base", {1, 0, 0, 0, 0, 0, 1}}, false);
  tf.add({{0, "base"}, "laser", {5, 0, 0, 0, 0, 0, 1}}, true);
  tf.add({{0, "base"}, "laser", {0.5, 0, 0, 0, 0, 1, 0}}, true);  // a later static replaces it
  Result<RosTransform> T = tf.lookup("odom", "laser", 5);
  ASSERT_TRUE(T.ok()) << T.error().message;
  const Pose2 p = planar_pose(*T);
  EXPECT_NEAR(p.x, 1.0, 1e-12);  // 0.5 (interpolated) + 0.5
  EXPECT_NEAR(std::abs(p.theta), std::numbers::pi, 1e-12);
  // And the other way round: T_laser_odom is the inverse.
  const Pose2 q = planar_pose(*tf.lookup("laser", "odom", 5));
  EXPECT_NEAR(q.x, 1.0, 1e-12);
  EXPECT_FALSE(tf.lookup("odom", "camera", 5).ok());
}

// A bag that records no nav_msgs/Odometry takes the odometry from /tf's odom -> base_footprint,
// which the synthetic run publishes at the same stamps and values as /odom.
TEST(RobotBag, WithoutAnOdometryTopicTheOdometryComesFromTf) {
  const support::SyntheticRun run = support::synthetic_run(RosEncoding::kRos1, 6, 36);
  ASSERT_EQ(run.topics[1].name, "/odom");
  Result<RobotBag> with_odom = convert(run);
  Result<RobotBag> from_tf = convert(without_topic(run, 1));
  ASSERT_TRUE(with_odom.ok()) << with_odom.error().message;
  ASSERT_TRUE(from_tf.ok()) << from_tf.error().message;
  EXPECT_EQ(from_tf->odom_topic, "/tf");
  EXPECT_EQ(from_tf->odom_frame, "odom");
  EXPECT_EQ(from_tf->base_frame, "base_footprint");
  ASSERT_EQ(from_tf->log.scans.size(), with_odom->log.scans.size());
  for (std::size_t k = 0; k < from_tf->log.scans.size(); ++k) {
    const Pose2& a = from_tf->log.scans[k].odometry;
    const Pose2& b = with_odom->log.scans[k].odometry;
    EXPECT_NEAR(a.x, b.x, 1e-9) << k;
    EXPECT_NEAR(a.y, b.y, 1e-9) << k;
    EXPECT_NEAR(a.theta, b.theta, 1e-9) << k;
    EXPECT_NEAR(from_tf->log.scans[k].laser_in_robot.x, support::kSyntheticLaserX, 1e-12);
  }
  // Neither an Odometry topic nor a moving transform: scans alone, the laser is the robot.
  Result<RobotBag> none = convert(
      without_topic(support::synthetic_run(RosEncoding::kRos1, 3, 36, /*with_tf=*/false), 1));
  ASSERT_TRUE(none.ok()) << none.error().message;
  EXPECT_FALSE(none->log.has_odometry);
  EXPECT_TRUE(none->log.odometry.empty());
  EXPECT_EQ(none->odom_topic, "");
  EXPECT_EQ(none->odom_frame, "");
  EXPECT_EQ(none->base_frame, "base_laser_link");
  ASSERT_EQ(none->log.scans.size(), 3u);
  for (const StampedScan& scan : none->log.scans) {
    for (const Pose2& p : {scan.odometry, scan.laser_in_robot}) {
      EXPECT_EQ(std::hypot(p.x, p.y) + std::abs(p.theta), 0.0);
    }
  }
}

TEST(TfTree, TheLowestMovingEdgeAboveAFrameIsItsOdometry) {
  TfTree tf;
  tf.add({{0, "map"}, "odom", {0, 0, 0, 0, 0, 0, 1}}, false);
  tf.add({{0, "odom"}, "base", {0, 0, 0, 0, 0, 0, 1}}, false);
  tf.add({{10, "odom"}, "base", {1, 0, 0, 0, 0, 0, 1}}, false);
  tf.add({{0, "base"}, "laser", {0.2, 0, 0, 0, 0, 0, 1}}, true);
  const std::optional<TfTree::MovingEdge> e = tf.lowest_moving_edge("/laser");
  ASSERT_TRUE(e.has_value());
  EXPECT_EQ(e->parent, "odom");
  EXPECT_EQ(e->child, "base");
  ASSERT_EQ(e->T_parent_child.size(), 2u);
  EXPECT_EQ(e->T_parent_child[1].first, 10);
  EXPECT_EQ(e->T_parent_child[1].second.x_m, 1.0);
  EXPECT_EQ(tf.lowest_moving_edge("odom")->parent, "map");
  EXPECT_FALSE(tf.lowest_moving_edge("map").has_value());
  EXPECT_FALSE(tf.lowest_moving_edge("camera").has_value());
}

// ---- The real Neato bags ----

/// T_base_laser composed by hand from the last /tf_static value of each edge of the chain.
Pose2 static_chain(const std::filesystem::path& path, const std::vector<std::string>& chain) {
  BagReadOptions keep;
  keep.keep = [](const BagTopic& t) { return t.name == "/tf_static"; };
  Result<RosBag> bag = read_ros_bag(path, keep);
  EXPECT_TRUE(bag.ok());
  std::map<std::string, RosTransform> last;  // child -> T_parent_child
  for (const BagMessage& m : bag->messages) {
    const RosEncoding e =
        bag->topics[m.topic].serialization == "cdr" ? RosEncoding::kCdr : RosEncoding::kRos1;
    Result<TfMessage> tf = decode_tf_message(bag->bytes(m), e);
    if (!tf.ok()) {
      ADD_FAILURE() << tf.error().message;
      continue;
    }
    for (const auto& t : tf->transforms) last[t.child_frame_id] = t.transform;
  }
  Pose2 T;
  for (std::size_t i = 1; i < chain.size(); ++i) T = T * planar_pose(last.at(chain[i]));
  return T;
}

void expect_neato_bag(const std::filesystem::path& path, std::size_t scans, std::size_t odometry,
                      float no_reading, const std::vector<std::string>& chain) {
  RobotBagOptions options;
  options.scan_topic = "/scan";
  Result<RobotBag> r = read_robot_bag(path, options);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->log.scans.size(), scans);
  EXPECT_EQ(r->base_frame, chain.front());
  EXPECT_EQ(r->laser_frame, "base_laser_link");
  EXPECT_EQ(r->odom_frame, "odom");
  EXPECT_EQ(r->log.odometry.size(), odometry);
  const Pose2 expected = static_chain(path, chain);
  std::size_t full_scans = 0;
  for (const StampedScan& s : r->log.scans) {
    EXPECT_NEAR(s.laser_in_robot.x, expected.x, 1e-9);
    EXPECT_NEAR(s.laser_in_robot.y, expected.y, 1e-9);
    EXPECT_NEAR(std::abs(normalize_angle(s.laser_in_robot.theta - expected.theta)), 0.0, 1e-9);
    if (s.scan.ranges_m.size() == 361u) {
      ++full_scans;
      EXPECT_NEAR(s.scan.angle_increment_rad, std::numbers::pi / 180.0, 1e-6);  // 1 degree
    }
    EXPECT_NEAR(s.scan.max_range_m, 5.0, 1e-6);
    EXPECT_NEAR(s.scan.min_range_m, 0.02, 1e-6);
  }
  // 361 beams at 1 degree; the ROS 1 bag holds one 36-beam scan as the driver sent it.
  EXPECT_GE(full_scans, scans - 1);
  // The driver's no-reading value really occurs and is read as no return.
  BagReadOptions keep;
  keep.keep = [](const BagTopic& t) { return t.name == "/scan"; };
  Result<RosBag> bag = read_ros_bag(path, keep);
  const RosEncoding e = bag->topics[bag->messages[0].topic].serialization == "cdr"
                            ? RosEncoding::kCdr
                            : RosEncoding::kRos1;
  Result<LaserScanMessage> first = decode_laser_scan(bag->bytes(bag->messages[0]), e);
  ASSERT_TRUE(first.ok());
  EXPECT_EQ(first->ranges_m.size(), 361u);
  std::size_t found = 0;
  for (std::size_t b = 0; b < first->ranges_m.size(); ++b) {
    const float v = first->ranges_m[b];
    if ((std::isinf(no_reading) && std::isinf(v)) || v == no_reading) {
      ++found;
      EXPECT_EQ(r->log.scans[0].scan.ranges_m[b], r->log.scans[0].scan.max_range_m);
    } else {
      EXPECT_NEAR(r->log.scans[0].scan.ranges_m[b], v, 1e-6);
    }
  }
  EXPECT_GT(found, 0u);
}

TEST(RobotBagRealData, Ros2FiniteStateControllerLaserPoseMatchesTfStatic) {
  const auto path = support::data_path("bags/ros2_neato_finite_state_controller");
  TESSERA_REQUIRE_DATA(path);
  expect_neato_bag(path, 280, 301, std::numeric_limits<float>::infinity(),
                   {"base_footprint", "base_link", "base_laser_link"});
}

TEST(RobotBagRealData, Ros2ObstacleAvoiderLaserPoseMatchesTfStatic) {
  const auto path = support::data_path("bags/ros2_neato_obstacle_avoider");
  TESSERA_REQUIRE_DATA(path);
  expect_neato_bag(path, 153, 166, std::numeric_limits<float>::infinity(),
                   {"base_footprint", "base_link", "base_laser_link"});
}

TEST(RobotBagRealData, Ros1NeatoLaserPoseMatchesTfStatic) {
  const auto path = support::data_path("bags/ros1_neato_drive_square_demo.bag");
  TESSERA_REQUIRE_DATA(path);
  expect_neato_bag(path, 404, 413, 0.0F, {"base_link", "base_laser_link"});
}

// The Neato's lidar spins at 5 Hz: each scan's 360 beams are taken over 0.2 s, while the robot
// turns at up to 2.5 rad/s. Each scan says so, and carries the robot's velocity over its sweep: the
// odometry's motion from its first beam to its last.
TEST(RobotBagRealData, EachScanCarriesTheRobotsMotionOverItsSweep) {
  const auto path = support::data_path("bags/ros2_neato_finite_state_controller");
  TESSERA_REQUIRE_DATA(path);
  RobotBagOptions options;
  options.scan_topic = "/scan";
  Result<RobotBag> r = read_robot_bag(path, options);
  ASSERT_TRUE(r.ok()) << r.error().message;
  std::vector<PoseAtNs> odometry;
  for (const OdometryReading& o : r->log.odometry) {
    odometry.push_back({std::llround(o.t_s * 1e9), o.pose});
  }
  double fastest_turn_rad_per_s = 0.0;
  for (const StampedScan& s : r->log.scans) {
    const std::size_t n = s.scan.ranges_m.size();
    ASSERT_EQ(n, 361u);
    EXPECT_EQ(s.scan.first_beam_s, 0.0);
    EXPECT_NEAR(beam_time_s(s.scan, n - 1), 0.2, 1e-3);
    const std::int64_t stamp = std::llround(s.t_s * 1e9);
    const std::int64_t last = stamp + std::llround(beam_time_s(s.scan, n - 1) * 1e9);
    const Pose2 swept = between(pose_at(odometry, stamp), pose_at(odometry, last));
    const Pose2 driven = displacement(s.robot_velocity, beam_time_s(s.scan, n - 1));
    // (The stamps went through seconds as doubles here: 1e-5 of slack.)
    EXPECT_NEAR(driven.x, swept.x, 1e-5);
    EXPECT_NEAR(driven.y, swept.y, 1e-5);
    EXPECT_NEAR(driven.theta, swept.theta, 1e-5);
    fastest_turn_rad_per_s =
        std::max(fastest_turn_rad_per_s, std::abs(s.robot_velocity.omega_rad_per_s));
  }
  EXPECT_GT(fastest_turn_rad_per_s, 2.0);  // 0.4 rad within one sweep
}

// The ROS 2 Neato's driver publishes its odometry both as /odom and as odom -> base_footprint on
// /tf. Read as if the bag had no /odom, the odometry from tf is the same, scan for scan. The ROS 1
// Neato bag's /tf holds only the robot's joints: without /odom it has no odometry and is read as
// scans alone.
TEST(RobotBagRealData, OdometryFromTfIsWhereTheOdometryTopicPutsTheRobot) {
  const auto path = support::data_path("bags/ros2_neato_finite_state_controller");
  TESSERA_REQUIRE_DATA(path);
  BagReadOptions read;
  read.keep = robot_bag_needs;
  Result<RosBag> bag = read_ros_bag(path, read);
  ASSERT_TRUE(bag.ok()) << bag.error().message;
  RobotBagOptions options;
  options.scan_topic = "/scan";
  Result<RobotBag> with_odom = robot_bag_from(*bag, path.string(), options);
  ASSERT_TRUE(with_odom.ok()) << with_odom.error().message;
  for (BagTopic& t : bag->topics) {
    if (t.name == "/odom") t.type = "nav_msgs/NotRecorded";
  }
  Result<RobotBag> from_tf = robot_bag_from(*bag, path.string(), options);
  ASSERT_TRUE(from_tf.ok()) << from_tf.error().message;
  EXPECT_EQ(from_tf->odom_topic, "/tf");
  EXPECT_EQ(from_tf->odom_frame, with_odom->odom_frame);
  EXPECT_EQ(from_tf->base_frame, with_odom->base_frame);
  ASSERT_EQ(from_tf->log.scans.size(), with_odom->log.scans.size());
  double worst_m = 0.0, worst_rad = 0.0;
  for (std::size_t k = 0; k < from_tf->log.scans.size(); ++k) {
    const Pose2 d = between(with_odom->log.scans[k].odometry, from_tf->log.scans[k].odometry);
    worst_m = std::max(worst_m, std::hypot(d.x, d.y));
    worst_rad = std::max(worst_rad, std::abs(d.theta));
  }
  EXPECT_LT(worst_m, 1e-9);
  EXPECT_LT(worst_rad, 1e-9);

  const auto ros1 = support::data_path("bags/ros1_neato_drive_square_demo.bag");
  TESSERA_REQUIRE_DATA(ros1);
  Result<RosBag> ros1_bag = read_ros_bag(ros1, read);
  ASSERT_TRUE(ros1_bag.ok()) << ros1_bag.error().message;
  Result<RobotBag> ros1_with_odom = robot_bag_from(*ros1_bag, ros1.string(), options);
  ASSERT_TRUE(ros1_with_odom.ok()) << ros1_with_odom.error().message;
  for (BagTopic& t : ros1_bag->topics) {
    if (t.name == "/odom") t.type = "nav_msgs/NotRecorded";
  }
  // Its /tf holds only the wheels' joints: no odometry at all, the scans alone; a base frame the
  // options name is placed by tf still.
  Result<RobotBag> none = robot_bag_from(*ros1_bag, ros1.string(), options);
  ASSERT_TRUE(none.ok()) << none.error().message;
  EXPECT_FALSE(none->log.has_odometry);
  EXPECT_EQ(none->base_frame, "base_laser_link");
  EXPECT_EQ(none->log.scans.size(), 404u);
  RobotBagOptions on_base = options;
  on_base.base_frame = "base_link";
  Result<RobotBag> placed = robot_bag_from(*ros1_bag, ros1.string(), on_base);
  ASSERT_TRUE(placed.ok()) << placed.error().message;
  EXPECT_FALSE(placed->log.has_odometry);
  const Pose2 d = between(ros1_with_odom->log.scans.front().laser_in_robot,
                          placed->log.scans.front().laser_in_robot);
  EXPECT_LT(std::hypot(d.x, d.y) + std::abs(d.theta), 1e-12);
  EXPECT_GT(std::abs(placed->log.scans.front().laser_in_robot.theta), 3.0);  // mounted backwards
  for (const StampedScan& scan : placed->log.scans) {
    EXPECT_EQ(std::hypot(scan.odometry.x, scan.odometry.y) + std::abs(scan.odometry.theta), 0.0);
  }
}

}  // namespace
}  // namespace tessera
