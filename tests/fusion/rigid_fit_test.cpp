#include "tessera/fusion/rigid_fit.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera::fusion {
namespace {

Eigen::Isometry3d random_motion(Rng& rng, double max_translation_m) {
  Eigen::Vector3d axis(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1));
  axis.normalize();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(rng.uniform(-3.1, 3.1), axis).toRotationMatrix();
  T.translation() = Eigen::Vector3d(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)) *
                    max_translation_m;
  return T;
}

std::vector<Eigen::Vector3d> random_points(Rng& rng, int n) {
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < n; ++i) {
    p.emplace_back(rng.uniform(-2, 2), rng.uniform(-1, 1), rng.uniform(0.5, 4.5));
  }
  return p;
}

double rotation_error_rad(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return Eigen::AngleAxisd(a.linear().transpose() * b.linear()).angle();
}

TEST(RigidFit, RecoversExactMotionsOverSeededTrials) {
  Rng rng(11);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Isometry3d T_a_b = random_motion(rng, 3.0);
    const int n = 3 + trial % 20;
    const std::vector<Eigen::Vector3d> b = random_points(rng, n);
    std::vector<Eigen::Vector3d> a;
    for (const auto& p : b) a.push_back(T_a_b * p);
    const RigidFit fit = fit_rigid(a, b);
    ASSERT_TRUE(fit.valid) << "trial " << trial;
    EXPECT_LT((fit.T_a_b.translation() - T_a_b.translation()).norm(), 1e-9) << "trial " << trial;
    EXPECT_LT(rotation_error_rad(fit.T_a_b, T_a_b), 1e-9) << "trial " << trial;
    EXPECT_NEAR(fit.T_a_b.linear().determinant(), 1.0, 1e-12);
  }
}

// Coplanar points make the SVD's smallest singular value zero; the sign fix must still give a
// rotation, not a reflection (Umeyama 1991, the case Arun et al. 1987 gets wrong).
TEST(RigidFit, CoplanarPointsGiveARotationNotAReflection) {
  Rng rng(3);
  const Eigen::Isometry3d T_a_b = random_motion(rng, 1.0);
  std::vector<Eigen::Vector3d> a, b;
  for (int i = 0; i < 10; ++i) {
    b.emplace_back(rng.uniform(-1, 1), rng.uniform(-1, 1), 2.0);  // a wall at z = 2 m
    a.push_back(T_a_b * b.back());
  }
  const RigidFit fit = fit_rigid(a, b);
  ASSERT_TRUE(fit.valid);
  EXPECT_NEAR(fit.T_a_b.linear().determinant(), 1.0, 1e-12);
  EXPECT_LT(rotation_error_rad(fit.T_a_b, T_a_b), 1e-9);
}

TEST(RigidFit, WeightsSelectWhichPairsCount) {
  Rng rng(5);
  const Eigen::Isometry3d T_a_b = random_motion(rng, 1.0);
  std::vector<Eigen::Vector3d> b = random_points(rng, 8);
  std::vector<Eigen::Vector3d> a;
  for (const auto& p : b) a.push_back(T_a_b * p);
  a[7] += Eigen::Vector3d(0.5, -0.3, 0.2);  // a wrong pair with zero weight
  const std::vector<double> w{1, 1, 1, 1, 1, 1, 1, 0};
  const RigidFit fit = fit_rigid(a, b, w);
  ASSERT_TRUE(fit.valid);
  EXPECT_LT((fit.T_a_b.translation() - T_a_b.translation()).norm(), 1e-9);
  EXPECT_FALSE(fit_rigid(a, b, std::vector<double>(8, 0.0)).valid);
}

TEST(RigidFit, TooFewOrCollinearPointsAreNotAFit) {
  const std::vector<Eigen::Vector3d> two{{0, 0, 1}, {1, 0, 1}};
  EXPECT_FALSE(fit_rigid(two, two).valid);
  const std::vector<Eigen::Vector3d> line{{0, 0, 1}, {1, 1, 2}, {2, 2, 3}, {3, 3, 4}};
  EXPECT_FALSE(fit_rigid(line, line).valid);
  const std::vector<Eigen::Vector3d> same{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  EXPECT_FALSE(fit_rigid(same, same).valid);
}

}  // namespace
}  // namespace tessera::fusion
