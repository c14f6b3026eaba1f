#pragma once
// 3D trajectories, as TUM RGB-D benchmark files hold them (Sturm et al. 2012): the type the TUM
// readers (io) produce and the TUM-style trajectory errors (eval/trajectory_error.hpp) work on.
// Core stays free of Eigen, so the 3D pose lives in this small header-only module beside it;
// planar trajectories enter through to_pose3.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "tessera/core/stamped_pose2.hpp"

namespace tessera {

/// T_world_body at time t_s: position in metres, orientation a unit quaternion.
struct StampedPose3 {
  double t_s = 0.0;
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  Eigen::Quaterniond orientation = Eigen::Quaterniond::Identity();

  /// The pose as a rigid transform (orientation normalised).
  [[nodiscard]] Eigen::Isometry3d transform() const {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = orientation.normalized().toRotationMatrix();
    T.translation() = position_m;
    return T;
  }
};

/// A planar pose as a 3D one: z = 0 and the heading as a rotation about z.
[[nodiscard]] inline StampedPose3 to_pose3(const StampedPose2& p) {
  const double half = 0.5 * p.pose.theta;
  return {p.t_s, Eigen::Vector3d(p.pose.x, p.pose.y, 0.0),
          Eigen::Quaterniond(std::cos(half), 0.0, 0.0, std::sin(half))};
}

/// to_pose3 of every pose, in the same order.
[[nodiscard]] inline std::vector<StampedPose3> to_pose3(const std::vector<StampedPose2>& poses) {
  std::vector<StampedPose3> out;
  out.reserve(poses.size());
  for (const StampedPose2& p : poses) out.push_back(to_pose3(p));
  return out;
}

}  // namespace tessera
