#include "tessera/fusion/node_matcher.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "support/data.hpp"
#include "synthetic_wall.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"

namespace tessera::fusion {
namespace {

using ::testing::AnyOf;
using ::testing::HasSubstr;

const std::filesystem::path kPairs = "rgbd/tum_fr1_xyz_pairs";

struct Error3 {
  double translation_m = 0.0;
  double rotation_deg = 0.0;
};

Error3 error_of(const Eigen::Isometry3d& estimate, const Eigen::Isometry3d& truth) {
  const Eigen::Isometry3d d = truth.inverse() * estimate;
  return {d.translation().norm(), Eigen::AngleAxisd(d.linear()).angle() * 180.0 / std::numbers::pi};
}

ImageNode node_of(const RgbdFrame& frame, FeatureType type, ImageNodeOptions o = {}) {
  o.feature_type = type;
  NodeCreation c = create_image_node(frame, {}, o);
  EXPECT_TRUE(c.ok()) << c.reason;
  return std::move(c.node);
}

MatchResult match_pair(const RgbdPair& pair, FeatureType type, std::uint64_t seed = 1,
                       const NodeMatcherOptions& o = {}) {
  Rng rng(seed);
  return match_nodes(node_of(pair.prev, type), node_of(pair.curr, type), o, rng);
}

RgbdPair read_case(const char* name) {
  Result<RgbdPair> pair = read_rgbd_pair_folder(support::data_path(kPairs / name));
  EXPECT_TRUE(pair.ok()) << pair.error().message;
  return pair.ok() ? std::move(pair).value() : RgbdPair{};
}

constexpr FeatureType kAllTypes[] = {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze};

// Issue 5: case_1's transform within 1 cm and 0.5 degrees of ground truth for each feature type
// (the thesis reported 2.9 to 15.9 cm for a robot standing still, Table 5.5).
TEST(NodeMatcher, RealCase1WithinOneCentimetreAndHalfADegreeForEveryFeatureType) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  const RgbdPair pair = read_case("case_1");
  ASSERT_TRUE(pair.has_ground_truth);
  for (const FeatureType type : kAllTypes) {
    const MatchResult r = match_pair(pair, type);
    ASSERT_TRUE(r.accepted) << to_string(type) << ": " << r.reason_text;
    EXPECT_EQ(r.reason, MatchReason::kAccepted) << to_string(type) << ": " << r.reason_text;
    EXPECT_EQ(r.method, MatchMethod::kRigid3d);
    const Error3 e = error_of(r.T_prev_curr, pair.T_prev_curr_truth());
    EXPECT_LT(e.translation_m, 0.01) << to_string(type) << ": " << r.reason_text;
    EXPECT_LT(e.rotation_deg, 0.5) << to_string(type) << ": " << r.reason_text;
    EXPECT_GE(r.inliers, 100) << to_string(type);
    RecordProperty(std::string(to_string(type)) + "_t_error_mm",
                   std::to_string(1000.0 * e.translation_m));
    std::printf(
        "case_1 %-5s matches %4d  3d %4d  inliers %4d  t %.4f m  r %.3f deg  reproj %.2f px  "
        "vs PnP %.4f m %.3f deg, chi2 %.1f\n",
        std::string(to_string(type)).c_str(), r.matches, r.matches_3d, r.inliers, e.translation_m,
        e.rotation_deg, r.median_reprojection_px, r.pnp_disagreement_m,
        r.pnp_disagreement_rad * 180.0 / std::numbers::pi, r.pnp_disagreement_chi2);
  }
}

// case_2's current depth image is a byte copy of case_1's (SOURCES.md): a 3D-3D estimate from it
// must not be accepted wrong. It is either rejected or solved from the previous depth alone.
TEST(NodeMatcher, RealCase2WithWrongDepthIsNeverAcceptedWrong) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_2"));
  const RgbdPair pair = read_case("case_2");
  ASSERT_TRUE(pair.has_ground_truth);
  for (const FeatureType type : kAllTypes) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
      const MatchResult r = match_pair(pair, type, seed);
      const Error3 e = error_of(r.T_prev_curr, pair.T_prev_curr_truth());
      std::printf("case_2 %-5s seed %d accepted %d reason %-16s t %.4f m  r %.3f deg  %s\n",
                  std::string(to_string(type)).c_str(), static_cast<int>(seed), r.accepted,
                  std::string(to_string(r.reason)).c_str(), e.translation_m, e.rotation_deg,
                  r.reason_text.c_str());
      if (r.accepted) {
        EXPECT_LT(e.translation_m, 0.02) << to_string(type) << ": " << r.reason_text;
        EXPECT_LT(e.rotation_deg, 1.0) << to_string(type) << ": " << r.reason_text;
        // The 3D-3D estimate uses the wrong depth; only the PnP fallback may accept.
        EXPECT_EQ(r.method, MatchMethod::kPnp) << to_string(type) << ": " << r.reason_text;
      }
    }
  }
}

