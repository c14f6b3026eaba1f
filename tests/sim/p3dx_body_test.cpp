#include "tessera/sim/p3dx_body.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

// A 3 x 2 m room, walls one 5 cm cell thick: the free space is x in [0.05, 2.95].
World room() { return walled_room(60, 40, 0.05, "room"); }

P3dxBodyOptions noiseless() {
  P3dxBodyOptions o;
  o.sonar_noise_m = 0.0;
  return o;
}

TEST(P3dxBody, ASonarReadsTheNearestEchoInItsConeFromItsMount) {
  const World w = room();
  const P3dxBodyOptions o = noiseless();
  Rng rng(1);
  const Pose2 robot{2.25, 1.0, 0.0};  // 0.7 m from the wall ahead
  const ObstacleSensing s = sense_p3dx(w, robot, o, rng);
  ASSERT_EQ(s.sonar.size(), 8u);
  for (const ObstacleRange& r : s.sonar) {
    if (std::abs(r.bearing_rad) > 0.2) continue;  // the two front sonars (+-10 degrees)
    // The cone's ray nearest the wall's normal decides: from the mount, at bearing - half cone.
    const double mount_x = robot.x + o.sonar_radius_m * std::cos(r.bearing_rad);
    const double expected = (2.95 - mount_x) / std::cos(std::abs(r.bearing_rad) - 0.13);
    EXPECT_NEAR(r.range_m, expected, 1e-9) << r.bearing_rad;
  }
  for (bool b : s.bumpers.front) EXPECT_FALSE(b);
  for (bool b : s.bumpers.rear) EXPECT_FALSE(b);
}

TEST(P3dxBody, TheBumperFacingTheContactIsPressedFrontOrRear) {
  const World w = room();
  const P3dxBodyOptions o = noiseless();
  Rng rng(1);
  const ObstacleSensing front = sense_p3dx(w, {2.95 - 0.265, 1.0, 0.0}, o, rng);
  EXPECT_THAT(front.bumpers.front, ::testing::ElementsAre(false, false, true, false, false));
  EXPECT_THAT(front.bumpers.rear, ::testing::Each(false));
  // Facing away from the wall: the wall touches the rear ring's centre bumper.
  const ObstacleSensing rear = sense_p3dx(w, {2.95 - 0.265, 1.0, std::numbers::pi}, o, rng);
  EXPECT_THAT(rear.bumpers.front, ::testing::Each(false));
  EXPECT_THAT(rear.bumpers.rear, ::testing::ElementsAre(false, false, true, false, false));
  // Turned 60 degrees left of a wall ahead: the wall is at -60 degrees, the right-most bumper's.
  const ObstacleSensing right = sense_p3dx(w, {2.95 - 0.265, 1.0, 1.0472}, o, rng);
  EXPECT_THAT(right.bumpers.front, ::testing::ElementsAre(false, false, false, false, true));
  // A wall brushing the robot's flank (at 90 degrees) presses no bumper.
  const ObstacleSensing flank = sense_p3dx(w, {1.5, 1.95 - 0.26, 0.0}, o, rng);
  EXPECT_THAT(flank.bumpers.front, ::testing::Each(false));
  EXPECT_THAT(flank.bumpers.rear, ::testing::Each(false));
}

TEST(P3dxBody, TheBodyStopsAgainstAWallButCanBackAwayAndTurn) {
  const World w = room();
  const Pose2 touching{2.95 - 0.26, 1.0, 0.0};
  const Pose2 into{2.95 - 0.23, 1.0, 0.1};
  const Pose2 stopped = blocked_motion(w, touching, into, 0.25);
  EXPECT_DOUBLE_EQ(stopped.x, touching.x);
  EXPECT_DOUBLE_EQ(stopped.theta, 0.1);  // turned in place
  const Pose2 away{2.95 - 0.3, 1.0, 0.0};
  EXPECT_DOUBLE_EQ(blocked_motion(w, touching, away, 0.25).x, away.x);
  EXPECT_TRUE(body_overlaps(w, {into.x, into.y}, 0.25));
  EXPECT_FALSE(body_overlaps(w, {touching.x, touching.y}, 0.25));
}

TEST(P3dxBody, ValidateNamesTheBadField) {
  EXPECT_FALSE(validate(P3dxBodyOptions{}).has_value());
  P3dxBodyOptions o;
  o.sonar_radius_m = 0.3;  // beyond the body
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("sonar_radius_m"));
  o = {};
  o.sonar_rays = 0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("sonar_rays"));
}

}  // namespace
}  // namespace tessera
