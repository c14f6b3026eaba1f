#pragma once
// Sub-cell scan matching: least squares over the pose, on a bicubic interpolation of the grid's
// probabilities, so that the scan lands where the grid is most occupied (Hess et al. 2016,
// Sec. IV-C, eq. (CS); Cartographer's CeresScanMatcher2D with its OccupiedSpaceCostFunction2D and
// translation/rotation delta costs). Solved by Levenberg-Marquardt on the 3 pose parameters with
// analytic derivatives of ceres::BiCubicInterpolator (no ceres::Problem per scan: three unknowns
// need no sparse machinery).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/slam/probability_grid.hpp"

namespace tessera::slam {

/// Cost = sum_i (w_occ / sqrt(n) * (1 - P(T p_i)))^2 + (w_t * |t - t_prior|)^2
///        + (w_r * (theta - theta_prior))^2, P the bicubic interpolation of the cell probabilities
/// (unknown and outside cells at unknown_probability). The weights are Cartographer's 2D defaults.
struct ScanRefinerOptions {
  double occupied_space_weight = 1.0;
  double translation_weight = 10.0;  // per metre
  double rotation_weight = 40.0;     // per radian
  int max_iterations = 20;
  /// What an unknown cell (and a cell outside the grid) reads. kMinProbability is Cartographer's
  /// choice: an unexplored cell costs as much as the emptiest one. But a submap sees each wall from
  /// one side, free cells before it and unknown ones behind: read as kMinProbability, those tilt
  /// the wall's interpolated ridge towards the side it was seen from, and a scan is matched a
  /// little short of it (local SLAM's path 0.1 % short in simulation with exact odometry, decision
  /// 0039). Laser SLAM reads them at the free cells' level (kSlamUnknownProbability).
  double unknown_probability = kMinProbability;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ScanRefinerOptions& o);

struct RefinedPose {
  Pose2 T_grid_robot;
  double initial_cost = 0.0;
  double final_cost = 0.0;
  int iterations = 0;
  /// Mean interpolated probability of the points at the result (a match quality in
  /// [kMinProbability, kMaxProbability]).
  double mean_probability = 0.0;
  /// J^T J of the occupied-space residuals alone at the result, over (x, y, theta) in the grid
  /// frame: how sharply the grid pins the pose (zero along a corridor's axis).
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
};

/// A heading the scan should have besides the prior's, e.g. the one that puts its walls along the
/// building's axes (laser_slam.hpp, manhattan): cost + (weight_per_rad * (theta - theta_rad))^2.
struct HeadingTarget {
  double theta_rad = 0.0;
  double weight_per_rad = 0.0;
};

/// Refines the pose of points_robot in `grid`, starting at T_grid_robot_start and regularised
/// towards T_grid_robot_prior (and `heading`, when given). Cost: O(iterations * points).
[[nodiscard]] RefinedPose refine_scan(const ProbabilityGrid& grid, const Pose2& T_grid_robot_prior,
                                      const Pose2& T_grid_robot_start,
                                      const std::vector<Vec2>& points_robot,
                                      const ScanRefinerOptions& options,
                                      const std::optional<HeadingTarget>& heading = std::nullopt);

}  // namespace tessera::slam
