// record_laser_slam on a simulated run: one scan, odometry and tf message per scan at the scan's
// stamp, the mounting once, the map and path at the end.
#include "tessera/record/slam_recording.hpp"

#include <gtest/gtest.h>

#include "recording_sink.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/record/ros_conversions.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera {
namespace {

TEST(SlamRecording, OneScanOdometryAndPosePerScanThenMapAndPath) {
  const World world = builtin_world("office", 0.05);
  LaserRunOptions run_options;
  run_options.max_duration_s = 10.0;
  Result<SimulatedLaserRun> run = simulate_laser_run(world, run_options, 3);
  ASSERT_TRUE(run.ok()) << run.error().message;
  Result<slam::LaserSlamResult> slam = slam::run_laser_slam(run->log, {});
  ASSERT_TRUE(slam.ok()) << slam.error().message;
  test::RecordingSink sink;
  ASSERT_TRUE(record_laser_slam(sink, run->log, *slam));

  const std::size_t scans = run->log.scans.size();
  ASSERT_GT(scans, 10U);
  EXPECT_EQ(sink.on("/scan").size(), scans);
  EXPECT_EQ(sink.on("/odom").size(), scans);
  EXPECT_EQ(sink.on("/tf").size(), scans);
  EXPECT_EQ(sink.on("/tf_static").size(), 1U);
  EXPECT_EQ(sink.on("/map").size(), 1U);
  EXPECT_EQ(sink.on("/path").size(), 1U);

  const std::size_t k = scans / 2;
  const auto scan_msg = sink.on("/scan")[k];
  EXPECT_EQ(scan_msg->t_ns, to_ns(run->log.scans[k].t_s));
  Result<LaserScanMessage> scan = decode_laser_scan(scan_msg->cdr, RosEncoding::kCdr);
  ASSERT_TRUE(scan.ok());
  EXPECT_EQ(scan->ranges_m.size(), run->log.scans[k].scan.ranges_m.size());
  Result<TfMessage> tf = decode_tf_message(sink.on("/tf")[k]->cdr, RosEncoding::kCdr);
  ASSERT_TRUE(tf.ok());
  EXPECT_EQ(tf->transforms[0].header.frame_id, "map");
  EXPECT_DOUBLE_EQ(tf->transforms[0].transform.x_m, slam->trajectory[k].pose.x);
  Result<OdometryMessage> odom = decode_odometry(sink.on("/odom")[k]->cdr, RosEncoding::kCdr);
  ASSERT_TRUE(odom.ok());
  EXPECT_DOUBLE_EQ(odom->pose.x_m, run->log.scans[k].odometry.x);
}

}  // namespace
}  // namespace tessera
