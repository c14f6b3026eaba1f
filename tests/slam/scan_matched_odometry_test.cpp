#include "tessera/slam/scan_matched_odometry.hpp"

#include <gtest/gtest.h>

#include <cmath>

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

// Live, scan by scan: the same poses as the whole-log function until the first restart, and after
// restarts every 50 scans (the default is every 3,000) the poses go on without a jump and still
// follow the robot.
TEST(ScanMatchedOdometry, RestartsKeepThePosesGoing) {
  const SimulatedLaserRun& run = testing::office_run();
  LaserLog log = run.log;
  ASSERT_GT(log.scans.size(), 250U);
  log.scans.resize(250);  // five restarts
  Result<LaserLog> whole = with_scan_matched_odometry(log, testing::small_submaps());
  ASSERT_TRUE(whole.ok()) << whole.error().message;
  ScanMatchedOdometry live(testing::small_submaps(), 50);
  std::vector<StampedPose2> poses;
  for (const StampedScan& scan : log.scans) {
    Result<Pose2> pose = live.add(scan);
    ASSERT_TRUE(pose.ok()) << pose.error().message;
    poses.push_back({scan.t_s, *pose});
  }
  for (std::size_t i = 0; i < 50; ++i) {
    EXPECT_EQ(poses[i].pose.x, whole->scans[i].odometry.x);
    EXPECT_EQ(poses[i].pose.theta, whole->scans[i].odometry.theta);
  }
  double worst_step_difference_m = 0.0;
  for (std::size_t i = 1; i < poses.size(); ++i) {
    const Pose2 step = between(poses[i - 1].pose, poses[i].pose);
    const Pose2 whole_step = between(whole->scans[i - 1].odometry, whole->scans[i].odometry);
    worst_step_difference_m =
        std::max(worst_step_difference_m, std::hypot(step.x - whole_step.x, step.y - whole_step.y));
  }
  EXPECT_LT(worst_step_difference_m, 0.03);
  Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(poses, run.truth);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_LT(ate->trans_m.rmse, 0.15);
}

TEST(ScanMatchedOdometry, ALogWithoutScansIsAnInputError) {
  LaserLog empty;
  empty.has_odometry = false;
  Result<LaserLog> made = with_scan_matched_odometry(empty);
  ASSERT_FALSE(made.ok());
  EXPECT_EQ(made.error().kind, ErrorKind::kInput);
}

}  // namespace
}  // namespace tessera::slam
