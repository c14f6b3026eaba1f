#pragma once
// The image features an image node is built from (thesis section 4.3.1: "Three different feature
// extraction methods were used in this project which were SIFT, SURF and ORB"). tessera offers
// ORB, SIFT and AKAZE through OpenCV 4.6 as Debian packages it; SURF is patented ("nonfree") and
// not built into Debian's OpenCV, so AKAZE (Alcantarilla et al. 2013) takes its place.
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"

namespace tessera::fusion {

enum class FeatureType {
  kOrb,    // Rublee et al. 2011: FAST corners + rotated BRIEF, 32-byte binary descriptors
  kSift,   // Lowe 2004: difference-of-Gaussians + 128 float gradient histograms
  kAkaze,  // Alcantarilla et al. 2013: nonlinear scale space + 61-byte binary M-LDB descriptors
};

/// "orb", "sift" or "akaze".
[[nodiscard]] std::string_view to_string(FeatureType type);

/// Parses "orb", "sift" or "akaze" (lower case, as the CLI and YAML spell them). kInput error
/// "unknown feature type 'surf' (expected orb, sift or akaze)" otherwise; SURF gets a note that it
/// is not in Debian's OpenCV.
[[nodiscard]] Result<FeatureType> parse_feature_type(std::string_view name);

/// True for binary descriptors compared by Hamming distance (ORB, AKAZE); false for SIFT's float
/// descriptors compared by Euclidean distance.
[[nodiscard]] constexpr bool is_binary(FeatureType type) { return type != FeatureType::kSift; }

}  // namespace tessera::fusion
