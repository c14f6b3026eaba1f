#pragma once
// The thesis' stationary test of the image-node transform (section 5.1.3, results in section 5.2.3
// and Table 5.5): a robot that does not drive captures frame after frame of one view (a desk, a
// cabinet, a blank wall) and matches each new image node with the previous one. The true motion
// between two captures is known (identity when the neck stays still, a pan when it turns), so
// every accepted estimate has an error; on a feature-poor view nothing may be accepted (the thesis
// accepted estimates 0.38 to 0.80 m wrong on its blank wall).
//
// This is the measuring part, on frames from any source; sim/stationary_scene.hpp renders the
// thesis' views in the simulator, tests/fusion/stationary_matching_test.cpp holds the bars and
// bench/fusion/stationary_table.cpp prints the table of docs/fusion-stationary.md.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <map>
#include <span>
#include <string>

#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

/// One capture: the frame and the true pose of its camera's optical frame (x right, y down,
/// z forward) in any fixed frame.
struct PosedFrame {
  RgbdFrame frame;
  Eigen::Isometry3d T_world_camera = Eigen::Isometry3d::Identity();
};

struct StationaryMatchingOptions {
  ImageNodeOptions node;  // node.feature_type selects ORB, SIFT or AKAZE
  NodeMatcherOptions matcher;
};

/// What the consecutive pairs of one capture sequence gave.
struct StationaryMatchingSummary {
  int frames = 0;
  int pairs = 0;     // frames - 1: frame k is matched with frame k - 1
  int accepted = 0;  // pairs whose estimate the matcher accepted
  /// Over the accepted pairs (0 when none): |translation| and rotation angle of
  /// T_truth^-1 * T_estimate, T = T_prev_curr.
  double mean_translation_error_m = 0.0;
  double max_translation_error_m = 0.0;
  double mean_rotation_error_rad = 0.0;
  double max_rotation_error_rad = 0.0;
  /// Rejected pairs by reason: a node check (image_node.hpp, "too few features", ...) when either
  /// frame did not become a node, else the matcher's reason (node_matcher.hpp, "too few
  /// matches", ...).
  std::map<std::string, int> rejections;
  /// Accepted pairs by how: "accepted" (3D-3D) or "accepted by PnP".
  std::map<std::string, int> acceptances;
};

/// Builds an image node from each frame and matches each one with the previous one. Deterministic
/// for a seed: pair k draws its RANSAC samples from Rng(seed).fork(k). Precondition:
/// validate(options.node) and validate(options.matcher) are empty. Cost: frames node creations
/// plus frames - 1 node matches (figures in docs/fusion-results.md).
[[nodiscard]] StationaryMatchingSummary match_consecutive_frames(
    std::span<const PosedFrame> frames, const StationaryMatchingOptions& options,
    std::uint64_t seed);

}  // namespace tessera::fusion
