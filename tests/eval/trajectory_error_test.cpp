#include "tessera/eval/trajectory_error.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "support/data.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/io/tum_trajectory.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

Eigen::Isometry3d some_rigid_motion() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1.0, -2.0, 0.5).normalized()).matrix();
  T.translation() = Eigen::Vector3d(3.0, -1.5, 0.25);
  return T;
}

StampedPose3 moved(const Eigen::Isometry3d& T, const StampedPose3& p) {
  return {p.t_s, T * p.position_m, Eigen::Quaterniond(T.linear()) * p.orientation};
}

/// A wiggly 3D trajectory at `rate_hz` over `duration_s`.
std::vector<StampedPose3> wiggly(double rate_hz, double duration_s) {
  std::vector<StampedPose3> poses;
  for (int k = 0; k <= static_cast<int>(duration_s * rate_hz); ++k) {
    const double t = k / rate_hz;
    poses.push_back({t, Eigen::Vector3d(std::cos(t), std::sin(1.5 * t), 0.2 * t),
                     Eigen::Quaterniond(Eigen::AngleAxisd(0.3 * t, Eigen::Vector3d::UnitZ()) *
                                        Eigen::AngleAxisd(0.1 * t, Eigen::Vector3d::UnitX()))});
  }
  return poses;
}

TEST(AssociateStamps, TakesTheSmallestDifferenceFirstAndEachStampOnce) {
  // (Binary-exact stamps.) Estimate 1.0 is 0.125 s from reference 0.875 and 0.0625 s from
  // reference 1.0625: the smaller difference wins and 0.875 stays unmatched.
  const std::vector<StampMatch> m = associate_stamps({0.875, 1.0625}, {1.0}, 0.25);
  ASSERT_EQ(m.size(), 1u);
  EXPECT_EQ(m[0].reference, 1u);
  EXPECT_EQ(m[0].estimate, 0u);
}

TEST(AssociateStamps, IsGreedyNotNearestPerReference) {
  // Estimate 0.1875 is the nearest to reference 0 (0.1875 s; -0.25 is 0.25 s away), but reference
  // 0.25 takes it first (0.0625 s); reference 0 then takes -0.25, as associate.py does.
  const std::vector<StampMatch> m = associate_stamps({0.0, 0.25}, {0.1875, -0.25}, 0.3);
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m[0].reference, 0u);
  EXPECT_EQ(m[0].estimate, 1u);
  EXPECT_EQ(m[1].reference, 1u);
  EXPECT_EQ(m[1].estimate, 0u);
}

TEST(AssociateStamps, MaxDifferenceIsExclusiveAndInputNeedNotBeSorted) {
  EXPECT_TRUE(associate_stamps({0.0}, {0.5}, 0.5).empty());
  EXPECT_EQ(associate_stamps({0.0}, {0.4375}, 0.5).size(), 1u);
  const std::vector<StampMatch> m = associate_stamps({3.0, 1.0, 2.0}, {2.0, 3.0, 1.0}, 0.01);
  ASSERT_EQ(m.size(), 3u);
  // Sorted by reference stamp: 1.0 (index 1), 2.0 (index 2), 3.0 (index 0).
  EXPECT_EQ(m[0].reference, 1u);
  EXPECT_EQ(m[0].estimate, 2u);
  EXPECT_EQ(m[1].reference, 2u);
  EXPECT_EQ(m[1].estimate, 0u);
  EXPECT_EQ(m[2].reference, 0u);
  EXPECT_EQ(m[2].estimate, 1u);
}

TEST(ErrorStatistics, MatchesNumpyDefinitions) {
  const ErrorStatistics s = error_statistics({3.0, 1.0, 4.0, 2.0});
  EXPECT_EQ(s.count, 4u);
  EXPECT_DOUBLE_EQ(s.mean, 2.5);
  EXPECT_DOUBLE_EQ(s.median, 2.5);  // mean of the two middle values
  EXPECT_DOUBLE_EQ(s.rmse, std::sqrt(30.0 / 4.0));
  EXPECT_DOUBLE_EQ(s.std, std::sqrt(1.25));  // population: divides by n
  EXPECT_DOUBLE_EQ(s.min, 1.0);
  EXPECT_DOUBLE_EQ(s.max, 4.0);
  EXPECT_DOUBLE_EQ(error_statistics({5.0, 1.0, 2.0}).median, 2.0);
}

TEST(AlignRigid, RecoversAKnownRotationAndTranslation) {
  const Eigen::Isometry3d T = some_rigid_motion();
  std::vector<Eigen::Vector3d> from, to;
  Rng rng(5);
  for (int i = 0; i < 20; ++i) {
    from.emplace_back(rng.uniform(-2, 2), rng.uniform(-2, 2), rng.uniform(-2, 2));
    to.push_back(T * from.back());
  }
  const Eigen::Isometry3d found = align_rigid(from, to);
  EXPECT_TRUE(found.matrix().isApprox(T.matrix(), 1e-12)) << found.matrix();
}

