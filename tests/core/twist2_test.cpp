// Twist2: the arc a constant velocity drives, and the velocity that drives a given motion.
#include "tessera/core/twist2.hpp"

#include <gtest/gtest.h>

#include <numbers>

namespace tessera {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(Twist2, AConstantVelocityDrivesAnArc) {
  // 1 m/s forward turning at pi/2 rad/s: a quarter circle of radius 2/pi.
  const Pose2 quarter = displacement({1.0, 0.0, kPi / 2.0}, 1.0);
  EXPECT_NEAR(quarter.x, 2.0 / kPi, 1e-12);
  EXPECT_NEAR(quarter.y, 2.0 / kPi, 1e-12);
  EXPECT_NEAR(quarter.theta, kPi / 2.0, 1e-12);
  // Straight ahead and sideways without turning; a turn on the spot stays put.
  const Pose2 straight = displacement({0.5, -0.2, 0.0}, 2.0);
  EXPECT_NEAR(straight.x, 1.0, 1e-12);
  EXPECT_NEAR(straight.y, -0.4, 1e-12);
  const Pose2 spin = displacement({0.0, 0.0, -1.0}, 0.3);
  EXPECT_NEAR(spin.x, 0.0, 1e-12);
  EXPECT_NEAR(spin.theta, -0.3, 1e-12);
}

TEST(Twist2, TheVelocityBetweenTwoPosesDrivesFromOneToTheOther) {
  for (const Pose2& motion : {Pose2{0.3, 0.1, 0.4}, Pose2{-0.2, 0.05, -1.2}, Pose2{0.1, 0.0, 0.0},
                              Pose2{0.0, 0.0, 0.2}}) {
    const Twist2 v = velocity_between(motion, 0.2);
    const Pose2 back = displacement(v, 0.2);
    EXPECT_NEAR(back.x, motion.x, 1e-12);
    EXPECT_NEAR(back.y, motion.y, 1e-12);
    EXPECT_NEAR(back.theta, motion.theta, 1e-12);
  }
  EXPECT_TRUE(Twist2{}.is_zero());
  EXPECT_FALSE(velocity_between({0.0, 0.0, 0.1}, 1.0).is_zero());
}

}  // namespace
}  // namespace tessera
