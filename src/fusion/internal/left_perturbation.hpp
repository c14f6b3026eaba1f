#pragma once
// A small rigid motion applied on the left, the update of the Gauss-Newton steps and covariance
// combinations in node_matcher.cpp and depth_icp.cpp.
#include <Eigen/Core>
#include <Eigen/Geometry>

namespace tessera::fusion::internal {

/// xi = (rotation vector, translation) applied on the left: exp(xi) * T (rotation and translation
/// taken separately, exact for the small steps it is used for).
inline Eigen::Isometry3d perturbed(const Eigen::Isometry3d& T,
                                   const Eigen::Matrix<double, 6, 1>& xi) {
  Eigen::Isometry3d E = Eigen::Isometry3d::Identity();
  const double angle = xi.head<3>().norm();
  if (angle > 0.0) E.linear() = Eigen::AngleAxisd(angle, xi.head<3>() / angle).toRotationMatrix();
  E.translation() = xi.tail<3>();
  return E * T;
}

}  // namespace tessera::fusion::internal
