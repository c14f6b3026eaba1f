#include "tessera/fusion/image_node.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "internal/fixed_text.hpp"
#include "internal/opencv_features.hpp"

namespace tessera::fusion {
namespace {

using internal::fixed;
using internal::make_extractor;

bool in_range(float z_m, const ImageNodeOptions& o) {
  return z_m >= o.min_depth_m && z_m <= o.max_depth_m;
}

double valid_depth_fraction(const RgbdFrame& frame, const ImageNodeOptions& o) {
  std::size_t valid = 0;
  for (const float z : frame.depth_m) valid += in_range(z, o) ? 1u : 0u;
  return frame.depth_m.empty()
             ? 0.0
             : static_cast<double>(valid) / static_cast<double>(frame.depth_m.size());
}

/// The depth at pixel (u, v) if the window around it is in range and flat enough; 0 otherwise.
float usable_depth(const RgbdFrame& frame, double u_px, double v_px, const ImageNodeOptions& o) {
  const int u = static_cast<int>(std::lround(u_px));
  const int v = static_cast<int>(std::lround(v_px));
  const int w = o.depth_window_px;
  if (u - w < 0 || v - w < 0 || u + w >= frame.width || v + w >= frame.height) return 0.0f;
  const auto at = [&](int x, int y) {
    return frame.depth_m[static_cast<std::size_t>(y) * static_cast<std::size_t>(frame.width) +
                         static_cast<std::size_t>(x)];
  };
  const float z = at(u, v);
  if (!in_range(z, o)) return 0.0f;
  const double max_step_m = o.max_depth_step_ratio * z;
  for (int y = v - w; y <= v + w; ++y) {
    for (int x = u - w; x <= u + w; ++x) {
      const float zn = at(x, y);
      if (!in_range(zn, o) || std::abs(zn - z) > max_step_m) return 0.0f;
    }
  }
  return z;
}

}  // namespace

std::optional<std::string> validate(const ImageNodeOptions& o) {
  if (o.max_features < 1) return "max_features must be >= 1";
  if (!(o.min_depth_m > 0.0) || !(o.max_depth_m > o.min_depth_m)) {
    return "depth range must satisfy 0 < min_depth_m < max_depth_m";
  }
  if (!(o.min_valid_depth_fraction >= 0.0 && o.min_valid_depth_fraction <= 1.0)) {
    return "min_valid_depth_fraction must be in [0, 1]";
  }
  if (o.min_features < 0 || o.min_features_with_depth < 0) {
    return "min_features and min_features_with_depth must be >= 0";
  }
  if (o.depth_window_px < 0) return "depth_window_px must be >= 0";
  if (!(o.max_depth_step_ratio >= 0.0)) return "max_depth_step_ratio must be >= 0";
  return std::nullopt;
}

int ImageNode::features_with_depth() const {
  return static_cast<int>(std::count_if(features.begin(), features.end(),
                                        [](const NodeFeature& f) { return f.has_depth; }));
}

std::string_view to_string(NodeCheck check) {
  switch (check) {
    case NodeCheck::kOk:
      return "ok";
    case NodeCheck::kInconsistentFrame:
      return "inconsistent frame";
    case NodeCheck::kTooLittleDepth:
      return "too little valid depth";
    case NodeCheck::kTooFewFeatures:
      return "too few features";
    case NodeCheck::kTooFewFeaturesWithDepth:
      return "too few features with depth";
  }
  return "ok";
}

NodeCreation create_image_node(const RgbdFrame& frame, const NodePlacement& placement,
                               const ImageNodeOptions& options) {
  TESSERA_ASSERT(!validate(options));
  NodeCreation out;
  if (!frame.consistent()) {
    out.check = NodeCheck::kInconsistentFrame;
    out.reason = "inconsistent frame: buffers or intrinsics do not match " +
                 std::to_string(frame.width) + " x " + std::to_string(frame.height);
    return out;
  }
  // Thesis Table 4.1 line 6, "check distance": enough depth inside the effective range.
  out.valid_depth_fraction = valid_depth_fraction(frame, options);
  if (out.valid_depth_fraction < options.min_valid_depth_fraction) {
    out.check = NodeCheck::kTooLittleDepth;
    out.reason = "too little valid depth: " + fixed(100.0 * out.valid_depth_fraction, 1) +
                 "% of the pixels in " + fixed(options.min_depth_m, 2) + " to " +
                 fixed(options.max_depth_m, 2) + " m, need " +
                 fixed(100.0 * options.min_valid_depth_fraction, 1) + "%";
    return out;
  }

  // Grayscale (section 4.3.1), then keypoints and descriptors. cv::Mat wraps the frame's bytes;
  // cvtColor only reads them.
  const cv::Mat rgb(frame.height, frame.width, CV_8UC3,
                    const_cast<std::uint8_t*>(frame.rgb.data()));
  cv::Mat gray;
  cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
  const cv::Ptr<cv::Feature2D> extractor =
      make_extractor(options.feature_type, options.max_features);
  std::vector<cv::KeyPoint> keypoints;
  extractor->detect(gray, keypoints);
  if (static_cast<int>(keypoints.size()) > options.max_features) {
    cv::KeyPointsFilter::retainBest(keypoints, options.max_features);
    // retainBest keeps ties at the cut; keep the count exact and the order deterministic.
    std::stable_sort(
        keypoints.begin(), keypoints.end(),
        [](const cv::KeyPoint& a, const cv::KeyPoint& b) { return a.response > b.response; });
    keypoints.resize(static_cast<std::size_t>(options.max_features));
  }
  cv::Mat descriptors;
  extractor->compute(gray, keypoints, descriptors);  // may drop keypoints near the border
  out.features = static_cast<int>(keypoints.size());
  if (out.features < options.min_features || descriptors.rows != out.features) {
    out.check = NodeCheck::kTooFewFeatures;
    out.reason = "too few features: " + std::to_string(out.features) + " " +
                 std::string(to_string(options.feature_type)) + " keypoints, need " +
                 std::to_string(options.min_features);
    return out;
  }

  ImageNode& node = out.node;
  node.t_s = frame.t_s;
  node.placement = placement;
  node.feature_type = options.feature_type;
  node.intrinsics = frame.intrinsics;
  node.features.reserve(keypoints.size());
  for (const cv::KeyPoint& kp : keypoints) {
    NodeFeature f;
    f.u_px = kp.pt.x;
    f.v_px = kp.pt.y;
    const float z_m = usable_depth(frame, f.u_px, f.v_px, options);
    if (z_m > 0.0f) {
      f.has_depth = true;
      f.point = back_project(frame.intrinsics, f.u_px, f.v_px, z_m);
    }
    node.features.push_back(f);
  }
  Descriptors& d = node.descriptors;
  d.count = descriptors.rows;
  d.length = descriptors.cols;
  if (descriptors.type() == CV_32F) {
    d.real.resize(static_cast<std::size_t>(d.count) * static_cast<std::size_t>(d.length));
    for (int r = 0; r < d.count; ++r) {
      std::memcpy(d.real.data() + static_cast<std::size_t>(r) * d.length, descriptors.ptr<float>(r),
                  sizeof(float) * static_cast<std::size_t>(d.length));
    }
  } else {
    TESSERA_ASSERT(descriptors.type() == CV_8U);
    d.binary.resize(static_cast<std::size_t>(d.count) * static_cast<std::size_t>(d.length));
    for (int r = 0; r < d.count; ++r) {
      std::memcpy(d.binary.data() + static_cast<std::size_t>(r) * d.length,
                  descriptors.ptr<std::uint8_t>(r), static_cast<std::size_t>(d.length));
    }
  }
  out.features_with_depth = node.features_with_depth();
  if (out.features_with_depth < options.min_features_with_depth) {
    out.check = NodeCheck::kTooFewFeaturesWithDepth;
    out.reason = "too few features with depth: " + std::to_string(out.features_with_depth) +
                 " of " + std::to_string(out.features) + " keypoints have a usable depth, need " +
                 std::to_string(options.min_features_with_depth);
    out.node = ImageNode{};
    return out;
  }
  return out;
}

}  // namespace tessera::fusion
