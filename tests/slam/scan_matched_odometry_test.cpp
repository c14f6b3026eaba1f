#include "tessera/slam/scan_matched_odometry.hpp"

#include <gtest/gtest.h>

#include "laser_test_world.hpp"
#include "office_run.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/eval/trajectory_error.hpp"

namespace tessera::slam {
namespace {

// A log without odometry gets local SLAM's poses as its odometry: what the localizer and a
// resumed session need between scans. Its own odometry fields are not read.
TEST(ScanMatchedOdometry, IsLocalSlamAloneAndIgnoresTheLogsOwnOdometry) {
  const SimulatedLaserRun& run = testing::office_run();
  LaserLog log = run.log;
  Rng scatter(11);
  for (StampedScan& s : log.scans) {
    s.odometry = Pose2{scatter.uniform(-3.0, 3.0), scatter.uniform(-3.0, 3.0), 0.0};
  }
  log.has_odometry = false;
  log.odometry.clear();
  Result<LaserLog> made = with_scan_matched_odometry(log, testing::small_submaps());
  ASSERT_TRUE(made.ok()) << made.error().message;
  EXPECT_TRUE(made->has_odometry);
  ASSERT_EQ(made->scans.size(), log.scans.size());
  ASSERT_EQ(made->odometry.size(), log.scans.size());
  std::vector<StampedPose2> odometry;
  for (std::size_t i = 0; i < made->scans.size(); ++i) {
    const StampedScan& s = made->scans[i];
    odometry.push_back({s.t_s, s.odometry});
    EXPECT_EQ(made->odometry[i].t_s, s.t_s);
    EXPECT_EQ(made->odometry[i].pose.x, s.odometry.x);
  }
  EXPECT_EQ(odometry.front().pose.x, 0.0);  // the first scan's frame
  EXPECT_EQ(odometry.front().pose.y, 0.0);
  // Local SLAM over a 70 s loop: near the truth, well within what the simulated wheels drift.
  Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(odometry, run.truth);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_LT(ate->trans_m.rmse, 0.1);
}

}  // namespace
}  // namespace tessera::slam
