#pragma once
// Robust rigid motion from 3D-3D correspondences with outliers: RANSAC (Fischler & Bolles 1981)
// over minimal samples of three pairs fitted in closed form (rigid_fit.hpp), the iteration count
// adapted to the best inlier share so far (Hartley & Zisserman 2004, section 4.7.1, eq. 4.18),
// then refinement: refit on all inliers and re-collect them until the set stops changing.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera::fusion {

struct RigidRansacOptions {
  /// A pair is an inlier when |a - T_a_b b| is at most this. 3 cm covers the Kinect v1's depth
  /// noise to about 3.5 m (Khoshelham & Elberink 2012: sigma_z = 1.425e-3 z^2 m) and is what
  /// ../shared/data/rgbd/tum_fr1_xyz_pairs/SOURCES.md used.
  double inlier_threshold_m = 0.03;
  /// Upper bound on hypotheses; fewer are drawn once `confidence` is reached.
  int max_iterations = 2000;
  /// Probability that at least one sample was all inliers when the search stops.
  double confidence = 0.999;
  /// A sample whose pairwise distances differ by more than this between the two sets cannot come
  /// from one rigid motion (distances are invariant); it is skipped without a fit.
  double max_distance_mismatch_m = 0.06;
  /// Refit on the inliers and re-collect them at most this many times.
  int refine_iterations = 10;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const RigidRansacOptions& o);

struct RigidRansacResult {
  bool valid = false;  // false when no sample gave a fit with 3 or more inliers
  Eigen::Isometry3d T_a_b = Eigen::Isometry3d::Identity();
  std::vector<int> inliers;  // indices into a and b, ascending
  double rmse_m = 0.0;       // root mean square of |a - T_a_b b| over the inliers
  int iterations = 0;        // hypotheses drawn
};

/// T_a_b such that a_i = T_a_b b_i for the inlier pairs. Deterministic for a given rng state (the
/// only randomness is the choice of samples). Preconditions: a.size() == b.size();
/// validate(options) is empty. Cost: O(iterations * n).
[[nodiscard]] RigidRansacResult rigid_ransac(std::span<const Eigen::Vector3d> a,
                                             std::span<const Eigen::Vector3d> b,
                                             const RigidRansacOptions& options, Rng& rng);

}  // namespace tessera::fusion
