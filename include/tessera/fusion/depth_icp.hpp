#pragma once
// Motion from the depth images alone, for views whose colour images hold too few features (issue
// 18 item 10; thesis section 5.2.3, where blank walls defeated feature matching and the thesis
// fell back on odometry). Where the depth still holds structure that pins all six degrees of
// freedom (a corner of two walls and the floor or ceiling), the motion is solved geometrically;
// where it does not (one plane, or two walls with nothing across them), it is refused.
//
//  1. A depth pyramid: each level averages blocks of block_px x block_px pixels (2, 4, 8 ...), a
//     block with less than half of its pixels in range, or with a depth step inside it, reads
//     nothing. Each level has a normal per cell from a principal-component fit over the 5 x 5
//     cells around it (Hoppe et al. 1992), kept only where that patch is flat.
//  2. Point-to-plane ICP (Chen & Medioni 1992) with projective data association (each current
//     point, moved by the estimate, is looked up at the pixel it projects to in the previous
//     view: Newcombe et al. 2011, KinectFusion), coarse to fine, Gauss-Newton steps on the left
//     perturbation, residuals weighted by the depth noise sigma_z = k z^2 (Khoshelham & Elberink
//     2012) and a Huber loss.
//  3. Refusal: the estimate is accepted only when the pairs at the finest level overlap enough,
//     their residual is at the depth noise, and the geometry is stable: the 6 x 6 matrix of the
//     point-to-plane constraints, with the points centred and scaled to unit mean distance
//     (Gelfand, Ikemoto, Rusinkiewicz & Levoy 2003, "Geometrically stable sampling for the ICP
//     algorithm"), must have no direction much weaker than the strongest. One plane leaves three
//     directions free (two translations in it, the rotation about its normal), two walls leave
//     the translation along both.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <numbers>
#include <optional>
#include <string>
#include <string_view>

#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

struct DepthIcpOptions {
  /// Depths outside this range read nothing (the Kinect v1's effective range, image_node.hpp).
  double min_depth_m = 0.5;
  double max_depth_m = 4.5;
  /// Pyramid: the finest level averages finest_block_px^2 pixels, each of the `levels` levels
  /// doubles the block (2, 4, 8 px by default).
  int finest_block_px = 2;
  int levels = 3;
  /// A block's depths may differ from their mean by at most this share of it (else the block
  /// straddles a depth edge and reads nothing).
  double max_block_step_ratio = 0.05;
  /// A normal is kept where the patch around the cell is flat: the smallest eigenvalue of its
  /// points' covariance at most this share of their sum (0 on an exact plane).
  double max_patch_curvature = 0.02;
  int iterations_per_level = 12;
  /// Stop a level early when a step moves less than these.
  double converged_m = 1e-5;
  double converged_rad = 1e-5;
  /// Data association at the finest level (each coarser level doubles the distance): the pair's
  /// points at most this far apart and their normals at most this angle apart.
  double max_pair_distance_m = 0.04;
  double max_normal_angle_rad = 20.0 * std::numbers::pi / 180.0;
  /// sigma_z = depth_noise_per_m * z^2 + depth_noise_floor_m (Kinect v1, as node_matcher.hpp).
  double depth_noise_per_m = 1.425e-3;
  double depth_noise_floor_m = 1e-3;
  /// Huber threshold on the residual in sigmas.
  double huber_sigmas = 2.0;
  /// Acceptance at the finest level: at least this share of the current points with a normal is
  /// paired, ...
  double min_overlap = 0.5;
  /// ... at least this many pairs, ...
  int min_pairs = 500;
  /// ... the root mean square of the residuals in sigmas at most this, ...
  double max_rms_sigmas = 3.0;
  /// ... and the geometry stable: the largest over the smallest eigenvalue of the scaled
  /// constraint matrix (Gelfand et al. 2003) at most this. Measured (docs/fusion-depth-icp.md):
  /// simulated corners with the floor or ceiling in view 10 to 183, the real TUM desk 26 to 27;
  /// one plane, two walls, or a wall and the floor 22,808 and more.
  double max_condition_number = 300.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const DepthIcpOptions& o);

enum class DepthIcpReason {
  kAccepted,
  kInconsistentFrames,  // buffers or sizes do not match
  kTooFewPoints,        // too few depth readings with a normal, or too few pairs
  kLowOverlap,          // too few current points found a partner in the previous view
  kHighResidual,        // the pairs disagree by more than the depth noise
  kDegenerate,          // the geometry leaves a direction of motion free
};

/// "accepted", "inconsistent frames", "too few points", "low overlap", "high residual",
/// "geometry degenerate" (the reason keys of report.json).
[[nodiscard]] std::string_view to_string(DepthIcpReason reason);

struct DepthIcpResult {
  bool accepted = false;
  DepthIcpReason reason = DepthIcpReason::kTooFewPoints;
  /// One line with the figures behind the decision.
  std::string reason_text;
  /// Maps points in the current camera frame into the previous camera frame; meaningful only when
  /// accepted (otherwise the last estimate, for diagnosis).
  Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();
  int points = 0;  // current points with a normal at the finest level
  int pairs = 0;   // of them, paired at the end
  double overlap = 0.0;
  double rms_sigmas = 0.0;
  double rmse_m = 0.0;  // point-to-plane residual of the pairs
  double condition_number = 0.0;
  int iterations = 0;  // Gauss-Newton steps over all levels
};

/// Aligns `curr` to `prev` from their depth images, starting from T_prev_curr_guess (identity
/// when nothing better is known: the ICP converges for motions of a few centimetres and degrees
/// between the views). Colour is not used. Deterministic. Precondition: validate(options) is
/// empty. Cost: O(pixels) for the pyramids plus O(cells) per iteration; figures in
/// docs/fusion-depth-icp.md.
[[nodiscard]] DepthIcpResult align_depth(
    const RgbdFrame& prev, const RgbdFrame& curr, const DepthIcpOptions& options,
    const Eigen::Isometry3d& T_prev_curr_guess = Eigen::Isometry3d::Identity());

}  // namespace tessera::fusion
