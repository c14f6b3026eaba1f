#include "tessera/eval/drift_correction.hpp"

#include <cmath>

namespace tessera {

Pose2 DriftCorrectionScore::T_truth_slam() const {
  const Eigen::Isometry3d& T = slam.T_reference_estimate;
  return {T.translation().x(), T.translation().y(), std::atan2(T.linear()(1, 0), T.linear()(0, 0))};
}

Result<DriftCorrectionScore> score_drift_correction(const std::vector<StampedPose2>& slam,
                                                    const std::vector<StampedPose2>& odometry,
                                                    const std::vector<StampedPose2>& truth,
                                                    const std::vector<StampedPose2>* local,
                                                    const TrajectoryErrorOptions& options) {
  Result<AbsoluteTrajectoryError> slam_ate = absolute_trajectory_error(slam, truth, options);
  if (!slam_ate) return slam_ate.error();
  DriftCorrectionScore score;
  score.slam = *slam_ate;
  if (local != nullptr) {
    Result<AbsoluteTrajectoryError> local_ate = absolute_trajectory_error(*local, truth, options);
    if (!local_ate) return local_ate.error();
    score.local = *local_ate;
  }
  Result<AbsoluteTrajectoryError> odometry_ate =
      absolute_trajectory_error(odometry, truth, options);
  if (!odometry_ate) return odometry_ate.error();
  score.odometry = *odometry_ate;
  return score;
}

}  // namespace tessera
