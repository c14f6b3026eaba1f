#pragma once
#include "tessera/core/pose2.hpp"

namespace tessera {

/// A ground-truth relation (Kummerle et al. 2009): the true pose of the robot at t2_s expressed in
/// the robot frame at t1_s. Only x, y and yaw of the file's 6-DoF line are kept (2D logs).
struct Relation {
  double t1_s = 0.0;
  double t2_s = 0.0;
  Pose2 motion;
};

}  // namespace tessera
