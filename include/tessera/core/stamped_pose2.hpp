#pragma once
#include "tessera/core/pose2.hpp"

namespace tessera {

/// A planar pose with its time stamp: one sample of a trajectory (TUM files, SLAM output, the
/// poses the relation metric interpolates). Seconds; `pose` in metres and radians.
struct StampedPose2 {
  double t_s = 0.0;
  Pose2 pose;
};

}  // namespace tessera
