#pragma once
// Closed-form least-squares rigid motion between two sets of corresponding 3D points, without
// scale: Arun, Huang & Blostein 1987 ("Least-squares fitting of two 3-D point sets") with
// Umeyama's 1991 reflection fix (eq. 39-41). The building block of rigid_ransac.hpp.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <span>

namespace tessera::fusion {

/// valid is false when the points do not pin a rotation down: fewer than 3 pairs, zero total
/// weight, or all points of either set (nearly) on one line.
struct RigidFit {
  bool valid = false;
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
};

/// The T_a_b minimising sum_i w_i |a_i - T_a_b b_i|^2 (w_i = 1 when `weights` is empty).
/// Preconditions: a.size() == b.size(); weights empty or of the same size, each >= 0.
/// Cost: O(n) plus one 3x3 SVD.
[[nodiscard]] RigidFit fit_rigid(std::span<const Eigen::Vector3d> a,
                                 std::span<const Eigen::Vector3d> b,
                                 std::span<const double> weights = {});

}  // namespace tessera::fusion
