#pragma once
// Feature correspondences between two images' descriptors (thesis 4.3.1; Lowe 2004 section 7.1):
// the nearest train descriptor of each query descriptor, kept when it is clearly nearer than the
// second nearest (the ratio test) and, when asked, when the query descriptor is in turn that train
// descriptor's nearest (the mutual test). Used by node_matcher.cpp and appearance_recall.cpp.
//
// Exhaustive, as OpenCV's BFMatcher, and the same matches as BFMatcher::knnMatch(k = 2) with
// BFMatcher::match the other way (ties go to the lower index; the distances are OpenCV's
// Hamming and L2 distances), but in one pass over the distance matrix instead of two, and with
// binary descriptors compared 64 bits at a time by the processor's popcount instead of a call
// per pair: ORB's 1,000 x 1,000 descriptors in about a tenth of the time (docs/fusion-recall.md).
#include <vector>

#include "tessera/fusion/feature_type.hpp"
#include "tessera/fusion/image_node.hpp"

namespace tessera::fusion {

struct DescriptorMatch {
  int query = 0;  // row of the query descriptors
  int train = 0;  // row of the train descriptors
};

/// The matches of `query` in `train`, in query order. `type` says how the rows compare: Hamming
/// distance for binary descriptors (is_binary), Euclidean for float ones. Empty when `train` has
/// fewer than two rows (no second nearest to test against). Preconditions: both hold descriptors
/// of `type` of the same length; 0 < ratio <= 1.
[[nodiscard]] std::vector<DescriptorMatch> ratio_test_matches(const Descriptors& query,
                                                              const Descriptors& train,
                                                              FeatureType type, double ratio,
                                                              bool mutual);

}  // namespace tessera::fusion