// The same 3D-3D check with the PnP fallback off: the wrong depth is refused with a reason.
TEST(NodeMatcher, RealCase2IsRejectedWhenThePnpFallbackIsOff) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_2"));
  const RgbdPair pair = read_case("case_2");
  NodeMatcherOptions o;
  o.pnp_fallback = false;
  for (const FeatureType type : kAllTypes) {
    const MatchResult r = match_pair(pair, type, 1, o);
    EXPECT_FALSE(r.accepted) << to_string(type) << ": " << r.reason_text;
    EXPECT_THAT(r.reason, AnyOf(MatchReason::kDepthInconsistent, MatchReason::kLowInlierRatio,
                                MatchReason::kTooFewInliers))
        << r.reason_text;
  }
}

TEST(NodeMatcher, SameSeedSameResult) {
  TESSERA_REQUIRE_DATA(support::data_path(kPairs / "case_1"));
  const RgbdPair pair = read_case("case_1");
  const ImageNode prev = node_of(pair.prev, FeatureType::kOrb);
  const ImageNode curr = node_of(pair.curr, FeatureType::kOrb);
  Rng rng1(5), rng2(5);
  const MatchResult a = match_nodes(prev, curr, NodeMatcherOptions{}, rng1);
  const MatchResult b = match_nodes(prev, curr, NodeMatcherOptions{}, rng2);
  EXPECT_EQ(a.inliers, b.inliers);
  EXPECT_TRUE(a.T_prev_curr.matrix() == b.T_prev_curr.matrix());
  EXPECT_EQ(a.reason_text, b.reason_text);
}

// A textured wall seen from two poses: a flat scene is not degenerate for 3D-3D and is recovered.
TEST(NodeMatcher, TexturedWallIsRecoveredForEveryFeatureType) {
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  const testing::WallTexture texture = testing::blob_texture(0.015, 9);
  const Eigen::Isometry3d T_prev_curr = testing::small_motion();
  const RgbdFrame prev = testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, texture, k);
  const RgbdFrame curr = testing::render_wall(T_prev_curr, 2.0, texture, k);
  for (const FeatureType type : kAllTypes) {
    Rng rng(1);
    const MatchResult r = match_nodes(node_of(prev, type), node_of(curr, type), {}, rng);
    ASSERT_TRUE(r.accepted) << to_string(type) << ": " << r.reason_text;
    const Error3 e = error_of(r.T_prev_curr, T_prev_curr);
    EXPECT_LT(e.translation_m, 0.005) << to_string(type);
    EXPECT_LT(e.rotation_deg, 0.2) << to_string(type);
    EXPECT_GT(r.image_coverage, 0.5);
  }
}

