#include "tessera/sim/rgbd_camera.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <vector>

#include "sim/rgbd_room.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;
using support::kEastWallX;
using support::kNorthWallY;

double depth_at(const RgbdFrame& f, int u, int v) {
  return f.depth_m[static_cast<std::size_t>(v) * f.width + u];
}
std::array<int, 3> rgb_at(const RgbdFrame& f, int u, int v) {
  const std::size_t i = 3 * (static_cast<std::size_t>(v) * f.width + u);
  return {f.rgb[i], f.rgb[i + 1], f.rgb[i + 2]};
}

/// Pixels whose grey value differs from the right or lower neighbour by more than 25: edges and
/// texture, what a feature detector needs.
int strong_gradients(const RgbdFrame& f) {
  const auto grey = [&](int u, int v) {
    const auto c = rgb_at(f, u, v);
    return (c[0] + c[1] + c[2]) / 3;
  };
  int n = 0;
  for (int v = 0; v + 1 < f.height; ++v) {
    for (int u = 0; u + 1 < f.width; ++u) {
      const int g = grey(u, v);
      n += std::abs(g - grey(u + 1, v)) > 25 || std::abs(g - grey(u, v + 1)) > 25;
    }
  }
  return n;
}

TEST(RgbdCamera, KinectDefaultsAndAConsistentFrame) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  const RgbdFrame f = cam.render({4.0, 2.25, 0.0}, 0.0, 1.5, rng);
  EXPECT_TRUE(f.consistent());
  EXPECT_EQ(f.width, 640);
  EXPECT_EQ(f.height, 480);
  EXPECT_DOUBLE_EQ(f.t_s, 1.5);
  EXPECT_NEAR(2.0 * std::atan(320.0 / f.intrinsics.fx_px), 57.0 * std::numbers::pi / 180.0, 1e-9);
  EXPECT_EQ(cam.options().mount_height_m, 1.03);
}

TEST(RgbdCamera, DepthFacingAWallAtAKnownDistanceIsExactToOneMillimetre) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  for (const double distance_m : {0.8, 1.5, 2.95, 4.2}) {
    const RgbdFrame f = cam.render({kEastWallX - distance_m, 2.25, 0.0}, 0.0, 0.0, rng);
    EXPECT_NEAR(depth_at(f, 320, 240), distance_m, 1e-3);
    EXPECT_NEAR(depth_at(f, 319, 239), distance_m, 1e-3);
    // Depth is z along the optical axis: the same over the whole wall facing the camera.
    EXPECT_NEAR(depth_at(f, 100, 200), distance_m, 1e-3) << distance_m;
  }
}

TEST(RgbdCamera, FloorAndCeilingDepthFollowTheMountHeight) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  // From the west wall looking east: 6.9 m of room, the far wall is out of range.
  const RgbdFrame f = cam.render({0.1, 2.25, 0.0}, 0.0, 0.0, rng);
  const PinholeIntrinsics& k = f.intrinsics;
  const double y_bottom = (479 - k.cy_px) / k.fy_px;
  EXPECT_NEAR(depth_at(f, 320, 479), 1.03 / y_bottom, 1e-4);
  EXPECT_EQ(rgb_at(f, 320, 479), (std::array<int, 3>{128, 116, 100}));
  const double y_top = (0 - k.cy_px) / k.fy_px;  // negative: above the axis
  EXPECT_NEAR(depth_at(f, 320, 0), (2.5 - 1.03) / -y_top, 1e-4);
  EXPECT_EQ(rgb_at(f, 320, 0), (std::array<int, 3>{246, 246, 246}));
  // The east wall at 6.85 m is beyond 4.5 m: no reading, but it is still drawn.
  EXPECT_EQ(depth_at(f, 320, 240), 0.0);
}

TEST(RgbdCamera, DepthOutsideTheRangeReadsZero) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  const RgbdFrame near = cam.render({kEastWallX - 0.3, 2.25, 0.0}, 0.0, 0.0, rng);
  for (float z : near.depth_m) EXPECT_EQ(z, 0.0F);  // 0.3 m < 0.5 m everywhere on the wall
}