TEST(AlignRigid, ReturnsARotationEvenWhenAMirrorFitsBetter) {
  // `to` is the mirror image of `from` (z -> -z): the best orthogonal map is a reflection, which
  // the determinant correction (Umeyama 1991) must refuse.
  const std::vector<Eigen::Vector3d> from = {
      {1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {1, 1, 1}, {-1, 0.5, 2}};
  std::vector<Eigen::Vector3d> to;
  for (const auto& p : from) to.emplace_back(p.x(), p.y(), -p.z());
  const Eigen::Isometry3d found = align_rigid(from, to);
  EXPECT_NEAR(found.linear().determinant(), 1.0, 1e-12);
  EXPECT_TRUE((found.linear() * found.linear().transpose()).isIdentity(1e-12));
}

TEST(AbsoluteTrajectoryError, RigidlyMovedCopyOfTheReferenceScoresZero) {
  const std::vector<StampedPose3> reference = wiggly(10.0, 20.0);
  std::vector<StampedPose3> estimate;
  for (const StampedPose3& p : reference) estimate.push_back(moved(some_rigid_motion(), p));
  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(estimate, reference);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_EQ(ate->trans_m.count, reference.size());
  EXPECT_LT(ate->trans_m.rmse, 1e-9);
  EXPECT_LT(ate->trans_m.max, 1e-9);
  EXPECT_TRUE(
      ate->T_reference_estimate.matrix().isApprox(some_rigid_motion().inverse().matrix(), 1e-9));
}

TEST(AbsoluteTrajectoryError, OnePoseOffByAKnownVectorGivesAKnownRmse) {
  // Reference: the six points (+-1, 0, 0), (0, +-1, 0), (0, 0, +-1) and their centroid. The
  // estimate moves the centroid by d, |d| = 0.3 m. The best alignment is the identity rotation
  // (the cross-covariance stays symmetric positive definite) shifted by d/7, so the moved pose is
  // off by 6|d|/7 and the six others by |d|/7: RMSE = |d| sqrt(6)/7, mean = 12|d|/49.
  const std::vector<Eigen::Vector3d> points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0},
                                               {0, 0, 1}, {0, 0, -1}, {0, 0, 0}};
  std::vector<StampedPose3> reference, estimate;
  const Eigen::Vector3d d(0.1, -0.2, 0.2);  // |d| = 0.3
  for (std::size_t i = 0; i < points.size(); ++i) {
    const StampedPose3 p{static_cast<double>(i), points[i], Eigen::Quaterniond::Identity()};
    reference.push_back(p);
    StampedPose3 e = p;
    if (i == 6) e.position_m += d;
    estimate.push_back(moved(some_rigid_motion(), e));  // the frame must not matter
  }
  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(estimate, reference);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_EQ(ate->trans_m.count, 7u);
  EXPECT_NEAR(ate->trans_m.rmse, 0.3 * std::sqrt(6.0) / 7.0, 1e-12);
  EXPECT_NEAR(ate->trans_m.mean, 0.3 * 12.0 / 49.0, 1e-12);
  EXPECT_NEAR(ate->trans_m.max, 0.3 * 6.0 / 7.0, 1e-12);
  EXPECT_NEAR(ate->trans_m.median, 0.3 / 7.0, 1e-12);
}

TEST(AbsoluteTrajectoryError, OnlyAssociatedPosesCountAndDuplicateStampsKeepTheLastPose) {
  std::vector<StampedPose3> reference = wiggly(10.0, 5.0);
  std::vector<StampedPose3> estimate = reference;
  for (StampedPose3& p : estimate) p.t_s += 0.005;  // within 0.02 s
  StampedPose3 stray = estimate[3];
  stray.t_s = 100.0;  // no reference near it
  stray.position_m.x() += 50.0;
  estimate.push_back(stray);
  StampedPose3 overwritten = estimate[4];
  overwritten.position_m.y() += 50.0;
  estimate.insert(estimate.begin() + 4, overwritten);  // same stamp, earlier in the file
  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(estimate, reference);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_EQ(ate->trans_m.count, reference.size());
  EXPECT_LT(ate->trans_m.max, 1e-9);
}

TEST(AbsoluteTrajectoryError, FewerThanTwoPairsIsAnInputError) {
  const std::vector<StampedPose3> reference = wiggly(10.0, 1.0);
  std::vector<StampedPose3> estimate = reference;
  for (StampedPose3& p : estimate) p.t_s += 0.05;  // every stamp too far
  estimate[0].t_s = reference[0].t_s;              // one pair only
  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(estimate, reference);
  ASSERT_FALSE(ate.ok());
  EXPECT_EQ(ate.error().kind, ErrorKind::kInput);
  EXPECT_THAT(ate.error().message, HasSubstr("1 of 11 estimate stamps are within 0.02 s"));
}

