// Pose-graph optimisation with Ceres: one residual block per edge, the error of the measured
// relative pose whitened by the square root of the edge's information matrix (the standard 2D
// SLAM formulation; cf. Ceres' examples/slam/pose_graph_2d). Loop closures carry a Huber loss.
#include "tessera/posegraph/pose_graph.hpp"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>

namespace tessera::posegraph {
namespace {

/// Wraps an angle into [-pi, pi) inside Ceres' automatic differentiation.
template <typename T>
T wrap_angle(const T& a) {
  using std::floor;
  const T two_pi(2.0 * M_PI);
  return a - two_pi * floor((a + T(M_PI)) / two_pi);
}

/// Residual of one edge: sqrt(information) * [R_from^T (p_to - p_from) - t_meas; dtheta -
/// theta_meas].
class RelativePoseError {
 public:
  RelativePoseError(const Pose2& measurement, const Eigen::Matrix3d& sqrt_information)
      : measurement_(measurement), sqrt_information_(sqrt_information) {}

  template <typename T>
  bool operator()(const T* const from, const T* const to, T* residual) const {
    using std::cos;
    using std::sin;
    const T c = cos(from[2]), s = sin(from[2]);
    const T dx = to[0] - from[0], dy = to[1] - from[1];
    Eigen::Matrix<T, 3, 1> e;
    e(0) = c * dx + s * dy - T(measurement_.x);
    e(1) = -s * dx + c * dy - T(measurement_.y);
    e(2) = wrap_angle(to[2] - from[2] - T(measurement_.theta));
    Eigen::Map<Eigen::Matrix<T, 3, 1>> r(residual);
    r = sqrt_information_.cast<T>() * e;
    return true;
  }

 private:
  Pose2 measurement_;
  Eigen::Matrix3d sqrt_information_;
};

/// Residual of one heading prior (pose_graph.hpp): the node's heading plus the offset, minus the
/// axis, wrapped into [-period/2, period/2), over sigma.
class HeadingPriorError {
 public:
  explicit HeadingPriorError(const HeadingPrior& prior, double period_rad)
      : prior_(prior), period_rad_(period_rad) {}

  template <typename T>
  bool operator()(const T* const pose, const T* const axis, T* residual) const {
    using std::floor;
    const T period(period_rad_);
    const T a = pose[2] + T(prior_.offset_rad) - axis[0];
    residual[0] = (a - period * floor((a + T(0.5) * period) / period)) / T(prior_.sigma_rad);
    return true;
  }

 private:
  HeadingPrior prior_;
  double period_rad_;
};

}  // namespace

Result<OptimizeSummary> optimize(PoseGraph& graph, const OptimizeOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const int n = static_cast<int>(graph.poses.size());
  std::vector<std::array<double, 3>> params(graph.poses.size());
  for (int i = 0; i < n; ++i)
    params[i] = {graph.poses[i].x, graph.poses[i].y, graph.poses[i].theta};

  ceres::Problem::Options problem_options;
  ceres::Problem problem(problem_options);
  for (const PoseGraphEdge& edge : graph.edges) {
    if (edge.from < 0 || edge.from >= n || edge.to < 0 || edge.to >= n) {
      return runtime_error("pose graph edge " + std::to_string(edge.from) + " -> " +
                           std::to_string(edge.to) + " names a node that is not in the graph");
    }
    const Eigen::LLT<Eigen::Matrix3d> llt(edge.information);
    if (llt.info() != Eigen::Success) {
      return runtime_error("pose graph edge " + std::to_string(edge.from) + " -> " +
                           std::to_string(edge.to) +
                           ": information matrix is not positive definite");
    }
    const Eigen::Matrix3d sqrt_information = llt.matrixL().transpose();
    auto* cost = new ceres::AutoDiffCostFunction<RelativePoseError, 3, 3, 3>(
        new RelativePoseError(edge.measurement, sqrt_information));
    ceres::LossFunction* loss = edge.robust ? new ceres::HuberLoss(options.huber_scale) : nullptr;
    problem.AddResidualBlock(cost, loss, params[edge.from].data(), params[edge.to].data());
  }
  double axis = graph.axis_rad;
  for (const HeadingPrior& prior : graph.heading_priors) {
    if (prior.node < 0 || prior.node >= n || !(prior.sigma_rad > 0.0)) {
      return runtime_error("heading prior on node " + std::to_string(prior.node) +
                           ": no such node or sigma_rad not > 0");
    }
    auto* cost = new ceres::AutoDiffCostFunction<HeadingPriorError, 1, 3, 1>(
        new HeadingPriorError(prior, graph.heading_period_rad));
    problem.AddResidualBlock(cost, new ceres::CauchyLoss(1.0), params[prior.node].data(), &axis);
  }
  OptimizeSummary out;
  if (problem.NumResidualBlocks() == 0) {
    out.converged = true;
    out.termination = "no edges";
    return out;
  }
  std::vector<int> fixed = options.fixed_nodes;
  if (fixed.empty()) fixed.push_back(0);
  for (int i : fixed) {
    if (i >= 0 && i < n && problem.HasParameterBlock(params[i].data())) {
      problem.SetParameterBlockConstant(params[i].data());
    }
  }

  ceres::Solver::Options solver_options;
  solver_options.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver_options.max_num_iterations = options.max_iterations;
  solver_options.minimizer_progress_to_stdout = false;
  solver_options.logging_type = ceres::SILENT;
  solver_options.num_threads = 1;
  ceres::Solver::Summary summary;
  ceres::Solve(solver_options, &problem, &summary);

  for (int i = 0; i < n; ++i) {
    graph.poses[i] = {params[i][0], params[i][1], normalize_angle(params[i][2])};
  }
  graph.axis_rad = axis;
  out.initial_cost = summary.initial_cost;
  out.final_cost = summary.final_cost;
  // The steps Ceres took, as max_num_iterations counts them (summary.iterations also holds the
  // initial evaluation, iteration 0).
  out.iterations = summary.num_successful_steps + summary.num_unsuccessful_steps;
  out.converged = summary.termination_type == ceres::CONVERGENCE;
  out.termination = summary.message;
  out.time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (summary.termination_type == ceres::FAILURE) {
    return runtime_error("pose graph optimisation failed: " + summary.message);
  }
  return out;
}

}  // namespace tessera::posegraph
