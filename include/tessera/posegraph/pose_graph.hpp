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

/// A 2D pose graph: node i has pose poses[i] (world frame) and the g2o id ids[i].
struct PoseGraph {
  std::vector<Pose2> poses;
  std::vector<int> ids;
  std::vector<PoseGraphEdge> edges;
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
