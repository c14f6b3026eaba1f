#include "tessera/fusion/rigid_fit.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "tessera/core/assert.hpp"

namespace tessera::fusion {

RigidFit fit_rigid(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b,
                   std::span<const double> weights) {
  TESSERA_ASSERT(a.size() == b.size());
  TESSERA_ASSERT(weights.empty() || weights.size() == a.size());
  RigidFit fit;
  if (a.size() < 3) return fit;
  const auto w = [&](std::size_t i) { return weights.empty() ? 1.0 : weights[i]; };

  double total = 0.0;
  Eigen::Vector3d mean_a = Eigen::Vector3d::Zero();
  Eigen::Vector3d mean_b = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    total += w(i);
    mean_a += w(i) * a[i];
    mean_b += w(i) * b[i];
  }
  if (!(total > 0.0)) return fit;
  mean_a /= total;
  mean_b /= total;

  // Cross-covariance Sigma_ab (Umeyama eq. 38) and each set's own scatter for the line test.
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d scatter_a = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d scatter_b = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector3d da = a[i] - mean_a;
    const Eigen::Vector3d db = b[i] - mean_b;
    cov += w(i) * da * db.transpose();
    scatter_a += w(i) * da * da.transpose();
    scatter_b += w(i) * db * db.transpose();
  }
  // Points on one line leave the rotation about that line free: the second-largest eigenvalue of
  // the scatter vanishes relative to the largest.
  constexpr double kLineRatio = 1e-10;
  for (const Eigen::Matrix3d* s : {&scatter_a, &scatter_b}) {
    const Eigen::Vector3d ev =
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(*s, Eigen::EigenvaluesOnly)
            .eigenvalues();  // ascending
    if (!(ev(2) > 0.0) || ev(1) <= kLineRatio * ev(2)) return fit;
  }

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(cov, Eigen::ComputeFullU | Eigen::ComputeFullV);
  // S = diag(1, 1, det(U) det(V)) turns a reflection into the nearest rotation (Umeyama eq. 39).
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  const Eigen::Matrix3d R = svd.matrixU() * S * svd.matrixV().transpose();
  fit.T_a_b.linear() = R;
  fit.T_a_b.translation() = mean_a - R * mean_b;
  fit.valid = true;
  return fit;
}

}  // namespace tessera::fusion
