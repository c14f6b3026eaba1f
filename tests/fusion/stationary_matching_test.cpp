#include "tessera/fusion/stationary_matching.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "support/data.hpp"
#include "tessera/io/tum_rgbd_sequence.hpp"
#include "tessera/render/simulated_rgbd_sequence.hpp"
#include "tessera/render/wall_textures.hpp"
#include "tessera/sim/stationary_scene.hpp"

namespace tessera::fusion {
namespace {

constexpr FeatureType kAllTypes[] = {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze};
constexpr double kNeckTurnRad = 3.0 * std::numbers::pi / 180.0;

/// The scene of docs/fusion-stationary.md (the photos bench/fusion/stationary_table.cpp uses).
Result<StationaryScene> real_photo_scene() {
  const std::filesystem::path rgbd = support::data_path("rgbd");
  Result<std::vector<WallTexture>> photos = read_wall_textures({
      rgbd / "tum_fr1_xyz_pairs/case_1/img_prev.png",
      rgbd / "rtabmap_loop_samples/images/20.jpg",
      rgbd / "rtabmap_loop_samples/images/5.jpg",
      rgbd / "rtabmap_loop_samples/images/30.jpg",
  });
  if (!photos) return photos.error();
  return make_stationary_scene(std::move(photos).value());
}

std::vector<PosedFrame> posed_captures(const StationaryScene& scene, std::size_t view, int frames,
                                       double neck_turn_rad) {
  StationaryCaptureOptions o;
  o.frames = frames;
  o.neck_turn_rad = neck_turn_rad;
  const StationaryView& v = scene.views[view];
  std::vector<PosedFrame> out;
  for (const StationaryCapture& c : capture_stationary_view(scene.camera, v, o, 100 + view)) {
    out.push_back({c.frame, optical_frame_pose(c.frame.t_s, v.T_world_robot, c.neck_pan_rad,
                                               scene.camera.options().mount_height_m)
                                .transform()});
  }
  return out;
}

// Issue 5 / thesis Table 5.5: standing still, the textured views give a mean transform error of at
// most 1 cm for every feature type (the thesis: 2.9 to 15.9 cm), and the blank views give no
// accepted estimate at all, still or turning the neck (the thesis: 0.38 to 0.80 m wrong).
// One test per feature type (about 15 s each), so that ctest runs them in parallel.
class StationaryMatchingPerType : public ::testing::TestWithParam<FeatureType> {};

TEST_P(StationaryMatchingPerType, ThesisStationaryTestTexturedWithinOneCentimetreBlankNeverAccepted) {
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/rtabmap_loop_samples/images"));
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/tum_fr1_xyz_pairs/case_1"));
  const Result<StationaryScene> scene = real_photo_scene();
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  constexpr int kFrames = 5;
  const FeatureType type = GetParam();
  for (std::size_t v = 0; v < scene->views.size(); ++v) {
    const StationaryView& view = scene->views[v];
    for (const double turn : {0.0, kNeckTurnRad}) {
      const std::vector<PosedFrame> frames = posed_captures(*scene, v, kFrames, turn);
      {
        StationaryMatchingOptions o;
        o.node.feature_type = type;
        const StationaryMatchingSummary s = match_consecutive_frames(frames, o, 1);
        const std::string what = std::string(to_string(type)) + " " + view.name +
                                 (turn == 0.0 ? " still" : " neck turns");
        ASSERT_EQ(s.pairs, kFrames - 1);
        if (view.textured && turn == 0.0) {
          EXPECT_EQ(s.accepted, s.pairs) << what;
          EXPECT_LE(s.mean_translation_error_m, 0.01) << what;
          EXPECT_LE(s.mean_rotation_error_rad, 0.5 * std::numbers::pi / 180.0) << what;
        } else if (view.textured) {
          // With 3-degree neck turns ORB and AKAZE hold the bar; SIFT reaches 10.6 to 13.6 mm on
          // the cabinet and the posters (docs/fusion-stationary.md, an open point). This bound
          // keeps that from getting worse.
          EXPECT_EQ(s.accepted, s.pairs) << what;
          EXPECT_LE(s.mean_translation_error_m, 0.015) << what;
          EXPECT_LE(s.mean_rotation_error_rad, 0.5 * std::numbers::pi / 180.0) << what;
        } else {
          EXPECT_EQ(s.accepted, 0) << what << ": mean error " << s.mean_translation_error_m;
        }
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllFeatureTypes, StationaryMatchingPerType, ::testing::ValuesIn(kAllTypes),
                         [](const ::testing::TestParamInfo<FeatureType>& param_info) {
                           return std::string(to_string(param_info.param));
                         });

// The same blank views with the node check switched off (the thesis matched whatever few features
// it found): the matcher itself must refuse every pair.
TEST(StationaryMatching, BlankViewsAreRejectedByTheMatcherEvenWithoutTheNodeCheck) {
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/rtabmap_loop_samples/images"));
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/tum_fr1_xyz_pairs/case_1"));
  const Result<StationaryScene> scene = real_photo_scene();
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  for (std::size_t v = 0; v < scene->views.size(); ++v) {
    if (scene->views[v].textured) continue;
    const std::vector<PosedFrame> frames = posed_captures(*scene, v, 5, kNeckTurnRad);
    for (const FeatureType type : kAllTypes) {
      StationaryMatchingOptions o;
      o.node.feature_type = type;
      o.node.min_features = 0;
      o.node.min_features_with_depth = 0;
      const StationaryMatchingSummary s = match_consecutive_frames(frames, o, 1);
      EXPECT_EQ(s.accepted, 0) << to_string(type) << " " << scene->views[v].name;
      int node_checks = 0;
      for (const auto& [reason, n] : s.rejections) {
        if (reason.starts_with("too few features") || reason == "too little valid depth") {
          node_checks += n;
        }
      }
      EXPECT_EQ(node_checks, 0) << "the node check was off";
    }
  }
}

TEST(StationaryMatching, OneFrameHasNoPairsAndIdenticalFramesMatchExactly) {
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/rtabmap_loop_samples/images"));
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/tum_fr1_xyz_pairs/case_1"));
  const Result<StationaryScene> scene = real_photo_scene();
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  std::vector<PosedFrame> frames = posed_captures(*scene, 0, 1, 0.0);
  const StationaryMatchingSummary one = match_consecutive_frames(frames, {}, 1);
  EXPECT_EQ(one.frames, 1);
  EXPECT_EQ(one.pairs, 0);
  EXPECT_EQ(one.accepted, 0);
  EXPECT_TRUE(one.rejections.empty());
  frames.push_back(frames.front());  // the same capture twice: the estimate is exact
  const StationaryMatchingSummary two = match_consecutive_frames(frames, {}, 1);
  EXPECT_EQ(two.accepted, 1);
  EXPECT_LT(two.mean_translation_error_m, 1e-6);
  EXPECT_EQ(two.acceptances.at("accepted"), 1);
}

TEST(StationaryMatching, AnErrorIsMeasuredAgainstTheTrueMotion) {
  // Claiming the second capture was taken 5 cm further right makes every estimate 5 cm wrong.
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/rtabmap_loop_samples/images"));
  TESSERA_REQUIRE_DATA(support::data_path("rgbd/tum_fr1_xyz_pairs/case_1"));
  const Result<StationaryScene> scene = real_photo_scene();
  ASSERT_TRUE(scene.ok()) << scene.error().message;
  std::vector<PosedFrame> frames = posed_captures(*scene, 0, 2, 0.0);
  frames[1].T_world_camera = frames[1].T_world_camera * Eigen::Translation3d(0.05, 0.0, 0.0);
  const StationaryMatchingSummary s = match_consecutive_frames(frames, {}, 1);
  ASSERT_EQ(s.accepted, 1);
  EXPECT_NEAR(s.mean_translation_error_m, 0.05, 0.01);
}

}  // namespace
}  // namespace tessera::fusion
