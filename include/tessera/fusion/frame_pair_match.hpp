#pragma once
// The motion between two RGB-D frames: features first (image_node.hpp and node_matcher.hpp), and
// where the colour images hold too few features to decide (a blank wall, a plain corner: thesis
// section 5.2.3), the depth images alone (depth_icp.hpp; issue 18 item 10). The depth ICP is not
// tried when the feature path refused for a reason that geometry cannot answer: too little depth,
// inconsistent frames, or a depth image that contradicts its colour image.
#include <Eigen/Geometry>
#include <optional>
#include <string_view>

#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/fusion/depth_icp.hpp"
#include "tessera/fusion/image_node.hpp"
#include "tessera/fusion/node_matcher.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

enum class PairMethod {
  kAuto,      // features, then the depth ICP when features are too few
  kFeatures,  // features only (the thesis' method)
  kDepthIcp,  // the depth ICP only
};

/// "auto", "features", "depth-icp".
[[nodiscard]] std::string_view to_string(PairMethod method);
/// Inverse of to_string; a usage error listing the names otherwise.
[[nodiscard]] Result<PairMethod> parse_pair_method(std::string_view name);

struct FramePairOptions {
  PairMethod method = PairMethod::kAuto;
  ImageNodeOptions node;
  NodeMatcherOptions matcher;
  DepthIcpOptions icp;
};

struct FramePairMatch {
  /// Not built with kDepthIcp.
  std::optional<NodeCreation> prev;
  std::optional<NodeCreation> curr;
  /// When both nodes were built.
  std::optional<MatchResult> features;
  /// When the depth ICP ran.
  std::optional<DepthIcpResult> depth;
  bool accepted = false;
  /// Maps points in the current camera frame into the previous one; meaningful when accepted.
  Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();
};

/// True when the feature path of `m` refused only for lack of features: a frame with too few
/// features (or too few with depth), or a match with too few matches or inliers, a low inlier
/// share, or inliers concentrated or degenerate.
[[nodiscard]] bool features_too_few(const FramePairMatch& m);

/// Matches `curr` against `prev` by options.method (see the file comment). Deterministic for a
/// given rng state. Preconditions: validate() of each option struct is empty.
[[nodiscard]] FramePairMatch match_frame_pair(const RgbdFrame& prev, const RgbdFrame& curr,
                                              const FramePairOptions& options, Rng& rng);

}  // namespace tessera::fusion