// Planar trajectories (the SLAM and fusion commands' case) score as their 3D lift: an L-shaped
// path, and an estimate that is its copy turned by 0.3 rad and shifted, with one pose 0.1 m off.
TEST(AbsoluteTrajectoryError, PlanarTrajectoriesScoreAsTheir3DLift) {
  std::vector<StampedPose2> reference, estimate;
  const Pose2 T{1.5, -2.0, 0.3};
  for (int i = 0; i < 20; ++i) {
    const Pose2 p = i < 10 ? Pose2{0.2 * i, 0.0, 0.0} : Pose2{1.8, 0.2 * (i - 9), 1.57};
    reference.push_back({0.1 * i, p});
    Pose2 q = T * p;
    if (i == 7) q.y += 0.1;
    estimate.push_back({0.1 * i, q});
  }
  const Result<AbsoluteTrajectoryError> planar = absolute_trajectory_error(estimate, reference);
  const Result<AbsoluteTrajectoryError> lifted =
      absolute_trajectory_error(to_pose3(estimate), to_pose3(reference));
  ASSERT_TRUE(planar.ok()) << planar.error().message;
  ASSERT_TRUE(lifted.ok());
  EXPECT_EQ(planar->trans_m.count, 20u);
  EXPECT_EQ(planar->trans_m.rmse, lifted->trans_m.rmse);
  EXPECT_GT(planar->trans_m.rmse, 0.01);  // the 0.1 m pose, spread by the alignment
  EXPECT_LT(planar->trans_m.rmse, 0.1 / std::sqrt(20.0));
}

TEST(TrajectoryErrorOptions, RejectsNonPositiveValues) {
  EXPECT_FALSE(validate(TrajectoryErrorOptions{}).has_value());
  EXPECT_THAT(validate(TrajectoryErrorOptions{0.0, 1.0}).value_or(""),
              HasSubstr("max_difference_s"));
  EXPECT_THAT(validate(TrajectoryErrorOptions{0.02, -1.0}).value_or(""), HasSubstr("rpe_delta_s"));
  EXPECT_TRUE(validate(TrajectoryErrorOptions{0.02, std::nan("")}).has_value());
}

/// A robot at (speed t, 0, 0) turned by turn_rate t about z, sampled every 0.25 s (binary-exact
/// stamps) for 10 s.
std::vector<StampedPose3> steady(double speed_m_per_s, double turn_rad_per_s) {
  std::vector<StampedPose3> poses;
  for (int k = 0; k <= 40; ++k) {
    const double t = 0.25 * k;
    poses.push_back(
        {t, Eigen::Vector3d(speed_m_per_s * t, 0.0, 0.0),
         Eigen::Quaterniond(Eigen::AngleAxisd(turn_rad_per_s * t, Eigen::Vector3d::UnitZ()))});
  }
  return poses;
}

TEST(RelativePoseError, PairsPosesOneDeltaApartAndDropsPairsEndingAtTheLastPose) {
  // 41 poses 0.25 s apart: pose i pairs with i + 4 for i = 0..35; for i = 36..40 the partner is
  // the last pose (evaluate_rpe.py drops those, even i = 36 whose partner is exactly 1 s later).
  const Result<RelativePoseError> rpe = relative_pose_error(steady(1.0, 0.1), steady(1.0, 0.1));
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_EQ(rpe->trans_m.count, 36u);
  EXPECT_DOUBLE_EQ(rpe->delta_s, 1.0);
  EXPECT_LT(rpe->trans_m.max, 1e-12);
  EXPECT_LT(rpe->rot_rad.max, 1e-7);  // acos near 1 resolves only ~1e-8
}

TEST(RelativePoseError, TenPercentFastEstimateIsOffByATenthOfAMetrePerSecond) {
  // No turning: over each 1 s pair the estimate moves 1.1 m, the reference 1 m.
  const Result<RelativePoseError> rpe = relative_pose_error(steady(1.1, 0.0), steady(1.0, 0.0));
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_EQ(rpe->trans_m.count, 36u);
  EXPECT_NEAR(rpe->trans_m.rmse, 0.1, 1e-12);
  EXPECT_NEAR(rpe->trans_m.min, 0.1, 1e-12);
  EXPECT_NEAR(rpe->rot_rad.max, 0.0, 1e-12);
}

