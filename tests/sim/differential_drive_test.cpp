#include "tessera/sim/differential_drive.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tessera/sensors/thesis_odometry.hpp"

namespace tessera {
namespace {

TEST(ArcMotion, StraightArcAndFullCircle) {
  const Pose2 straight = arc_motion(0.5, 0.0, 2.0);
  EXPECT_DOUBLE_EQ(straight.x, 1.0);
  EXPECT_DOUBLE_EQ(straight.y, 0.0);
  // A quarter circle of radius 1 m to the left.
  const Pose2 q = arc_motion(1.0, 1.0, 0.5 * std::numbers::pi);
  EXPECT_NEAR(q.x, 1.0, 1e-12);
  EXPECT_NEAR(q.y, 1.0, 1e-12);
  EXPECT_NEAR(q.theta, 0.5 * std::numbers::pi, 1e-12);
  // Turning in place.
  const Pose2 spin = arc_motion(0.0, -0.5, 1.0);
  EXPECT_DOUBLE_EQ(spin.x, 0.0);
  EXPECT_DOUBLE_EQ(spin.y, 0.0);
  EXPECT_DOUBLE_EQ(spin.theta, -0.5);
}

TEST(ArcMotion, ComposingSmallStepsGivesTheSameArc) {
  Pose2 p;
  for (int k = 0; k < 1000; ++k) p = p * arc_motion(0.4, 0.3, 0.01);
  const Pose2 once = arc_motion(0.4, 0.3, 10.0);
  EXPECT_NEAR(p.x, once.x, 1e-9);
  EXPECT_NEAR(p.y, once.y, 1e-9);
  EXPECT_NEAR(p.theta, once.theta, 1e-9);
  // Tiny turn rates on either side of the switch to the series form: y = v w dt^2 / 2.
  const Pose2 a = arc_motion(1.0, 0.99e-6, 1.0), b = arc_motion(1.0, 1.01e-6, 1.0);
  EXPECT_NEAR(a.y, 0.495e-6, 1e-12);
  EXPECT_NEAR(b.y, 0.505e-6, 1e-12);
}

TEST(DifferentialDriveRobot, PerfectOdometryFollowsTheTruth) {
  DifferentialDriveRobot robot({1.0, 2.0, 0.5}, perfect_odometry(), Rng(1));
  for (int k = 0; k < 200; ++k) (void)robot.step(0.3, k < 100 ? 0.2 : -0.4, 0.05);
  EXPECT_NEAR(robot.odometry_pose().x, robot.true_pose().x, 1e-12);
  EXPECT_NEAR(robot.odometry_pose().y, robot.true_pose().y, 1e-12);
  EXPECT_NEAR(robot.odometry_pose().theta, robot.true_pose().theta, 1e-12);
  EXPECT_NEAR(robot.path_length_m(), 200 * 0.3 * 0.05, 1e-12);
  EXPECT_NEAR(robot.turned_rad(), 100 * 0.05 * 0.6, 1e-12);
}

TEST(DifferentialDriveRobot, StepsReportTheTrueAndTheOdometryIncrement) {
  DifferentialDriveRobot robot({0.0, 0.0, 0.0}, thesis_fusion_odometry(), Rng(4));
  const Pose2 before_truth = robot.true_pose(), before_odom = robot.odometry_pose();
  const DriveStep s = robot.step(0.3, 0.1, 0.1);
  const Pose2 t = before_truth * s.true_increment, o = before_odom * s.odometry_increment;
  EXPECT_NEAR(t.x, robot.true_pose().x, 1e-15);
  EXPECT_NEAR(o.x, robot.odometry_pose().x, 1e-15);
  EXPECT_NEAR(o.y, robot.odometry_pose().y, 1e-15);
  // With the thesis' drift, odometry under-reads the distance.
  EXPECT_NE(s.odometry_increment.x, s.true_increment.x);
}

}  // namespace
}  // namespace tessera
