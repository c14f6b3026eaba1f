#pragma once
// "ATE of SLAM vs odometry vs truth": how much a SLAM run corrects its odometry's drift. The SLAM
// trajectory and odometry alone are each scored against the same ground truth with the TUM
// benchmark's ATE (eval/trajectory_error.hpp: associate, align rigidly, RMSE of the distances), and
// the ratio odometry / SLAM says how many times smaller the error is with SLAM. One scorer for the
// laser SLAM's simulated runs (tessera slam --world), the Fusion SLAM's mapping runs and recorded
// sequences (tessera fusion --world / --sequence) and teach-and-repeat (thesis Table 5.1, drift
// correction of section 6.2). A third trajectory (the laser SLAM's local SLAM without loop
// closures) may be scored alongside. No I/O.
#include <optional>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/eval/trajectory_error.hpp"

namespace tessera {

struct DriftCorrectionScore {
  AbsoluteTrajectoryError slam;      // the SLAM's (corrected) trajectory against the truth
  AbsoluteTrajectoryError odometry;  // odometry alone against the truth
  std::optional<AbsoluteTrajectoryError> local;  // when a local trajectory was given

  /// ATE RMSE of odometry over that of SLAM: how many times smaller SLAM's error is; 0 when SLAM's
  /// is 0 (nothing to divide by).
  [[nodiscard]] double odometry_over_slam() const {
    return slam.trans_m.rmse > 0.0 ? odometry.trans_m.rmse / slam.trans_m.rmse : 0.0;
  }
  /// The SLAM trajectory's alignment onto the truth, planar (x, y and the rotation about z):
  /// applied to the SLAM's map, it puts the map in the truth's frame (decision 0009).
  [[nodiscard]] Pose2 T_truth_slam() const;
};

/// Scores `slam` and `odometry` (and `local` when not null) against `truth`, each with
/// absolute_trajectory_error(estimate, truth, options). The first error of the three (slam,
/// local, odometry) when one cannot be scored (fewer than 2 associated pairs).
/// Precondition: validate(options) is empty. Cost: that of three ATEs.
[[nodiscard]] Result<DriftCorrectionScore> score_drift_correction(
    const std::vector<StampedPose2>& slam, const std::vector<StampedPose2>& odometry,
    const std::vector<StampedPose2>& truth, const std::vector<StampedPose2>* local = nullptr,
    const TrajectoryErrorOptions& options = {});

}  // namespace tessera
