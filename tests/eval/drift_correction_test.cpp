#include "tessera/eval/drift_correction.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tessera {
namespace {

using ::testing::HasSubstr;

/// A circle of radius 2 m, one pose per second.
std::vector<StampedPose2> circle(int poses) {
  std::vector<StampedPose2> out;
  for (int i = 0; i < poses; ++i) {
    const double a = 0.3 * i;
    out.push_back({static_cast<double>(i), Pose2{2.0 * std::cos(a), 2.0 * std::sin(a), a}});
  }
  return out;
}

/// `truth` with a sideways error of +-error_m, alternating.
std::vector<StampedPose2> wobbled(std::vector<StampedPose2> truth, double error_m) {
  for (std::size_t i = 0; i < truth.size(); ++i) truth[i].pose.y += (i % 2 == 0 ? 1 : -1) * error_m;
  return truth;
}

TEST(DriftCorrection, ScoresSlamAndOdometryAgainstTheSameTruthAndGivesTheirRatio) {
  const std::vector<StampedPose2> truth = circle(20);
  const Result<DriftCorrectionScore> s =
      score_drift_correction(wobbled(truth, 0.01), wobbled(truth, 0.1), truth);
  ASSERT_TRUE(s) << s.error().message;
  EXPECT_EQ(s->slam.trans_m.count, 20u);
  EXPECT_LT(s->slam.trans_m.rmse, 0.0101);
  EXPECT_GT(s->odometry.trans_m.rmse, 0.05);
  EXPECT_FALSE(s->local.has_value());
  EXPECT_NEAR(s->odometry_over_slam(), s->odometry.trans_m.rmse / s->slam.trans_m.rmse, 1e-12);
  EXPECT_GT(s->odometry_over_slam(), 5.0);
}

TEST(DriftCorrection, ScoresTheLocalTrajectoryWhenGiven) {
  const std::vector<StampedPose2> truth = circle(10);
  const std::vector<StampedPose2> local = wobbled(truth, 0.05);
  const Result<DriftCorrectionScore> s =
      score_drift_correction(truth, wobbled(truth, 0.1), truth, &local);
  ASSERT_TRUE(s) << s.error().message;
  ASSERT_TRUE(s->local.has_value());
  EXPECT_GT(s->local->trans_m.rmse, 0.02);
  EXPECT_NEAR(s->slam.trans_m.rmse, 0.0, 1e-9);
}

TEST(DriftCorrection, ATrajectoryThatDoesNotOverlapTheTruthIsAnError) {
  const std::vector<StampedPose2> truth = circle(10);
  std::vector<StampedPose2> late = truth;
  for (StampedPose2& p : late) p.t_s += 100.0;
  EXPECT_FALSE(score_drift_correction(truth, late, truth));
  EXPECT_FALSE(score_drift_correction(late, truth, truth));
  const Result<DriftCorrectionScore> s = score_drift_correction(truth, truth, truth, &late);
  ASSERT_FALSE(s);
  EXPECT_THAT(s.error().message, HasSubstr("estimate stamps"));
}

}  // namespace
}  // namespace tessera