TEST(RelativePoseError, FastTurningEstimateIsOffByTheExtraAnglePerSecond) {
  // Turning on the spot: 0.11 rad against 0.1 rad per 1 s pair.
  const Result<RelativePoseError> rpe = relative_pose_error(steady(0.0, 0.11), steady(0.0, 0.1));
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_NEAR(rpe->rot_rad.rmse, 0.01, 1e-9);
  EXPECT_NEAR(rpe->rot_rad.min, 0.01, 1e-9);
  EXPECT_NEAR(rpe->trans_m.max, 0.0, 1e-12);
}

TEST(RelativePoseError, IsBlindToTheEstimatesFrame) {
  std::vector<StampedPose3> estimate;
  for (const StampedPose3& p : wiggly(20.0, 10.0))
    estimate.push_back(moved(some_rigid_motion(), p));
  const Result<RelativePoseError> rpe = relative_pose_error(estimate, wiggly(20.0, 10.0));
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_GT(rpe->trans_m.count, 150u);
  EXPECT_LT(rpe->trans_m.max, 1e-9);
}

TEST(RelativePoseError, DropsPairsWithAnEndFarFromEveryReferenceStamp) {
  // Reference without the stamps 4.25 .. 5.75 s; its median interval is 0.25 s, so an estimate
  // stamp may be at most 0.5 s from its reference stamp: 4.75, 5.0 and 5.25 s are not. Six of
  // the 36 pairs have such an end (i or i + 4 in {19, 20, 21}).
  std::vector<StampedPose3> reference;
  for (const StampedPose3& p : steady(1.0, 0.1)) {
    if (p.t_s < 4.2 || p.t_s > 5.8) reference.push_back(p);
  }
  const Result<RelativePoseError> rpe = relative_pose_error(steady(1.0, 0.1), reference);
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_EQ(rpe->trans_m.count, 30u);
}

TEST(RelativePoseError, TooFewPairsOrNoOverlapAreInputErrors) {
  const std::vector<StampedPose3> reference = steady(1.0, 0.1);
  std::vector<StampedPose3> later = reference;
  for (StampedPose3& p : later) p.t_s += 1000.0;
  const Result<RelativePoseError> apart = relative_pose_error(later, reference);
  ASSERT_FALSE(apart.ok());
  EXPECT_EQ(apart.error().kind, ErrorKind::kInput);
  EXPECT_THAT(apart.error().message, HasSubstr("do not overlap"));

  const std::vector<StampedPose3> short_run(reference.begin(), reference.begin() + 4);  // 0.75 s
  const Result<RelativePoseError> too_short = relative_pose_error(short_run, reference);
  ASSERT_FALSE(too_short.ok());
  EXPECT_THAT(too_short.error().message, HasSubstr("the RPE needs at least 2"));
}

// The check of issue 4: TUM fr1/xyz, RGBDSLAM's estimate against the mocap ground truth, as the
// benchmark's tools compute it (reference values in rgbd/tum_trajectories/SOURCES.md).
TEST(TumBenchmark, Fr1XyzRgbdslamMatchesTheBenchmarkTools) {
  const auto dir = support::data_path("rgbd/tum_trajectories");
  TESSERA_REQUIRE_DATA(dir / "fr1_xyz_groundtruth.txt");
  const Result<std::vector<StampedPose3>> truth =
      read_tum_trajectory3(dir / "fr1_xyz_groundtruth.txt");
  const Result<std::vector<StampedPose3>> estimate =
      read_tum_trajectory3(dir / "fr1_xyz_rgbdslam_estimate.txt");
  ASSERT_TRUE(truth.ok()) << truth.error().message;
  ASSERT_TRUE(estimate.ok()) << estimate.error().message;

  const Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(*estimate, *truth);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  EXPECT_EQ(ate->trans_m.count, 786u);
  EXPECT_NEAR(ate->trans_m.rmse, 0.0135, 0.0005);
  EXPECT_NEAR(ate->trans_m.mean, 0.0120, 0.0005);
  EXPECT_NEAR(ate->trans_m.median, 0.0112, 0.0005);

  // RPE: SOURCES.md lists 0.0216 m, which composes the error as ref_rel^-1 * est_rel (evo's
  // order); evaluate_rpe.py composes est_rel * ref_rel^-1 and gives 0.02122 m over 753 pairs (a
  // plain Python port of the script agrees to 1e-12). The angle is the same either way.
  const Result<RelativePoseError> rpe = relative_pose_error(*estimate, *truth);
  ASSERT_TRUE(rpe.ok()) << rpe.error().message;
  EXPECT_EQ(rpe->trans_m.count, 753u);
  EXPECT_NEAR(rpe->trans_m.rmse, 0.02122, 0.00002);
  EXPECT_NEAR(rpe->rot_rad.rmse * 180.0 / std::numbers::pi, 0.934, 0.001);
}

}  // namespace
}  // namespace tessera
