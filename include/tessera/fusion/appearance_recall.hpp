#pragma once
// Appearance-based recall of earlier places from monocular images (issue 5, item 7; thesis
// section 6.2 item 4): for each new image, which earlier image shows the same place? Scored as
// RTAB-Map scores its loop-closure detector on its sample set (Labbe & Michaud 2013; tools/
// ConsoleApp/main.cpp): each query image gets one hypothesis, the best-scoring earlier image, and
// the hypotheses are swept by score for recall at 100% precision (loop_recall.hpp).
//
// The score is a 2D image-matching score, with no depth and no poses:
//  1. ORB, SIFT or AKAZE features on the grey image (feature_type.hpp);
//  2. descriptor matching: nearest neighbours by Hamming (ORB, AKAZE) or Euclidean (SIFT)
//     distance, Lowe's ratio test (Lowe 2004, section 7.1) and a mutual check;
//  3. geometric verification: a fundamental matrix by RANSAC (Hartley & Zisserman 2004, section
//     11.6; OpenCV's findFundamentalMat with FM_RANSAC, whose random generator starts from a fixed
//     state on every call, so the result is the same on every run); score = its inlier count.
// Images in the short-term memory (the last `short_term_memory` images before the query) are not
// candidates, as in RTAB-Map, whose consecutive images look alike without being loop closures.
//
// No file I/O: images come in as plain grey buffers; io/loop_closure_set.hpp loads RTAB-Map's set.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/image_node.hpp"

namespace tessera::fusion {

/// A grey image as a plain buffer: width * height bytes, row-major, row 0 at the top.
struct GrayImageView {
  int width = 0;
  int height = 0;
  std::span<const std::uint8_t> pixels;

  /// True when the buffer matches width x height and the image is not empty.
  [[nodiscard]] bool consistent() const {
    return width > 0 && height > 0 &&
           pixels.size() == static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
};

struct AppearanceOptions {
  FeatureType feature_type = FeatureType::kOrb;
  /// Strongest keypoints kept per image.
  int max_features = 1000;
  /// Lowe's ratio (0.8 as in Lowe 2004 and node_matcher.hpp) and the mutual nearest-neighbour check.
  double ratio = 0.8;
  bool mutual = true;
  /// Fewer descriptor matches than this score 0 without a RANSAC. 15 is the least for which
  /// OpenCV's findFundamentalMat runs RANSAC (below it falls back to least-median of squares).
  int min_matches = 15;
  /// RANSAC inlier threshold: distance of a point to its epipolar line, pixels.
  double epipolar_threshold_px = 1.0;
  double ransac_confidence = 0.999;
  int ransac_max_iterations = 2000;
  /// Images right before the query that are not candidates: RTAB-Map's default short-term memory
  /// size (Parameters.h, Mem/STMSize = 10).
  int short_term_memory = 10;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const AppearanceOptions& o);

/// An image's keypoints (pixel centres at integers) and descriptors, as image_node.hpp stores them.
struct ImageDescription {
  FeatureType feature_type = FeatureType::kOrb;
  std::vector<double> u_px;  // column of keypoint i
  std::vector<double> v_px;  // row of keypoint i, 0 at the top
  Descriptors descriptors;   // row i describes keypoint i

  [[nodiscard]] int size() const { return static_cast<int>(u_px.size()); }
};

/// Features of one image. Deterministic. Preconditions: image.consistent(), validate(o) is empty.
/// Cost: one feature extraction (figures in docs/fusion-recall.md).
[[nodiscard]] ImageDescription describe_image(const GrayImageView& image,
                                              const AppearanceOptions& o);

struct PairScore {
  int matches = 0;  // descriptor matches after the ratio and mutual tests
  int inliers = 0;  // fundamental-matrix inliers: the score; 0 when verification did not run
};

/// The image-matching score of two described images. Symmetric up to the order of matches.
/// Deterministic. Preconditions: both built with the same feature type; validate(o) is empty.
/// Cost: an exhaustive descriptor search, O(n_a * n_b) distances (descriptor_matching.hpp), plus
/// one RANSAC.
[[nodiscard]] PairScore score_image_pair(const ImageDescription& query,
                                         const ImageDescription& candidate,
                                         const AppearanceOptions& o);

/// One query image's hypothesis: the earlier image (0-based index) with the highest score, the
/// lower index on a tie; candidate -1 and score 0 when no candidate scored above 0.
struct LoopHypothesis {
  int query = 0;
  int candidate = -1;
  int score = 0;
  int matches = 0;
};

/// Hypotheses for every image in order: image i is scored against images 0 .. i - 1 -
/// o.short_term_memory (none for the first images). Deterministic. Precondition: validate(o) is
/// empty; every description has o.feature_type. Cost: O(n^2) descriptor searches; RANSAC only
/// for the candidates whose matches could still beat the best inliers so far (most matches first).
[[nodiscard]] std::vector<LoopHypothesis> best_loop_hypotheses(
    std::span<const ImageDescription> images, const AppearanceOptions& o);

}  // namespace tessera::fusion
