#pragma once
// OpenCV glue shared by the fusion sources that detect and match features (image_node.cpp,
// appearance_recall.cpp, node_matcher.cpp). Private, so OpenCV stays out of the public headers.
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/image_node.hpp"

namespace tessera::fusion::internal {

/// The OpenCV detector and descriptor extractor of `type` (thesis section 4.3.1). ORB and SIFT keep
/// the max_features strongest keypoints; AKAZE has no such limit and ignores it.
[[nodiscard]] inline cv::Ptr<cv::Feature2D> make_extractor(FeatureType type, int max_features) {
  switch (type) {
    case FeatureType::kOrb:
      return cv::ORB::create(max_features);
    case FeatureType::kSift:
      return cv::SIFT::create(max_features);
    case FeatureType::kAkaze:
      return cv::AKAZE::create();
  }
  return cv::ORB::create(max_features);
}

/// Descriptors of `type` as a cv::Mat over their own buffer, one row per feature: CV_8U for binary
/// types, CV_32F for SIFT; empty when there are none. No copy: the matrix points into `d`, so it
/// lives no longer than `d`, and callers only read it (hence the const_cast).
[[nodiscard]] inline cv::Mat descriptor_mat(const Descriptors& d, FeatureType type) {
  if (d.count == 0) return {};
  if (is_binary(type)) {
    return {d.count, d.length, CV_8U, const_cast<std::uint8_t*>(d.binary.data())};
  }
  return {d.count, d.length, CV_32F, const_cast<float*>(d.real.data())};
}

}  // namespace tessera::fusion::internal
