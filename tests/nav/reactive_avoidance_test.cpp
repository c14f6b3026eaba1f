#include "tessera/nav/reactive_avoidance.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace tessera {
namespace {

constexpr VelocityCommand kCruise{0.3, 0.05};

TEST(ReactiveAvoidance, NothingInRangePassesTheNavigationCommandThrough) {
  ReactiveAvoidance a;
  ObstacleSensing s;
  s.sonar = {{0.0, 1.01}, {0.5, 3.0}, {-0.5, 0.0} /* no echo */};
  s.depth = {{0.0, 0.61}, {0.2, std::numeric_limits<double>::quiet_NaN()}};
  const VelocityCommand c = a.filter(s, kCruise, 0.1);
  EXPECT_EQ(c.v_m_per_s, kCruise.v_m_per_s);
  EXPECT_EQ(c.omega_rad_per_s, kCruise.omega_rad_per_s);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
}

TEST(ReactiveAvoidance, SonarWithinOneMetreTurnsAwayAtThreeTenthsRadianPerSecond) {
  ReactiveAvoidance a;
  ObstacleSensing s;
  s.sonar = {{0.6, 0.9}, {-0.6, 2.0}};  // closest on the left
  const VelocityCommand c = a.filter(s, kCruise, 0.1);
  EXPECT_DOUBLE_EQ(c.omega_rad_per_s, -0.3);  // clockwise, away from the left
  EXPECT_DOUBLE_EQ(c.v_m_per_s, 0.1);         // slowed, still moving
  EXPECT_EQ(a.last_action(), AvoidanceAction::kTurnAwayFar);
  s.sonar = {{-0.3, 0.7}};  // on the right
  EXPECT_DOUBLE_EQ(a.filter(s, kCruise, 0.1).omega_rad_per_s, 0.3);
}

TEST(ReactiveAvoidance, DepthCountsOnlyWithinSixTenthsAndWithinFourTenthsTurnsFasterInPlace) {
  ReactiveAvoidance a;
  ObstacleSensing s;
  s.depth = {{0.1, 0.65}};
  (void)a.filter(s, kCruise, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);  // 0.65 m: beyond the Kinect's 0.6
  s.depth = {{0.1, 0.55}};
  EXPECT_DOUBLE_EQ(a.filter(s, kCruise, 0.1).omega_rad_per_s, -0.3);
  s.depth = {{0.1, 0.35}};
  const VelocityCommand near = a.filter(s, kCruise, 0.1);
  EXPECT_DOUBLE_EQ(near.omega_rad_per_s, -0.5);
  EXPECT_DOUBLE_EQ(near.v_m_per_s, 0.0);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kTurnAwayNear);
  // The closest of sonar and depth decides the side: a depth hit on the right at 0.3 m beats a
  // sonar echo on the left at 0.8 m.
  s.sonar = {{0.8, 0.8}};
  s.depth = {{-0.2, 0.3}};
  EXPECT_DOUBLE_EQ(a.filter(s, kCruise, 0.1).omega_rad_per_s, 0.5);
}

TEST(ReactiveAvoidance, ObstaclesBehindTheSideDoNotTurnTheRobot) {
  ReactiveAvoidance a;
  ObstacleSensing s;
  s.sonar = {{2.5, 0.3}};  // behind-left
  (void)a.filter(s, kCruise, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
}

// Ours: with a strip half-width, a wall beside a corridor does not turn the robot, an obstacle in
// the strip ahead does (thesis' rule: both do).
TEST(ReactiveAvoidance, WithAPathStripOnlyObstaclesInTheStripAheadTurnTheRobot) {
  ObstacleSensing wall_beside;
  wall_beside.sonar = {{1.5708, 0.15}, {0.8727, 0.35}};  // a wall 0.35 m to the left
  ReactiveAvoidance thesis;
  (void)thesis.filter(wall_beside, kCruise, 0.1);
  EXPECT_EQ(thesis.last_action(), AvoidanceAction::kTurnAwayNear);

  ReactiveAvoidanceOptions o;
  o.path_half_width_m = 0.3;
  o.sensor_radius_m = 0.2;
  ReactiveAvoidance ours(o);
  EXPECT_EQ(ours.filter(wall_beside, kCruise, 0.1).v_m_per_s, kCruise.v_m_per_s);
  EXPECT_EQ(ours.last_action(), AvoidanceAction::kPassThrough);

  ObstacleSensing box_ahead = wall_beside;
  box_ahead.sonar.push_back({-0.1745, 0.7});  // 0.9 m from the centre, 0.16 m right of its line
  const VelocityCommand c = ours.filter(box_ahead, kCruise, 0.1);
  EXPECT_EQ(ours.last_action(), AvoidanceAction::kTurnAwayFar);
  EXPECT_DOUBLE_EQ(c.omega_rad_per_s, 0.3);  // away from the right
  o.path_half_width_m = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("path_half_width_m"));
}

