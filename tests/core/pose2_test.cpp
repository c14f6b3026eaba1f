#include "tessera/core/pose2.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

Pose2 random_pose(Rng& rng, double max_translation_m) {
  return {rng.uniform(-max_translation_m, max_translation_m),
          rng.uniform(-max_translation_m, max_translation_m),
          rng.uniform(-std::numbers::pi, std::numbers::pi)};
}

void expect_pose_near(const Pose2& a, const Pose2& b, double tol_m, double tol_rad) {
  EXPECT_NEAR(a.x, b.x, tol_m);
  EXPECT_NEAR(a.y, b.y, tol_m);
  EXPECT_NEAR(normalize_angle(a.theta - b.theta), 0.0, tol_rad);
}

TEST(NormalizeAngle, ResultIsAlwaysInHalfOpenRange) {
  Rng rng(3);
  for (int trial = 0; trial < 10000; ++trial) {
    const double a = rng.uniform(-100.0, 100.0);
    const double r = normalize_angle(a);
    EXPECT_GE(r, -std::numbers::pi);
    EXPECT_LT(r, std::numbers::pi);
    EXPECT_NEAR(std::remainder(a - r, 2.0 * std::numbers::pi), 0.0, 1e-9) << a;
  }
}

TEST(Pose2, QuarterTurnMapsXAxisOntoYAxis) {
  const Pose2 T_a_b{1.0, 2.0, std::numbers::pi / 2.0};
  const Vec2 p_a = T_a_b * Vec2{1.0, 0.0};
  EXPECT_NEAR(p_a.x, 1.0, 1e-12);
  EXPECT_NEAR(p_a.y, 3.0, 1e-12);
}

TEST(Pose2, InverseComposesToIdentity) {
  Rng rng(11);
  for (int trial = 0; trial < 1000; ++trial) {
    const Pose2 T = random_pose(rng, 50.0);
    expect_pose_near(T * T.inverse(), Pose2{}, 1e-9, 1e-12);
    expect_pose_near(T.inverse() * T, Pose2{}, 1e-9, 1e-12);
  }
}

TEST(Pose2, BetweenUndoesComposition) {
  Rng rng(7);
  for (int trial = 0; trial < 1000; ++trial) {
    const Pose2 T_w_a = random_pose(rng, 50.0);
    const Pose2 T_a_b = random_pose(rng, 5.0);
    expect_pose_near(between(T_w_a, T_w_a * T_a_b), T_a_b, 1e-9, 1e-12);
  }
}

TEST(Pose2, CompositionIsAssociative) {
  Rng rng(5);
  for (int trial = 0; trial < 1000; ++trial) {
    const Pose2 a = random_pose(rng, 10.0), b = random_pose(rng, 10.0), c = random_pose(rng, 10.0);
    expect_pose_near((a * b) * c, a * (b * c), 1e-9, 1e-12);
  }
}

}  // namespace
}  // namespace tessera
