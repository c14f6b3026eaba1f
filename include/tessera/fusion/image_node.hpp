#pragma once
// Image nodes (thesis section 4.3.1, "Image Call-back Loop"): an RGB-D frame is checked for enough
// features and enough depth inside the Kinect's effective range, converted to grey, described by
// ORB, SIFT or AKAZE features, and each feature with a depth reading is back-projected to a 3D
// point in the camera frame. The node keeps the robot pose, the neck angle and the hex cell it was
// taken in, so that later nodes can be matched against it (node_matcher.hpp).
//
// OpenCV stays out of this header: descriptors are plain rows of bytes (ORB, AKAZE) or floats
// (SIFT), which the matcher wraps in cv::Mat without copying.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/fusion/feature_type.hpp"
#include "tessera/sensors/pinhole_camera.hpp"
#include "tessera/sensors/rgbd_frame.hpp"

namespace tessera::fusion {

struct ImageNodeOptions {
  FeatureType feature_type = FeatureType::kOrb;
  /// Strongest keypoints kept per image (ORB's and SIFT's nfeatures; AKAZE keeps the strongest of
  /// what its threshold finds). 2000 is what ../shared/data/rgbd/tum_fr1_xyz_pairs/SOURCES.md used.
  int max_features = 2000;
  /// The Kinect v1's effective depth range (thesis section 3.1.3; issue 5: 0.5 to 4.5 m). Depth
  /// outside it counts as no reading.
  double min_depth_m = 0.5;
  double max_depth_m = 4.5;
  /// The thesis' "check distance": at least this share of the image's pixels has a depth reading
  /// in range.
  double min_valid_depth_fraction = 0.2;
  /// The thesis' "check features": at least this many keypoints ...
  int min_features = 30;
  /// ... and at least this many of them with a usable depth (3D points).
  int min_features_with_depth = 20;
  /// A keypoint's depth is the reading at its pixel, used only when every reading within
  /// depth_window_px (a (2w+1)^2 window) is in range and they differ from it by at most
  /// max_depth_step_ratio of it: keypoints on depth edges would otherwise get a mix of foreground
  /// and background (the Kinect's depth and colour edges do not line up exactly).
  int depth_window_px = 1;
  double max_depth_step_ratio = 0.03;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ImageNodeOptions& o);

/// One keypoint of a node. Every keypoint is kept: those without a usable depth still serve as the
/// 2D side of a 3D->2D match (node_matcher.hpp's PnP fallback).
struct NodeFeature {
  double u_px = 0.0;  // column, pixel centres at integers
  double v_px = 0.0;  // row, 0 at the top
  bool has_depth = false;
  CameraPoint point;  // back-projected (pinhole_camera.hpp, optical frame); valid if has_depth
};

/// Row i describes NodeFeature i. ORB and AKAZE: `length` bytes per row in `binary`; SIFT:
/// `length` floats per row in `real`.
struct Descriptors {
  int count = 0;
  int length = 0;
  std::vector<std::uint8_t> binary;
  std::vector<float> real;
};

/// Where and when the node was taken.
struct NodePlacement {
  Pose2 T_map_robot;  // robot pose (the odometry estimate when taken; drift correction moves it)
  double neck_rad = 0.0;      // pan angle of the camera neck, counter-clockwise (thesis 3.1.3)
  std::int64_t cell_id = -1;  // hex cell the node belongs to; -1 when not assigned
};

struct ImageNode {
  double t_s = 0.0;
  NodePlacement placement;
  FeatureType feature_type = FeatureType::kOrb;
  PinholeIntrinsics intrinsics;
  std::vector<NodeFeature> features;
  Descriptors descriptors;

  [[nodiscard]] int features_with_depth() const;
};

/// Why a frame did not become a node (the thesis' checks, section 4.3.1, Table 4.1 lines 6-8).
enum class NodeCheck {
  kOk,
  kInconsistentFrame,        // buffers or intrinsics do not match the frame's size
  kTooLittleDepth,           // valid depth fraction below min_valid_depth_fraction
  kTooFewFeatures,           // fewer than min_features keypoints
  kTooFewFeaturesWithDepth,  // fewer than min_features_with_depth 3D points
};

/// "ok", "too little valid depth", ...
[[nodiscard]] std::string_view to_string(NodeCheck check);

struct NodeCreation {
  NodeCheck check = NodeCheck::kOk;
  std::string reason;  // one line, with the figures; empty when ok
  double valid_depth_fraction = 0.0;
  int features = 0;
  int features_with_depth = 0;
  ImageNode node;  // filled when ok()

  [[nodiscard]] bool ok() const { return check == NodeCheck::kOk; }
};

/// Builds an image node from `frame` (the depth check first, so that a frame without depth costs
/// no feature extraction). Deterministic. Cost: one feature extraction on the grey image (see
/// bench/fusion/fusion_bench.cpp for figures) plus O(pixels) for the depth check.
/// Precondition: validate(options) is empty.
[[nodiscard]] NodeCreation create_image_node(const RgbdFrame& frame, const NodePlacement& placement,
                                             const ImageNodeOptions& options);

}  // namespace tessera::fusion