// Ours: the strip follows the arc the navigation command drives, and turning in place sweeps
// nothing (a disc can always turn).
TEST(ReactiveAvoidance, TheStripFollowsTheCommandedArc) {
  ReactiveAvoidanceOptions o;
  o.path_half_width_m = 0.3;
  ObstacleSensing ahead;
  ahead.sonar = {{0.0, 0.5}};  // dead ahead
  ReactiveAvoidance a(o);
  (void)a.filter(ahead, {0.0, 0.5}, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
  // 0.58 m ahead and 0.445 m to the left: off a straight strip, on a left turn of radius 0.6 m
  // (75 degrees along it).
  ObstacleSensing left;
  left.sonar = {{std::atan2(0.445, 0.58), std::hypot(0.58, 0.445)}};
  (void)a.filter(left, {0.3, 0.0}, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
  (void)a.filter(left, {0.3, 0.5}, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kTurnAwayFar);
}

// Ours: after a turn away the robot goes straight on, then may not turn back towards the obstacle
// while it is still beside it.
TEST(ReactiveAvoidance, AfterATurnAwayTheRobotGoesOnPastTheObstacleBeforeTurningBack) {
  ReactiveAvoidanceOptions o;
  o.path_half_width_m = 0.35;
  o.sensor_radius_m = 0.2;
  o.straight_after_turn_s = 1.0;
  ReactiveAvoidance a(o);
  ObstacleSensing box_ahead_right;
  box_ahead_right.sonar = {{-0.17, 0.6}};
  EXPECT_DOUBLE_EQ(a.filter(box_ahead_right, kCruise, 0.1).omega_rad_per_s, 0.3);  // turn left
  const VelocityCommand back_right{0.2, -0.5};  // the navigation turns back towards the box
  ObstacleSensing clear;
  for (int k = 0; k < 9; ++k) {  // 1 s at 0.1 s a call (the 10th call ends it)
    const VelocityCommand c = a.filter(clear, back_right, 0.1);
    EXPECT_EQ(a.last_action(), AvoidanceAction::kStraightOn) << k;
    EXPECT_DOUBLE_EQ(c.v_m_per_s, 0.1);
    EXPECT_DOUBLE_EQ(c.omega_rad_per_s, 0.0);
  }
  ObstacleSensing beside_right;
  beside_right.sonar = {{-1.5708, 0.2}};
  (void)a.filter(beside_right, back_right, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kStraightOn);                 // still beside: not yet
  EXPECT_EQ(a.filter(beside_right, {0.2, 0.4}, 0.1).omega_rad_per_s, 0.4);  // away: allowed
  EXPECT_EQ(a.filter(clear, back_right, 0.1).omega_rad_per_s, -0.5);        // past it: turn back
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
}

TEST(ReactiveAvoidance, BumperHitBacksOffAndTurnsHarderTheMoreCentralTheHit) {
  ReactiveAvoidance a;
  ObstacleSensing s;
  s.bumpers.front[0] = true;  // left-most
  VelocityCommand c = a.filter(s, kCruise, 0.1);
  EXPECT_DOUBLE_EQ(c.v_m_per_s, -0.1);
  EXPECT_DOUBLE_EQ(c.omega_rad_per_s, -0.1);  // away from the left, 0.1 rad/s x 1
  EXPECT_EQ(a.last_action(), AvoidanceAction::kBumperEscape);
  s.bumpers.front = {};
  s.bumpers.front[3] = true;  // right of centre
  c = a.filter(s, kCruise, 0.1);
  EXPECT_DOUBLE_EQ(c.omega_rad_per_s, 0.2);
  s.bumpers.front = {};
  s.bumpers.front[2] = true;  // centre
  c = a.filter(s, kCruise, 0.1);
  EXPECT_NEAR(c.omega_rad_per_s, 0.3, 1e-12);
  // Bumpers win over a sonar obstacle in the same cycle.
  s.sonar = {{0.0, 0.2}};
  (void)a.filter(s, kCruise, 0.1);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kBumperEscape);
  // A rear hit drives forward.
  s = {};
  s.bumpers.rear[4] = true;
  c = a.filter(s, kCruise, 0.1);
  EXPECT_DOUBLE_EQ(c.v_m_per_s, 0.1);
  EXPECT_DOUBLE_EQ(c.omega_rad_per_s, 0.1);
}

TEST(ReactiveAvoidance, KeepsBackingOffForTheBackoffDurationAfterTheBumperReleases) {
  ReactiveAvoidanceOptions o;
  o.backoff_duration_s = 0.5;
  ReactiveAvoidance a(o);
  ObstacleSensing hit;
  hit.bumpers.front[4] = true;
  const VelocityCommand escape = a.filter(hit, kCruise, 0.1);
  const ObstacleSensing clear;
  for (int i = 0; i < 5; ++i) {
    const VelocityCommand c = a.filter(clear, kCruise, 0.1);
    EXPECT_EQ(c.v_m_per_s, escape.v_m_per_s) << i;
    EXPECT_EQ(c.omega_rad_per_s, escape.omega_rad_per_s) << i;
  }
  const VelocityCommand after = a.filter(clear, kCruise, 0.1);
  EXPECT_EQ(after.v_m_per_s, kCruise.v_m_per_s);
  EXPECT_EQ(a.last_action(), AvoidanceAction::kPassThrough);
}

TEST(ReactiveAvoidanceOptions, ValidateNamesTheBadField) {
  EXPECT_FALSE(validate(ReactiveAvoidanceOptions{}).has_value());
  ReactiveAvoidanceOptions o;
  o.sonar_range_m = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("sonar_range_m"));
  o = {};
  o.backoff_duration_s = -0.1;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("backoff_duration_s"));
}

}  // namespace
}  // namespace tessera