TEST(RgbdCamera, TheNeckAngleTurnsTheView) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  const RgbdFrame ahead = cam.render({4.0, 2.25, 0.0}, 0.0, 0.0, rng);
  const RgbdFrame left = cam.render({4.0, 2.25, 0.0}, 0.5 * std::numbers::pi, 0.0, rng);
  const RgbdFrame turned = cam.render({4.0, 2.25, 0.5 * std::numbers::pi}, 0.0, 0.0, rng);
  // Pan left by 90 degrees: the camera faces the north wall, 2.2 m away.
  EXPECT_NEAR(depth_at(left, 320, 240), kNorthWallY - 2.25, 1e-3);
  EXPECT_NEAR(depth_at(ahead, 320, 240), kEastWallX - 4.0, 1e-3);
  EXPECT_EQ(left.rgb, turned.rgb);
  EXPECT_EQ(left.depth_m, turned.depth_m);
  EXPECT_NE(left.rgb, ahead.rgb);
}

TEST(RgbdCamera, ABlankWallIsOneColourAndAPosterWallIsTextured) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  // 1.5 m from the blank north wall: it fills the view (heights 0.44 to 1.62 m).
  const RgbdFrame blank = cam.render({3.5, kNorthWallY - 1.5, 0.5 * std::numbers::pi}, 0.0, 0.0, rng);
  std::set<std::array<int, 3>> colours;
  for (int v = 0; v < blank.height; ++v) {
    for (int u = 0; u < blank.width; ++u) colours.insert(rgb_at(blank, u, v));
  }
  EXPECT_EQ(colours.size(), 1u);
  EXPECT_EQ(strong_gradients(blank), 0);
  const RgbdFrame poster = cam.render({kEastWallX - 1.5, 2.25, 0.0}, 0.0, 0.0, rng);
  EXPECT_GT(strong_gradients(poster), 2000);
}

TEST(RgbdCamera, APosterReadsLeftToRightAndTopToBottomAsThePhoto) {
  // A texture that is red in its left half and blue in its top-right quarter.
  WallTexture t{4, 4, std::vector<std::uint8_t>(48, 0), "quadrants"};
  for (int y = 0; y < 4; ++y) {
    for (int x = 0; x < 4; ++x) {
      const std::size_t i = static_cast<std::size_t>(3 * (y * 4 + x));
      if (x < 2) t.rgb[i] = 255;
      if (x >= 2 && y < 2) t.rgb[i + 2] = 255;
    }
  }
  const World world = support::rgbd_room();
  const auto faces = find_wall_faces(world).faces;
  RgbdCameraOptions o;
  o.depth_noise_coefficient_1_per_m = 0.0;
  const Result<RgbdCamera> cam = RgbdCamera::create(world, o, {t}, {support::east_poster(faces)});
  ASSERT_TRUE(cam.ok());
  Rng rng(1);
  const RgbdFrame f = cam->render({kEastWallX - 1.5, 2.25, 0.0}, 0.0, 0.0, rng);
  // The poster spans about +-240 px across and +-150 px up and down at 1.5 m.
  EXPECT_EQ(rgb_at(f, 200, 240)[0], 255);               // left half: red
  EXPECT_EQ(rgb_at(f, 440, 150), (std::array<int, 3>{0, 0, 255}));  // top right: blue
  EXPECT_EQ(rgb_at(f, 440, 330), (std::array<int, 3>{0, 0, 0}));    // bottom right: black
}

TEST(RgbdCamera, AFineTextureFarAwayAveragesInsteadOfAliasing) {
  // A one-texel black and white checkerboard, 512 texels across 1.2 m: at 4 m a pixel covers
  // about 3 texels.
  WallTexture stripes{512, 384, {}, "stripes"};
  stripes.rgb.resize(3 * 512 * 384);
  for (int y = 0; y < 384; ++y) {
    for (int x = 0; x < 512; ++x) {
      const std::uint8_t v = ((x + y) % 2 == 0) ? 255 : 0;
      for (int c = 0; c < 3; ++c) stripes.rgb[static_cast<std::size_t>(3 * (y * 512 + x) + c)] = v;
    }
  }
  const World world = support::rgbd_room();
  const auto faces = find_wall_faces(world).faces;
  RgbdCameraOptions o;
  const Result<RgbdCamera> cam =
      RgbdCamera::create(world, o, {stripes}, {support::east_poster(faces)});
  ASSERT_TRUE(cam.ok());
  Rng rng(1);
  const RgbdFrame f = cam->render({kEastWallX - 4.0, 2.25, 0.0}, 0.0, 0.0, rng);
  double sum = 0.0, sum2 = 0.0;
  int n = 0;
  for (int v = 220; v < 260; ++v) {
    for (int u = 290; u < 350; ++u) {
      const double g = rgb_at(f, u, v)[1];
      sum += g;
      sum2 += g * g;
      ++n;
    }
  }
  const double mean = sum / n, stddev = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  EXPECT_NEAR(mean, 127.5, 10.0);
  EXPECT_LT(stddev, 15.0);  // point sampling would give black and white pixels (stddev ~127)
}

