// The pair policy (fusion/frame_pair_match.hpp): features first; the depth ICP only when the
// colour images hold too few features, never when the depth itself is missing.
#include "tessera/fusion/frame_pair_match.hpp"

#include <gtest/gtest.h>

#include <numbers>

#include "support/data.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/sim/blank_room.hpp"

namespace tessera::fusion {
namespace {

struct Frames {
  RgbdFrame prev;
  RgbdFrame curr;
  Eigen::Isometry3d T_prev_curr;
};

/// The blank room's corner with the floor, before and after a small motion.
Frames blank_corner() {
  Result<BlankRoom> room = make_blank_room();
  EXPECT_TRUE(room);
  const BlankView& view = room->views[3];
  EXPECT_EQ(view.name, "corner and floor (3.2 m)");
  const Pose2 next = view.T_world_robot * Pose2{0.03, -0.02, 2.0 * std::numbers::pi / 180.0};
  Rng rng(5);
  const double h = room->camera.options().mount_height_m;
  return {room->camera.render(view.T_world_robot, 0.0, 0.0, rng),
          room->camera.render(next, 0.0, 1.0, rng),
          optical_frame_pose(0.0, view.T_world_robot, 0.0, h).transform().inverse() *
              optical_frame_pose(1.0, next, 0.0, h).transform()};
}

TEST(FramePairMatch, ABlankCornerIsSolvedByDepthWhenFeaturesAreTooFew) {
  const Frames f = blank_corner();
  Rng rng(1);
  const FramePairMatch m = match_frame_pair(f.prev, f.curr, {}, rng);
  ASSERT_TRUE(m.prev && m.curr);
  EXPECT_TRUE(features_too_few(m));
  ASSERT_TRUE(m.depth);
  ASSERT_TRUE(m.accepted) << m.depth->reason_text;
  EXPECT_LT((f.T_prev_curr.inverse() * m.T_prev_curr).translation().norm(), 0.02);

  // The thesis' method alone refuses the same pair.
  FramePairOptions features_only;
  features_only.method = PairMethod::kFeatures;
  Rng rng2(1);
  const FramePairMatch thesis = match_frame_pair(f.prev, f.curr, features_only, rng2);
  EXPECT_FALSE(thesis.accepted);
  EXPECT_FALSE(thesis.depth);
}

TEST(FramePairMatch, DepthOnlySkipsTheFeatures) {
  const Frames f = blank_corner();
  FramePairOptions o;
  o.method = PairMethod::kDepthIcp;
  Rng rng(1);
  const FramePairMatch m = match_frame_pair(f.prev, f.curr, o, rng);
  EXPECT_FALSE(m.prev);
  EXPECT_FALSE(m.features);
  ASSERT_TRUE(m.depth);
  EXPECT_TRUE(m.accepted);
}

TEST(FramePairMatch, MissingDepthIsNotHandedToTheIcp) {
  Frames f = blank_corner();
  std::fill(f.curr.depth_m.begin(), f.curr.depth_m.end(), 0.0f);
  Rng rng(1);
  const FramePairMatch m = match_frame_pair(f.prev, f.curr, {}, rng);
  ASSERT_TRUE(m.curr);
  EXPECT_EQ(m.curr->check, NodeCheck::kTooLittleDepth);
  EXPECT_FALSE(features_too_few(m));
  EXPECT_FALSE(m.depth);
  EXPECT_FALSE(m.accepted);
}

TEST(FramePairMatch, ATexturedPairIsSolvedByFeaturesAlone) {
  const auto folder = support::data_path("rgbd/tum_fr1_xyz_pairs/case_1");
  TESSERA_REQUIRE_DATA(folder);
  const Result<RgbdPair> pair = read_rgbd_pair_folder(folder);
  ASSERT_TRUE(pair) << pair.error().message;
  Rng rng(1);
  const FramePairMatch m = match_frame_pair(pair->prev, pair->curr, {}, rng);
  ASSERT_TRUE(m.features);
  EXPECT_TRUE(m.features->accepted);
  EXPECT_TRUE(m.accepted);
  EXPECT_FALSE(m.depth);
}

TEST(PairMethod, NamesRoundTripAndUnknownNamesAreUsageErrors) {
  for (const PairMethod m : {PairMethod::kAuto, PairMethod::kFeatures, PairMethod::kDepthIcp}) {
    const Result<PairMethod> parsed = parse_pair_method(to_string(m));
    ASSERT_TRUE(parsed);
    EXPECT_EQ(*parsed, m);
  }
  const Result<PairMethod> bad = parse_pair_method("icp");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.error().kind, ErrorKind::kUsage);
  EXPECT_NE(bad.error().message.find("depth-icp"), std::string::npos);
}

}  // namespace
}  // namespace tessera::fusion
