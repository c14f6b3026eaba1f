#include "tessera/sensors/wheel_encoders.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

constexpr double kCellM = 0.22;
constexpr double kHalfPi = 0.5 * std::numbers::pi;

TEST(WheelEncoders, PerfectEncodersReproduceAForwardCellAndAQuarterTurn) {
  WheelEncoderOptions o;
  o.scale_error_stddev = 0.0;
  o.tick_noise_stddev = 0.0;
  Rng rng(1);
  const WheelEncoders enc(o, rng);
  const Pose2 fwd = enc.measure(forward_travel(kCellM), rng);
  EXPECT_NEAR(fwd.x, kCellM, 1e-5);  // one tick is 10 micrometres
  EXPECT_NEAR(fwd.y, 0.0, 1e-12);
  EXPECT_NEAR(fwd.theta, 0.0, 1e-12);
  const Pose2 turn = enc.measure(turn_travel(kHalfPi, o), rng);
  EXPECT_NEAR(turn.x, 0.0, 1e-9);
  EXPECT_NEAR(turn.theta, kHalfPi, 1e-4);
}

TEST(WheelEncoders, PoseIncrementFollowsACircularArc) {
  // Quarter circle of radius 0.5 m: the chord ends at (0.5, 0.5).
  const double w = 0.12;
  const double r = 0.5;
  const Pose2 p = pose_increment({(r - w / 2) * kHalfPi, (r + w / 2) * kHalfPi}, w);
  EXPECT_NEAR(p.x, r, 1e-12);
  EXPECT_NEAR(p.y, r, 1e-12);
  EXPECT_NEAR(p.theta, kHalfPi, 1e-12);
}

// Dead reckoning over n forward cells: position error of the believed end pose.
double drift_after(int cells, std::uint64_t seed) {
  Rng rng(seed);
  const WheelEncoders enc(WheelEncoderOptions{}, rng);
  Pose2 truth, belief;
  for (int i = 0; i < cells; ++i) {
    truth = truth * Pose2{kCellM, 0.0, 0.0};
    belief = belief * enc.measure(forward_travel(kCellM), rng);
  }
  return std::hypot(truth.x - belief.x, truth.y - belief.y);
}

TEST(WheelEncoders, ErrorGrowsWithDistanceTravelled) {
  double prev = 0.0;
  for (int cells : {1, 4, 16, 64}) {
    double sum = 0.0;
    for (std::uint64_t seed = 0; seed < 200; ++seed) sum += drift_after(cells, seed);
    const double mean = sum / 200.0;
    EXPECT_GT(mean, prev * 1.5) << cells << " cells";
    prev = mean;
  }
}

TEST(WheelEncoders, SameSeedGivesTheSameDrift) {
  for (std::uint64_t seed : {3u, 17u, 99u}) EXPECT_EQ(drift_after(20, seed), drift_after(20, seed));
  EXPECT_NE(drift_after(20, 3), drift_after(20, 4));
}

TEST(WheelEncoders, TurnsAccumulateHeadingError) {
  double sum1 = 0.0, sum8 = 0.0;
  for (std::uint64_t seed = 0; seed < 200; ++seed) {
    Rng rng(seed);
    const WheelEncoderOptions o;
    const WheelEncoders enc(o, rng);
    double heading = 0.0;
    for (int i = 0; i < 8; ++i) {
      heading += enc.measure(turn_travel(kHalfPi, o), rng).theta;
      if (i == 0) sum1 += std::abs(heading - kHalfPi);
    }
    sum8 += std::abs(heading - 8 * kHalfPi);
  }
  EXPECT_GT(sum8, 3.0 * sum1);
}

TEST(WheelEncoders, ValidateNamesTheBadField) {
  WheelEncoderOptions o;
  EXPECT_FALSE(validate(o).has_value());
  o.track_width_m = 0.0;
  ASSERT_TRUE(validate(o).has_value());
  EXPECT_NE(validate(o)->find("track_width_m"), std::string::npos);
}

}  // namespace
}  // namespace tessera
