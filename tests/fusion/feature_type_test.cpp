#include "tessera/fusion/feature_type.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace tessera::fusion {
namespace {

using ::testing::HasSubstr;

TEST(FeatureType, NamesRoundTrip) {
  for (const FeatureType t : {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze}) {
    const Result<FeatureType> parsed = parse_feature_type(to_string(t));
    ASSERT_TRUE(parsed.ok()) << to_string(t);
    EXPECT_EQ(*parsed, t);
  }
}

TEST(FeatureType, BinaryDescriptorsAreOrbAndAkaze) {
  EXPECT_TRUE(is_binary(FeatureType::kOrb));
  EXPECT_TRUE(is_binary(FeatureType::kAkaze));
  EXPECT_FALSE(is_binary(FeatureType::kSift));
}

TEST(FeatureType, UnknownNameIsAnInputErrorListingTheChoices) {
  const Result<FeatureType> parsed = parse_feature_type("brisk");
  ASSERT_FALSE(parsed.ok());
  EXPECT_EQ(parsed.error().kind, ErrorKind::kInput);
  EXPECT_THAT(parsed.error().message, HasSubstr("'brisk'"));
  EXPECT_THAT(parsed.error().message, HasSubstr("orb, sift or akaze"));
  EXPECT_FALSE(parse_feature_type("ORB").ok());  // the CLI spelling is lower case
}

TEST(FeatureType, SurfIsExplainedAsNotInDebiansOpenCv) {
  const Result<FeatureType> parsed = parse_feature_type("surf");
  ASSERT_FALSE(parsed.ok());
  EXPECT_THAT(parsed.error().message, HasSubstr("nonfree"));
}

}  // namespace
}  // namespace tessera::fusion
