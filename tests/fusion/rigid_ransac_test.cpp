#include "tessera/fusion/rigid_ransac.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <vector>

namespace tessera::fusion {
namespace {

struct Scene {
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  std::vector<Eigen::Vector3d> a, b;
  std::set<int> outliers;
};

/// n pairs related by T_a_b with Gaussian noise on a; `outlier_share` of them replaced by random
/// points (wrong descriptor matches).
Scene make_scene(std::uint64_t seed, int n, double outlier_share, double noise_m) {
  Rng rng(seed);
  Scene s;
  s.T_a_b.linear() =
      Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, 1.0, -0.1).normalized()).toRotationMatrix();
  s.T_a_b.translation() = Eigen::Vector3d(0.4, -0.1, 0.25);
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector3d p(rng.uniform(-2, 2), rng.uniform(-1.5, 1.5), rng.uniform(0.8, 4.0));
    s.b.push_back(p);
    if (i < static_cast<int>(outlier_share * n)) {
      s.a.emplace_back(rng.uniform(-2, 2), rng.uniform(-1.5, 1.5), rng.uniform(0.8, 4.0));
      s.outliers.insert(i);
    } else {
      s.a.push_back(s.T_a_b * p + Eigen::Vector3d(rng.gaussian(noise_m), rng.gaussian(noise_m),
                                                  rng.gaussian(noise_m)));
    }
  }
  return s;
}

TEST(RigidRansac, RecoversTheMotionDespiteSixtyPercentOutliers) {
  const Scene s = make_scene(1, 300, 0.6, 0.0);
  Rng rng(7);
  const RigidRansacResult r = rigid_ransac(s.a, s.b, RigidRansacOptions{}, rng);
  ASSERT_TRUE(r.valid);
  EXPECT_LT((r.T_a_b.translation() - s.T_a_b.translation()).norm(), 1e-9);
  EXPECT_LT(Eigen::AngleAxisd(r.T_a_b.linear().transpose() * s.T_a_b.linear()).angle(), 1e-9);
  // Every true pair is an inlier; a random outlier may land within 3 cm by chance, rarely.
  int true_inliers = 0;
  for (const int i : r.inliers) true_inliers += s.outliers.count(i) == 0 ? 1 : 0;
  EXPECT_EQ(true_inliers, 120);
  EXPECT_LE(r.inliers.size(), 122u);
  EXPECT_LT(r.rmse_m, 0.03);
}

TEST(RigidRansac, RefinementAveragesNoiseOverAllInliers) {
  const Scene s = make_scene(2, 400, 0.3, 0.005);
  Rng rng(9);
  const RigidRansacResult r = rigid_ransac(s.a, s.b, RigidRansacOptions{}, rng);
  ASSERT_TRUE(r.valid);
  // 280 pairs with 5 mm noise: the refined motion is far better than any 3-point sample.
  EXPECT_LT((r.T_a_b.translation() - s.T_a_b.translation()).norm(), 0.002);
  EXPECT_LT(Eigen::AngleAxisd(r.T_a_b.linear().transpose() * s.T_a_b.linear()).angle(), 0.001);
  EXPECT_NEAR(r.rmse_m, 0.005 * std::sqrt(3.0), 0.002);
}

TEST(RigidRansac, SameSeedSameResult) {
  const Scene s = make_scene(3, 200, 0.5, 0.01);
  Rng rng1(42), rng2(42);
  const RigidRansacResult r1 = rigid_ransac(s.a, s.b, RigidRansacOptions{}, rng1);
  const RigidRansacResult r2 = rigid_ransac(s.a, s.b, RigidRansacOptions{}, rng2);
  ASSERT_TRUE(r1.valid);
  EXPECT_EQ(r1.inliers, r2.inliers);
  EXPECT_EQ(r1.iterations, r2.iterations);
  EXPECT_TRUE(r1.T_a_b.matrix() == r2.T_a_b.matrix());
}

TEST(RigidRansac, AdaptiveStopDrawsFewHypothesesWhenAllPairsAgree) {
  const Scene s = make_scene(4, 100, 0.0, 0.0);
  Rng rng(1);
  const RigidRansacResult r = rigid_ransac(s.a, s.b, RigidRansacOptions{}, rng);
  ASSERT_TRUE(r.valid);
  EXPECT_EQ(r.inliers.size(), 100u);
  EXPECT_LE(r.iterations, 5);
}

TEST(RigidRansac, PureNoiseFindsNoLargeConsensus) {
  Rng gen(5);
  std::vector<Eigen::Vector3d> a, b;
  for (int i = 0; i < 100; ++i) {
    a.emplace_back(gen.uniform(-2, 2), gen.uniform(-2, 2), gen.uniform(1, 4));
    b.emplace_back(gen.uniform(-2, 2), gen.uniform(-2, 2), gen.uniform(1, 4));
  }
  Rng rng(6);
  const RigidRansacResult r = rigid_ransac(a, b, RigidRansacOptions{}, rng);
  EXPECT_LT(r.inliers.size(), 10u);
  EXPECT_EQ(r.iterations, RigidRansacOptions{}.max_iterations);
}

TEST(RigidRansac, FewerThanThreePairsIsNoResult) {
  const std::vector<Eigen::Vector3d> two{{0, 0, 1}, {1, 0, 1}};
  Rng rng(1);
  EXPECT_FALSE(rigid_ransac(two, two, RigidRansacOptions{}, rng).valid);
}

TEST(RigidRansac, OptionsAreValidated) {
  EXPECT_FALSE(validate(RigidRansacOptions{}));
  RigidRansacOptions o;
  o.inlier_threshold_m = 0.0;
  EXPECT_TRUE(validate(o));
  o = {};
  o.confidence = 1.0;
  EXPECT_TRUE(validate(o));
}

}  // namespace
}  // namespace tessera::fusion
