#include "tessera/fusion/appearance_recall.hpp"

#include <algorithm>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/features2d.hpp>

#include "internal/opencv_features.hpp"
#include "tessera/core/assert.hpp"
#include "tessera/fusion/descriptor_matching.hpp"

namespace tessera::fusion {

std::optional<std::string> validate(const AppearanceOptions& o) {
  if (o.max_features < 1) return "max_features must be >= 1";
  if (!(o.ratio > 0.0 && o.ratio <= 1.0)) return "ratio must be in (0, 1]";
  if (o.min_matches < 15) {
    return "min_matches must be >= 15 (the least for which findFundamentalMat runs RANSAC)";
  }
  if (!(o.epipolar_threshold_px > 0.0)) return "epipolar_threshold_px must be > 0";
  if (!(o.ransac_confidence > 0.0 && o.ransac_confidence < 1.0)) {
    return "ransac_confidence must be in (0, 1)";
  }
  if (o.ransac_max_iterations < 1) return "ransac_max_iterations must be >= 1";
  if (o.short_term_memory < 0) return "short_term_memory must be >= 0";
  return std::nullopt;
}

ImageDescription describe_image(const GrayImageView& image, const AppearanceOptions& o) {
  TESSERA_ASSERT(image.consistent());
  TESSERA_ASSERT(!validate(o));
  const cv::Mat gray(image.height, image.width, CV_8U, const_cast<std::uint8_t*>(image.pixels.data()));
  const cv::Ptr<cv::Feature2D> extractor = internal::make_extractor(o.feature_type, o.max_features);
  std::vector<cv::KeyPoint> keypoints;
  extractor->detect(gray, keypoints);
  if (static_cast<int>(keypoints.size()) > o.max_features) {
    // retainBest keeps ties at the cut; keep the count exact and the order deterministic (as
    // image_node.cpp does).
    cv::KeyPointsFilter::retainBest(keypoints, o.max_features);
    std::stable_sort(keypoints.begin(), keypoints.end(),
                     [](const cv::KeyPoint& a, const cv::KeyPoint& b) {
                       return a.response > b.response;
                     });
    keypoints.resize(static_cast<std::size_t>(o.max_features));
  }
  cv::Mat descriptors;
  extractor->compute(gray, keypoints, descriptors);  // may drop keypoints near the border

  ImageDescription d;
  d.feature_type = o.feature_type;
  if (descriptors.rows != static_cast<int>(keypoints.size())) return d;  // no usable features
  d.u_px.reserve(keypoints.size());
  d.v_px.reserve(keypoints.size());
  for (const cv::KeyPoint& k : keypoints) {
    d.u_px.push_back(k.pt.x);
    d.v_px.push_back(k.pt.y);
  }
  Descriptors& s = d.descriptors;
  s.count = descriptors.rows;
  s.length = descriptors.cols;
  if (s.count == 0) return d;
  if (is_binary(o.feature_type)) {
    TESSERA_ASSERT(descriptors.type() == CV_8U);
    s.binary.resize(static_cast<std::size_t>(s.count) * static_cast<std::size_t>(s.length));
    for (int r = 0; r < s.count; ++r) {
      std::copy_n(descriptors.ptr<std::uint8_t>(r), s.length,
                  s.binary.begin() + static_cast<std::ptrdiff_t>(r) * s.length);
    }
  } else {
    TESSERA_ASSERT(descriptors.type() == CV_32F);
    s.real.resize(static_cast<std::size_t>(s.count) * static_cast<std::size_t>(s.length));
    for (int r = 0; r < s.count; ++r) {
      std::copy_n(descriptors.ptr<float>(r), s.length,
                  s.real.begin() + static_cast<std::ptrdiff_t>(r) * s.length);
    }
  }
  return d;
}

namespace {

/// The pixel positions of a pair's matched features (query's, candidate's).
struct MatchedPoints {
  std::vector<cv::Point2f> query, candidate;
};

/// Ratio test on the two nearest candidate features of each query feature, then the mutual test
/// (as node_matcher.cpp).
MatchedPoints matched_points(const ImageDescription& query, const ImageDescription& candidate,
                             const AppearanceOptions& o) {
  MatchedPoints p;
  for (const DescriptorMatch& m : ratio_test_matches(query.descriptors, candidate.descriptors,
                                                     query.feature_type, o.ratio, o.mutual)) {
    const auto iq = static_cast<std::size_t>(m.query);
    const auto ic = static_cast<std::size_t>(m.train);
    p.query.emplace_back(static_cast<float>(query.u_px[iq]), static_cast<float>(query.v_px[iq]));
    p.candidate.emplace_back(static_cast<float>(candidate.u_px[ic]),
                             static_cast<float>(candidate.v_px[ic]));
  }
  return p;
}

/// The matches and, when there are at least min_matches, how many of them one epipolar geometry
/// explains.
PairScore verified(const MatchedPoints& p, const AppearanceOptions& o) {
  PairScore score;
  score.matches = static_cast<int>(p.query.size());
  if (score.matches < o.min_matches) return score;
  // Geometric verification. FM_RANSAC (with 15 or more points) draws its samples from a cv::RNG
  // that each call seeds with the same constant (OpenCV ptsetreg.cpp), so it is deterministic.
  std::vector<std::uint8_t> mask;
  const cv::Mat F =
      cv::findFundamentalMat(p.query, p.candidate, cv::FM_RANSAC, o.epipolar_threshold_px,
                             o.ransac_confidence, o.ransac_max_iterations, mask);
  if (F.empty() || mask.size() != p.query.size()) return score;
  score.inliers = static_cast<int>(
      std::count_if(mask.begin(), mask.end(), [](std::uint8_t m) { return m != 0; }));
  return score;
}

}  // namespace

PairScore score_image_pair(const ImageDescription& query, const ImageDescription& candidate,
                           const AppearanceOptions& o) {
  TESSERA_ASSERT(query.feature_type == candidate.feature_type);
  TESSERA_ASSERT(!validate(o));
  return verified(matched_points(query, candidate, o), o);
}

std::vector<LoopHypothesis> best_loop_hypotheses(std::span<const ImageDescription> images,
                                                 const AppearanceOptions& o) {
  TESSERA_ASSERT(!validate(o));
  std::vector<LoopHypothesis> out;
  out.reserve(images.size());
  const int n = static_cast<int>(images.size());
  for (int i = 0; i < n; ++i) {
    LoopHypothesis h;
    h.query = i;
    const std::size_t qi = static_cast<std::size_t>(i);
    TESSERA_ASSERT(images[qi].feature_type == o.feature_type);
    // Every candidate's matches first; the geometric verification (most of the cost) then runs
    // from the most matches down and stops where a candidate's matches, the most inliers it could
    // have, cannot beat the best so far: the same hypothesis as verifying every candidate, where
    // the most inliers win and the lower index wins a tie.
    std::vector<MatchedPoints> matched;
    std::vector<int> order;
    for (int j = 0; j < i - o.short_term_memory; ++j) {
      matched.push_back(matched_points(images[qi], images[static_cast<std::size_t>(j)], o));
      order.push_back(j);
    }
    const auto size_of = [&](int j) { return matched[static_cast<std::size_t>(j)].query.size(); };
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return size_of(a) > size_of(b); });
    for (const int j : order) {
      const int most = static_cast<int>(size_of(j));
      if (most < h.score || most == 0) break;
      // At best a tie, which the lower index wins.
      if (most == h.score && j > h.candidate) continue;
      const PairScore s = verified(matched[static_cast<std::size_t>(j)], o);
      if (s.inliers > h.score || (s.inliers == h.score && s.inliers > 0 && j < h.candidate)) {
        h.candidate = j;
        h.score = s.inliers;
        h.matches = s.matches;
      }
    }
    out.push_back(h);
  }
  return out;
}

}  // namespace tessera::fusion
