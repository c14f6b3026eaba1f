#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"

namespace tessera::posegraph {

/// A relative-pose constraint: the pose of node `to` expressed in the frame of node `from`.
struct PoseGraphEdge {
  int from = 0;
  int to = 0;
  Pose2 measurement;
  /// Inverse covariance over (x, y, theta) of the measurement in the frame of `from`.
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  /// Loop closures get a robust loss, so that one wrong closure cannot bend the map.
  bool robust = false;
};

/// "Mapping using knowledge of the environment" (lecture, section on SLAM): in a building of
/// straight walls at right angles (a Manhattan world, Coughlan & Yuille 1999), the dominant wall
/// direction a node's scan shows, offset_rad in the robot frame, lies along the building's axis or
/// across it. The prior: poses[node].theta + offset_rad - axis_rad is a multiple of
/// heading_period_rad, with standard deviation sigma_rad, under a Cauchy loss (a scan whose walls
/// are not along the axes is an outlier, not a pull).
struct HeadingPrior {
  int node = 0;
  double offset_rad = 0.0;
  double sigma_rad = 0.05;
};

/// A 2D pose graph: node i has pose poses[i] (world frame) and the g2o id ids[i].
struct PoseGraph {
  std::vector<Pose2> poses;
  std::vector<int> ids;
  std::vector<PoseGraphEdge> edges;
  /// Manhattan priors (empty: none) and the building's axis in the world frame, which the
  /// optimisation estimates with the poses when there are priors.
  std::vector<HeadingPrior> heading_priors;
  double axis_rad = 0.0;
  double heading_period_rad = 1.5707963267948966;  // pi / 2: walls along and across the axis
};

struct OptimizeOptions {
  int max_iterations = 100;
  /// Scale of the Huber loss on robust edges, in units of the whitened residual.
  double huber_scale = 1.0;
  /// Nodes held fixed (the gauge); node 0 when empty.
  std::vector<int> fixed_nodes;
};

struct OptimizeSummary {
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;  // solver steps taken, at most max_iterations
  double time_s = 0.0;
  bool converged = false;
  std::string termination;  // Ceres' one-line report
};

/// Least-squares optimisation of the graph's poses with Ceres (Levenberg-Marquardt, sparse).
/// Runtime error when the graph refers to a missing node or Ceres fails.
[[nodiscard]] Result<OptimizeSummary> optimize(PoseGraph& graph, const OptimizeOptions& options);

}  // namespace tessera::posegraph
