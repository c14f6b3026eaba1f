#include "tessera/fusion/feature_type.hpp"

namespace tessera::fusion {

std::string_view to_string(FeatureType type) {
  switch (type) {
    case FeatureType::kOrb:
      return "orb";
    case FeatureType::kSift:
      return "sift";
    case FeatureType::kAkaze:
      return "akaze";
  }
  return "orb";
}

Result<FeatureType> parse_feature_type(std::string_view name) {
  if (name == "orb") return FeatureType::kOrb;
  if (name == "sift") return FeatureType::kSift;
  if (name == "akaze") return FeatureType::kAkaze;
  std::string message =
      "unknown feature type '" + std::string(name) + "' (expected orb, sift or akaze)";
  if (name == "surf") message += "; SURF is nonfree and not built into Debian's OpenCV";
  return input_error(std::move(message));
}

}  // namespace tessera::fusion