// The thesis' blank-wall failure (section 5.2.3): a few features from specks that differ between
// the two views were "forcibly matched", giving 0.38 to 0.80 m errors. Here the nodes are let
// through the feature check on purpose, and the matcher must refuse.
TEST(NodeMatcher, BlankWallWithRandomSpecksIsRejected) {
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  const auto specks = [](std::uint64_t seed) -> testing::WallTexture {
    return [seed](double x_m, double y_m) {
      // Dark specks on a 10 cm lattice, each present with probability 0.1, different per view.
      const auto i = static_cast<std::int64_t>(std::floor(x_m / 0.1));
      const auto j = static_cast<std::int64_t>(std::floor(y_m / 0.1));
      const double fx = x_m / 0.1 - std::floor(x_m / 0.1), fy = y_m / 0.1 - std::floor(y_m / 0.1);
      const bool speck = testing::lattice_value(i, j, seed) < 0.1 && std::abs(fx - 0.5) < 0.1 &&
                         std::abs(fy - 0.5) < 0.1;
      return speck ? 60.0 : 230.0;
    };
  };
  const Eigen::Isometry3d T_prev_curr = testing::small_motion();
  const RgbdFrame prev =
      testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, specks(1), k, 1.0, 1);
  const RgbdFrame curr = testing::render_wall(T_prev_curr, 2.0, specks(2), k, 1.0, 2);
  ImageNodeOptions lenient;
  lenient.min_features = 0;
  lenient.min_features_with_depth = 0;
  for (const FeatureType type : kAllTypes) {
    const ImageNode a = node_of(prev, type, lenient);
    const ImageNode b = node_of(curr, type, lenient);
    EXPECT_GT(a.features.size(), 0u) << to_string(type);
    Rng rng(1);
    const MatchResult r = match_nodes(a, b, {}, rng);
    EXPECT_FALSE(r.accepted) << to_string(type) << ": " << r.reason_text;
    EXPECT_THAT(r.reason, AnyOf(MatchReason::kTooFewMatches, MatchReason::kTooFewInliers))
        << to_string(type) << ": " << r.reason_text;
  }
}

// A feature-sparse view: one small poster on a blank wall. The matches are right but all in one
// corner of the images; the rotation is poorly pinned, so the match is refused with that reason.
TEST(NodeMatcher, SmallPosterOnABlankWallIsRejectedAsConcentrated) {
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  const testing::WallTexture texture = testing::poster_on_blank_wall(-0.6, -0.4, 0.22);
  const Eigen::Isometry3d T_prev_curr = testing::small_motion();
  const RgbdFrame prev = testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, texture, k);
  const RgbdFrame curr = testing::render_wall(T_prev_curr, 2.0, texture, k);
  for (const FeatureType type : kAllTypes) {
    Rng rng(1);
    const MatchResult r = match_nodes(node_of(prev, type), node_of(curr, type), {}, rng);
    EXPECT_FALSE(r.accepted) << to_string(type) << ": " << r.reason_text;
    EXPECT_EQ(r.reason, MatchReason::kInliersConcentrated)
        << to_string(type) << ": " << r.reason_text;
    EXPECT_THAT(r.reason_text, HasSubstr("inliers cover"));
    EXPECT_GE(r.inliers, NodeMatcherOptions{}.min_inliers) << to_string(type);
  }
}

TEST(NodeMatcher, DifferentFeatureTypesAreNotMatched) {
  const RgbdFrame frame =
      testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, testing::blob_texture(0.015, 4),
                           PinholeIntrinsics::kinect_v1());
  Rng rng(1);
  const MatchResult r =
      match_nodes(node_of(frame, FeatureType::kOrb), node_of(frame, FeatureType::kAkaze), {}, rng);
  EXPECT_FALSE(r.accepted);
  EXPECT_EQ(r.reason, MatchReason::kFeatureTypeMismatch);
}

TEST(NodeMatcher, OptionsAreValidated) {
  EXPECT_FALSE(validate(NodeMatcherOptions{}));
  NodeMatcherOptions o;
  o.ratio = 1.5;
  EXPECT_TRUE(validate(o));
  o = {};
  o.ransac.max_iterations = 0;
  ASSERT_TRUE(validate(o));
  EXPECT_THAT(*validate(o), HasSubstr("ransac."));
}

}  // namespace
}  // namespace tessera::fusion
