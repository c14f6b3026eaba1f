#include "tessera/sensors/odometry_model.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace tessera {
namespace {

/// The true increment of a differential drive that drives `distance_m` along an arc turning by
/// `turn_rad` (a straight line when turn_rad is 0).
Pose2 arc_increment(double distance_m, double turn_rad) {
  if (turn_rad == 0.0) return {distance_m, 0.0, 0.0};
  const double r = distance_m / turn_rad;
  return {r * std::sin(turn_rad), r * (1.0 - std::cos(turn_rad)), turn_rad};
}

OdometryErrorOptions systematic_only() {
  OdometryErrorOptions o;
  o.rot_var_rad2_per_rad = 0.0;
  o.rot_var_rad2_per_m = 0.0;
  o.trans_var_m2_per_m = 0.0;
  o.trans_var_m2_per_rad = 0.0;
  return o;
}

TEST(OdometryModel, PerfectOdometryReportsTheTrueMotion) {
  Rng rng(1);
  const std::vector<Pose2> motions = {arc_increment(0.05, 0.0),  arc_increment(0.05, 0.02),
                                      arc_increment(0.05, -0.3), Pose2{0.0, 0.0, 0.1},
                                      Pose2{-0.04, 0.001, 0.01}, Pose2{0.0, 0.0, 0.0}};
  for (const Pose2& m : motions) {
    const Pose2 r = noisy_odometry_increment(m, perfect_odometry(), rng);
    EXPECT_NEAR(r.x, m.x, 1e-15);
    EXPECT_NEAR(r.y, m.y, 1e-15);
    EXPECT_NEAR(r.theta, m.theta, 1e-15);
  }
}

TEST(OdometryModel, SystematicScalesStretchDistanceAndTurn) {
  OdometryErrorOptions o = systematic_only();
  o.heading_drift_rad_per_m = 0.0;
  o.distance_scale_error = 0.02;
  o.rotation_scale_error = -0.1;
  Rng rng(1);
  const Pose2 straight = noisy_odometry_increment({0.5, 0.0, 0.0}, o, rng);
  EXPECT_DOUBLE_EQ(straight.x, 0.51);
  EXPECT_DOUBLE_EQ(straight.y, 0.0);
  EXPECT_DOUBLE_EQ(straight.theta, 0.0);
  const Pose2 turn = noisy_odometry_increment({0.0, 0.0, 1.0}, o, rng);
  EXPECT_DOUBLE_EQ(turn.x, 0.0);
  EXPECT_NEAR(turn.theta, 0.9, 1e-15);
  // Backwards: a negative distance, scaled the same way, not a half turn.
  const Pose2 back = noisy_odometry_increment({-0.5, 0.0, 0.0}, o, rng);
  EXPECT_DOUBLE_EQ(back.x, -0.51);
  EXPECT_DOUBLE_EQ(back.theta, 0.0);
}

// A turn on the spot measured as the motion between two poses leaves floating-point dust of
// translation (1e-17 m) pointing anywhere. Its direction is no rot1: the reading is the same as
// for a clean turn, not one whose noise grows with an arbitrary angle of up to 90 degrees
// (decision 0046 found 0.15-0.23 rad reported for 0.20 rad turned in 0.2 s).
TEST(OdometryModel, ATurnOnTheSpotReadsTheSameWhateverDustOfTranslationItCarries) {
  const OdometryErrorOptions o;
  int with_dust = 0;
  for (int k = 0; k < 40; ++k) {
    const Pose2 T_world_a{3.1 + 0.37 * k, -2.3 + 0.11 * k, -3.0 + 0.15 * k};
    const Pose2 T_a_b = between(T_world_a, T_world_a * Pose2{0.0, 0.0, 0.2});
    if (T_a_b.x != 0.0 || T_a_b.y != 0.0) ++with_dust;
    Rng dusty_rng(11), clean_rng(11);
    const Pose2 dusty = noisy_odometry_increment(T_a_b, o, dusty_rng);
    const Pose2 clean = noisy_odometry_increment({0.0, 0.0, T_a_b.theta}, o, clean_rng);
    EXPECT_NEAR(dusty.theta, clean.theta, 1e-12) << k;
    EXPECT_NEAR(dusty.x, clean.x, 1e-12) << k;
    EXPECT_NEAR(dusty.y, clean.y, 1e-12) << k;
  }
  EXPECT_GT(with_dust, 10);  // the case this test is about does occur
}

TEST(OdometryModel, HeadingDriftBendsAStraightDriveCounterClockwise) {
  OdometryErrorOptions o = systematic_only();
  o.distance_scale_error = 0.0;
  o.rotation_scale_error = 0.0;
  o.heading_drift_rad_per_m = 0.01;
  Rng rng(1);
  Pose2 odometry;
  for (int k = 0; k < 100; ++k)
    odometry = odometry * noisy_odometry_increment({0.01, 0, 0}, o, rng);
  EXPECT_NEAR(odometry.theta, 0.01, 1e-12);  // 1 m driven
  EXPECT_GT(odometry.y, 0.0);                // bent to the left
  EXPECT_NEAR(odometry.y, 0.005, 1e-4);      // a circle of radius 100 m: 1 / (2 * 100)
}

// The variances grow linearly with the motion, so the heading error of a drive does not depend on
// how finely it is split into increments (Thrun's squared terms would shrink with the step).
TEST(OdometryModel, HeadingVarianceGrowsLinearlyWithDistanceWhateverTheStepSize) {
  OdometryErrorOptions o = perfect_odometry();
  o.rot_var_rad2_per_m = 1e-3;
  const auto heading_variance = [&](double distance_m, int steps, std::uint64_t seed) {
    Rng rng(seed);
    constexpr int kTrials = 4000;
    double sum2 = 0.0;
    for (int t = 0; t < kTrials; ++t) {
      double heading = 0.0;
      for (int k = 0; k < steps; ++k) {
        heading += noisy_odometry_increment({distance_m / steps, 0.0, 0.0}, o, rng).theta;
      }
      sum2 += heading * heading;
    }
    return sum2 / kTrials;
  };
  // Expected: 1e-3 rad^2 per metre. 4000 trials: the estimate's relative stddev is sqrt(2/4000).
  EXPECT_NEAR(heading_variance(4.0, 1, 1), 4e-3, 4e-3 * 0.1);
  EXPECT_NEAR(heading_variance(4.0, 40, 2), 4e-3, 4e-3 * 0.1);
  EXPECT_NEAR(heading_variance(1.0, 40, 3), 1e-3, 1e-3 * 0.1);
}

TEST(OdometryModel, DistanceVarianceFollowsAlpha3AndAlpha4) {
  OdometryErrorOptions o = perfect_odometry();
  o.trans_var_m2_per_m = 2e-3;
  o.trans_var_m2_per_rad = 1e-3;
  Rng rng(5);
  constexpr int kTrials = 8000;
  double sum = 0.0, sum2 = 0.0;
  for (int t = 0; t < kTrials; ++t) {
    // 1 m along an arc of 0.5 rad: rot1 = rot2 = 0.25 rad.
    const Pose2 r = noisy_odometry_increment(arc_increment(1.0, 0.5), o, rng);
    const double d =
        std::hypot(r.x, r.y) - std::hypot(arc_increment(1.0, 0.5).x, arc_increment(1.0, 0.5).y);
    sum += d;
    sum2 += d * d;
  }
  const double chord = std::hypot(arc_increment(1.0, 0.5).x, arc_increment(1.0, 0.5).y);
  const double expected = 2e-3 * chord + 1e-3 * 0.5;
  EXPECT_NEAR(sum / kTrials, 0.0, 3.0 * std::sqrt(expected / kTrials));
  EXPECT_NEAR(sum2 / kTrials, expected, expected * 0.06);
}

TEST(OdometryModel, SameSeedSameReadings) {
  const OdometryErrorOptions o;
  Rng a(9), b(9);
  for (int k = 0; k < 50; ++k) {
    const Pose2 m = arc_increment(0.05, 0.01 * k - 0.2);
    const Pose2 ra = noisy_odometry_increment(m, o, a);
    const Pose2 rb = noisy_odometry_increment(m, o, b);
    EXPECT_EQ(ra.x, rb.x);
    EXPECT_EQ(ra.y, rb.y);
    EXPECT_EQ(ra.theta, rb.theta);
  }
}

TEST(OdometryModel, DefaultsAreValidAndBadValuesNameTheField) {
  EXPECT_FALSE(validate(OdometryErrorOptions{}).has_value());
  EXPECT_FALSE(validate(perfect_odometry()).has_value());
  OdometryErrorOptions o;
  o.trans_var_m2_per_m = -1e-4;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("trans_var_m2_per_m must be >= 0"));
  o = {};
  o.distance_scale_error = 0.7;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("distance_scale_error"));
  o = {};
  o.rotation_scale_error = std::nan("");
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("rotation_scale_error"));
  o = {};
  o.heading_drift_rad_per_m = std::numeric_limits<double>::infinity();
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("heading_drift_rad_per_m"));
  o = {};
  o.rot_var_rad2_per_rad = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("rot_var_rad2_per_rad"));
}

}  // namespace
}  // namespace tessera
