#include "tessera/sim/stationary_scene.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <set>

#include "sim/rgbd_room.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

std::vector<WallTexture> four_photos() {
  return {support::test_photo(), support::test_photo(320, 240), support::test_photo(200, 150),
          support::test_photo(128, 96)};
}

StationaryScene scene_without_noise() {
  RgbdCameraOptions o;
  o.depth_noise_coefficient_1_per_m = 0.0;
  Result<StationaryScene> s = make_stationary_scene(four_photos(), o);
  EXPECT_TRUE(s.ok());
  return std::move(s).value();
}

std::size_t distinct_colours(const RgbdFrame& f) {
  std::set<std::array<std::uint8_t, 3>> colours;
  for (std::size_t i = 0; i + 2 < f.rgb.size(); i += 3) {
    colours.insert({f.rgb[i], f.rgb[i + 1], f.rgb[i + 2]});
  }
  return colours.size();
}

TEST(StationaryScene, FewerThanFourPhotosIsAnInputError) {
  const Result<StationaryScene> s = make_stationary_scene({support::test_photo()});
  ASSERT_FALSE(s.ok());
  EXPECT_EQ(s.error().kind, ErrorKind::kInput);
  EXPECT_THAT(s.error().message, HasSubstr("need 4 photos, got 1"));
}

TEST(StationaryScene, EachViewFacesItsWallAtItsDistance) {
  const StationaryScene scene = scene_without_noise();
  ASSERT_EQ(scene.views.size(), 6u);
  StationaryCaptureOptions o;
  o.frames = 1;
  o.rgb_noise_sigma = 0.0;
  for (const StationaryView& v : scene.views) {
    const RgbdFrame f = capture_stationary_view(scene.camera, v, o, 1).front().frame;
    // Depth is z along the optical axis: the image centre sees the wall (or the corner) ahead.
    EXPECT_NEAR(f.depth_m[240 * 640 + 320], v.distance_m, 0.03) << v.name;
  }
}

TEST(StationaryScene, TexturedViewsShowAPosterAndBlankViewsOnlyPlainSurfaces) {
  const StationaryScene scene = scene_without_noise();
  StationaryCaptureOptions o;
  o.frames = 1;
  o.rgb_noise_sigma = 0.0;
  for (const StationaryView& v : scene.views) {
    const RgbdFrame f = capture_stationary_view(scene.camera, v, o, 1).front().frame;
    if (v.textured) {
      EXPECT_GT(distinct_colours(f), 1000u) << v.name;
    } else {
      // Wall faces of two orientations at most, the floor and the ceiling.
      EXPECT_LE(distinct_colours(f), 4u) << v.name;
    }
  }
}

TEST(StationaryScene, CapturesDifferOnlyByNoiseAndTheNeckAlternates) {
  const StationaryScene scene = scene_without_noise();
  StationaryCaptureOptions o;
  o.frames = 4;
  o.rgb_noise_sigma = 0.0;
  o.neck_turn_rad = 0.05;
  const auto turning = capture_stationary_view(scene.camera, scene.views[0], o, 1);
  ASSERT_EQ(turning.size(), 4u);
  EXPECT_EQ(turning[0].neck_pan_rad, 0.0);
  EXPECT_EQ(turning[1].neck_pan_rad, 0.05);
  EXPECT_EQ(turning[2].neck_pan_rad, 0.0);
  EXPECT_EQ(turning[3].neck_pan_rad, 0.05);
  // Without noise, captures at the same neck angle are the same image; a turn changes it.
  EXPECT_EQ(turning[0].frame.rgb, turning[2].frame.rgb);
  EXPECT_NE(turning[0].frame.rgb, turning[1].frame.rgb);
  EXPECT_DOUBLE_EQ(turning[3].frame.t_s, 3.0);

  o.neck_turn_rad = 0.0;
  o.rgb_noise_sigma = 2.0;
  const auto still = capture_stationary_view(scene.camera, scene.views[0], o, 1);
  EXPECT_NE(still[0].frame.rgb, still[1].frame.rgb);  // independent colour noise per capture
  double sum2 = 0.0;
  for (std::size_t i = 0; i < still[0].frame.rgb.size(); ++i) {
    const double d = double(still[0].frame.rgb[i]) - turning[0].frame.rgb[i];
    sum2 += d * d;
  }
  EXPECT_NEAR(std::sqrt(sum2 / double(still[0].frame.rgb.size())), 2.0, 0.2);
  // The same seed gives the same captures.
  const auto again = capture_stationary_view(scene.camera, scene.views[0], o, 1);
  EXPECT_EQ(again[1].frame.rgb, still[1].frame.rgb);
}

TEST(StationaryScene, ValidateNamesTheBrokenField) {
  EXPECT_FALSE(validate(StationaryCaptureOptions{}).has_value());
  StationaryCaptureOptions o;
  o.frames = 0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("frames"));
  o = {};
  o.neck_turn_rad = 2.0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("neck_turn_rad"));
  o = {};
  o.rgb_noise_sigma = -1.0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("rgb_noise_sigma"));
}

}  // namespace
}  // namespace tessera