TEST(RgbdCamera, DepthNoiseGrowsWithTheSquareOfTheRange) {
  const RgbdCamera cam = support::room_camera({}, /*noise=*/true);
  Rng rng(3);
  for (const double distance_m : {1.0, 3.0}) {
    const RgbdFrame f = cam.render({kEastWallX - distance_m, 2.25, 0.0}, 0.0, 0.0, rng);
    double sum = 0.0, sum2 = 0.0;
    int n = 0;
    for (int v = 100; v < 380; ++v) {
      for (int u = 100; u < 540; ++u) {
        const double e = depth_at(f, u, v) - distance_m;
        sum += e;
        sum2 += e * e;
        ++n;
      }
    }
    const double sigma = 1.425e-3 * distance_m * distance_m;
    EXPECT_NEAR(sum / n, 0.0, 0.05 * sigma);
    EXPECT_NEAR(std::sqrt(sum2 / n), sigma, 0.03 * sigma) << distance_m;
  }
}

TEST(RgbdCamera, SameSeedSameNoise) {
  const RgbdCamera cam = support::room_camera({}, true);
  Rng a(9), b(9), c(10);
  const Pose2 pose{3.0, 2.0, 0.2};
  const RgbdFrame fa = cam.render(pose, 0.1, 0.0, a);
  const RgbdFrame fb = cam.render(pose, 0.1, 0.0, b);
  const RgbdFrame fc = cam.render(pose, 0.1, 0.0, c);
  EXPECT_EQ(fa.depth_m, fb.depth_m);
  EXPECT_NE(fa.depth_m, fc.depth_m);
  EXPECT_EQ(fa.rgb, fc.rgb);
}

TEST(RgbdCamera, QuantisedDepthTakesDisparitySteps) {
  RgbdCameraOptions o;
  o.inverse_depth_step_1_per_m = 2.8e-3;
  const RgbdCamera cam = support::room_camera(o);
  Rng rng(1);
  const RgbdFrame f = cam.render({kEastWallX - 3.0, 2.25, 0.0}, 0.0, 0.0, rng);
  const double z = depth_at(f, 320, 240);
  const double steps = 1.0 / (z * 2.8e-3);
  EXPECT_NEAR(steps, std::round(steps), 1e-3);
  EXPECT_NEAR(z, 3.0, 0.5 * 2.8e-3 * 9.0 + 1e-4);  // within half a step (step = 2.8e-3 z^2)
}

TEST(RgbdCamera, InsideAWallItSeesBlackAndNoDepth) {
  const RgbdCamera cam = support::room_camera();
  Rng rng(1);
  const RgbdFrame f = cam.render({0.02, 0.02, 0.0}, 0.0, 0.0, rng);
  for (float z : f.depth_m) ASSERT_EQ(z, 0.0F);
  for (std::uint8_t c : f.rgb) ASSERT_EQ(c, 0);
}

TEST(RgbdCamera, CreateRejectsBadOptionsTexturesAndPosters) {
  const World world = support::rgbd_room();
  const auto faces = find_wall_faces(world).faces;
  RgbdCameraOptions o;
  o.max_depth_m = 0.2;
  Result<RgbdCamera> r = RgbdCamera::create(world, o, {}, {});
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kInput);
  EXPECT_THAT(r.error().message, HasSubstr("rgbd camera: need 0 <= min_depth_m < max_depth_m"));
  o = {};
  o.mount_height_m = 3.0;
  EXPECT_THAT(RgbdCamera::create(world, o, {}, {}).error().message, HasSubstr("mount_height_m"));
  WallTexture broken{10, 10, std::vector<std::uint8_t>(5), "broken.png"};
  EXPECT_THAT(RgbdCamera::create(world, {}, {broken}, {}).error().message,
              HasSubstr("texture 0 (broken.png)"));
  Poster p = support::east_poster(faces);
  p.texture = 1;
  EXPECT_THAT(RgbdCamera::create(world, {}, {support::test_photo()}, {p}).error().message,
              HasSubstr("poster 0: texture 1 does not exist"));
}

}  // namespace
}  // namespace tessera
