#pragma once
// Trajectory errors of the TUM RGB-D benchmark (Sturm et al. 2012, "A benchmark for the evaluation
// of RGB-D SLAM systems", IROS), computed as its tools do: associate.py pairs the stamps,
// evaluate_ate.py aligns the estimate onto the reference and reports the absolute trajectory error
// (ATE), evaluate_rpe.py --fixed_delta reports the relative pose error (RPE) over a time delta.
// Both trajectories are T_world_body in their own world frames; only the ATE needs an alignment.
#include <Eigen/Geometry>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/trajectory/stamped_pose3.hpp"

namespace tessera {

struct TrajectoryErrorOptions {
  double max_difference_s = 0.02;  // associate.py --max_difference: pair stamps closer than this
  double rpe_delta_s = 1.0;        // evaluate_rpe.py --fixed_delta --delta 1 --delta_unit s
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const TrajectoryErrorOptions& o);

/// One pair of associated stamps: indices into the reference and the estimate.
struct StampMatch {
  std::size_t reference = 0;
  std::size_t estimate = 0;
};

/// associate.py: every pair with |t_ref - t_est| < max_difference_s is a candidate; candidates are
/// taken greedily from the smallest difference up (ties: smaller reference stamp, then smaller
/// estimate stamp), each stamp at most once. Result sorted by reference stamp. The stamps need not
/// be sorted. Cost: O((n + m) log m + c log c) for c candidates.
[[nodiscard]] std::vector<StampMatch> associate_stamps(const std::vector<double>& reference_s,
                                                       const std::vector<double>& estimate_s,
                                                       double max_difference_s);

/// Summary of a list of errors as the TUM tools print it. `std` is numpy.std: the population
/// standard deviation (divides by n); `median` averages the two middle values of an even count.
struct ErrorStatistics {
  std::size_t count = 0;
  double rmse = 0.0;
  double mean = 0.0;
  double median = 0.0;
  double std = 0.0;
  double min = 0.0;
  double max = 0.0;
};

/// Precondition: !errors.empty(). Cost: O(n log n).
[[nodiscard]] ErrorStatistics error_statistics(std::vector<double> errors);

/// The least-squares rigid motion (no scale) that maps `from` points onto `to` points, in closed
/// form: Horn 1987 / Umeyama 1991 via the SVD of the cross-covariance, with the determinant
/// correction that keeps it a rotation. Returns T with to[i] ~ T * from[i]. Precondition: equal
/// sizes, at least one point. Cost: O(n).
[[nodiscard]] Eigen::Isometry3d align_rigid(const std::vector<Eigen::Vector3d>& from,
                                            const std::vector<Eigen::Vector3d>& to);

struct AbsoluteTrajectoryError {
  std::size_t estimate_poses = 0;
  std::size_t reference_poses = 0;
  ErrorStatistics trans_m;  // count = associated pairs; per pair |T * p_est - p_ref|
  Eigen::Isometry3d T_reference_estimate = Eigen::Isometry3d::Identity();  // the alignment
};

/// evaluate_ate.py: associates the stamps (associate_stamps, options.max_difference_s), aligns the
/// estimate's positions onto the reference's (align_rigid) and measures the distance of each pair.
/// Orientations do not enter. A stamp that appears twice keeps its last pose, as the tools'
/// dictionaries do. Input error when fewer than 2 pairs associate.
/// Precondition: validate(options) is empty.
[[nodiscard]] Result<AbsoluteTrajectoryError> absolute_trajectory_error(
    const std::vector<StampedPose3>& estimate, const std::vector<StampedPose3>& reference,
    const TrajectoryErrorOptions& options = {});

/// The same for planar trajectories (each pose lifted by to_pose3: z = 0, rotation about z).
[[nodiscard]] inline Result<AbsoluteTrajectoryError> absolute_trajectory_error(
    const std::vector<StampedPose2>& estimate, const std::vector<StampedPose2>& reference,
    const TrajectoryErrorOptions& options = {}) {
  return absolute_trajectory_error(to_pose3(estimate), to_pose3(reference), options);
}

struct RelativePoseError {
  double delta_s = 0.0;
  ErrorStatistics trans_m;  // count = pose pairs compared
  ErrorStatistics rot_rad;  // angle of the error rotation, in [0, pi]
};

/// evaluate_rpe.py --fixed_delta --delta_unit s, pairing as the script does: for each estimate
/// pose i (stamps sorted), j is the estimate pose whose stamp is closest to t_i + delta_s, and the
/// pair is dropped when j is the last pose; each end takes the reference pose with the closest
/// stamp, and the pair is dropped when either is farther than twice the reference's median stamp
/// interval. Error = (est_i^-1 * est_j) * (ref_i^-1 * ref_j)^-1; its translation norm and rotation
/// angle. All pairs are used (the script samples 10,000 at random when there are more).
/// Duplicate stamps keep their last pose. Input error when the reference has fewer than 2 poses,
/// fewer than 2 estimate stamps overlap it, or fewer than 2 pairs remain.
/// Precondition: validate(options) is empty.
[[nodiscard]] Result<RelativePoseError> relative_pose_error(
    const std::vector<StampedPose3>& estimate, const std::vector<StampedPose3>& reference,
    const TrajectoryErrorOptions& options = {});

}  // namespace tessera
