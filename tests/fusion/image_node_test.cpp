#include "tessera/fusion/image_node.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "support/data.hpp"
#include "synthetic_wall.hpp"
#include "tessera/io/rgbd_pair_folder.hpp"

namespace tessera::fusion {
namespace {

using ::testing::HasSubstr;

const std::filesystem::path kCase1 = "rgbd/tum_fr1_xyz_pairs/case_1";

RgbdFrame textured_wall() {
  return testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, testing::blob_texture(0.015, 3),
                              PinholeIntrinsics::kinect_v1());
}

TEST(ImageNode, RealFrameBecomesANodeWithBackProjectedFeaturesForEveryType) {
  TESSERA_REQUIRE_DATA(support::data_path(kCase1));
  const Result<RgbdPair> pair = read_rgbd_pair_folder(support::data_path(kCase1));
  ASSERT_TRUE(pair.ok()) << pair.error().message;
  const NodePlacement where{{1.0, 2.0, 0.5}, 0.25, 17};
  for (const FeatureType type : {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze}) {
    ImageNodeOptions o;
    o.feature_type = type;
    const NodeCreation c = create_image_node(pair->prev, where, o);
    ASSERT_TRUE(c.ok()) << to_string(type) << ": " << c.reason;
    const ImageNode& node = c.node;
    EXPECT_GT(c.valid_depth_fraction, 0.6);  // SOURCES.md: about 75% of the pixels are valid
    EXPECT_GE(c.features, 300) << to_string(type);
    EXPECT_LE(c.features, o.max_features);
    EXPECT_GT(c.features_with_depth, c.features / 3) << to_string(type);
    EXPECT_EQ(node.descriptors.count, c.features);
    EXPECT_EQ(node.features.size(), static_cast<std::size_t>(c.features));
    EXPECT_EQ(node.feature_type, type);
    EXPECT_EQ(node.placement.cell_id, 17);
    EXPECT_DOUBLE_EQ(node.placement.neck_rad, 0.25);
    EXPECT_DOUBLE_EQ(node.placement.T_map_robot.x, 1.0);
    if (is_binary(type)) {
      EXPECT_EQ(node.descriptors.binary.size(),
                static_cast<std::size_t>(c.features) * node.descriptors.length);
    } else {
      EXPECT_EQ(node.descriptors.length, 128);
      EXPECT_EQ(node.descriptors.real.size(), static_cast<std::size_t>(c.features) * 128);
    }
    // Each 3D point projects back onto its keypoint and lies in the effective range.
    for (const NodeFeature& f : node.features) {
      if (!f.has_depth) continue;
      EXPECT_GE(f.point.z_m, o.min_depth_m);
      EXPECT_LE(f.point.z_m, o.max_depth_m);
      const PinholeIntrinsics& k = node.intrinsics;
      EXPECT_NEAR(k.fx_px * f.point.x_m / f.point.z_m + k.cx_px, f.u_px, 1e-6);
      EXPECT_NEAR(k.fy_px * f.point.y_m / f.point.z_m + k.cy_px, f.v_px, 1e-6);
    }
  }
}

TEST(ImageNode, SameFrameSameNode) {
  const RgbdFrame frame = textured_wall();
  const NodeCreation a = create_image_node(frame, {}, ImageNodeOptions{});
  const NodeCreation b = create_image_node(frame, {}, ImageNodeOptions{});
  ASSERT_TRUE(a.ok()) << a.reason;
  EXPECT_EQ(a.node.descriptors.binary, b.node.descriptors.binary);
  ASSERT_EQ(a.node.features.size(), b.node.features.size());
  for (std::size_t i = 0; i < a.node.features.size(); ++i) {
    EXPECT_EQ(a.node.features[i].u_px, b.node.features[i].u_px);
  }
}

TEST(ImageNode, WallBackProjectsOntoItsPlane) {
  const NodeCreation c = create_image_node(textured_wall(), {}, ImageNodeOptions{});
  ASSERT_TRUE(c.ok()) << c.reason;
  EXPECT_EQ(c.features_with_depth, c.features);  // a flat wall has no depth edges
  for (const NodeFeature& f : c.node.features) EXPECT_NEAR(f.point.z_m, 2.0, 1e-5);
}

// The thesis' "check features": a plain wall gives (almost) nothing to match.
TEST(ImageNode, PlainWallIsRejectedForTooFewFeatures) {
  const RgbdFrame frame = testing::render_wall(
      Eigen::Isometry3d::Identity(), 2.0, [](double, double) { return 200.0; },
      PinholeIntrinsics::kinect_v1(),
      /*pixel_noise=*/1.0);
  for (const FeatureType type : {FeatureType::kOrb, FeatureType::kSift, FeatureType::kAkaze}) {
    ImageNodeOptions o;
    o.feature_type = type;
    const NodeCreation c = create_image_node(frame, {}, o);
    EXPECT_EQ(c.check, NodeCheck::kTooFewFeatures) << to_string(type) << ": " << c.reason;
    EXPECT_THAT(c.reason, HasSubstr("too few features")) << to_string(type);
    EXPECT_TRUE(c.node.features.empty());
  }
}

// The thesis' "check distance": a view too close or too far for the Kinect.
TEST(ImageNode, FrameWithLittleDepthInRangeIsRejected) {
  RgbdFrame frame = textured_wall();
  for (std::size_t i = 0; i < frame.depth_m.size(); ++i) {
    if (i % 10 != 0) frame.depth_m[i] = 0.0f;  // 10% valid
  }
  NodeCreation c = create_image_node(frame, {}, ImageNodeOptions{});
  EXPECT_EQ(c.check, NodeCheck::kTooLittleDepth) << c.reason;
  EXPECT_THAT(c.reason, HasSubstr("too little valid depth: 10.0%"));
  EXPECT_NEAR(c.valid_depth_fraction, 0.1, 1e-3);

  // Readings beyond the effective range count as none.
  frame = textured_wall();
  for (float& z : frame.depth_m) z = 6.0f;
  c = create_image_node(frame, {}, ImageNodeOptions{});
  EXPECT_EQ(c.check, NodeCheck::kTooLittleDepth) << c.reason;
}

// Depth only where the image is blank: features exist, but none can be placed in 3D.
TEST(ImageNode, FeaturesWithoutDepthAreRejected) {
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  const testing::WallTexture left_textured = [](double x_m, double y_m) {
    return x_m < 0.0 ? testing::blob_texture(0.015, 5)(x_m, y_m) : 200.0;
  };
  RgbdFrame frame = testing::render_wall(Eigen::Isometry3d::Identity(), 2.0, left_textured, k);
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width / 2 + 20; ++u) {
      frame.depth_m[static_cast<std::size_t>(v * frame.width + u)] = 0.0f;
    }
  }
  const NodeCreation c = create_image_node(frame, {}, ImageNodeOptions{});
  EXPECT_EQ(c.check, NodeCheck::kTooFewFeaturesWithDepth) << c.reason;
  EXPECT_GE(c.features, ImageNodeOptions{}.min_features);
  EXPECT_THAT(c.reason, HasSubstr("too few features with depth"));
}

// A depth edge mixes foreground and background: keypoints on it get no 3D point.
TEST(ImageNode, KeypointsOnDepthEdgesHaveNoDepth) {
  RgbdFrame frame = textured_wall();
  for (int v = 0; v < frame.height; ++v) {
    for (int u = 0; u < frame.width; ++u) {
      if ((u / 8 + v / 8) % 2 == 0)
        frame.depth_m[static_cast<std::size_t>(v * frame.width + u)] = 1.0f;
    }
  }
  ImageNodeOptions o;
  o.min_features_with_depth = 0;
  const NodeCreation c = create_image_node(frame, {}, o);
  ASSERT_TRUE(c.ok()) << c.reason;
  for (const NodeFeature& f : c.node.features) {
    if (!f.has_depth) continue;
    const int u = static_cast<int>(std::lround(f.u_px)), v = static_cast<int>(std::lround(f.v_px));
    const bool near = (u / 8 + v / 8) % 2 == 0;
    EXPECT_NEAR(f.point.z_m, near ? 1.0 : 2.0, 1e-5);
  }
  EXPECT_LT(c.features_with_depth, c.features);
}

TEST(ImageNode, InconsistentFrameIsRejected) {
  RgbdFrame frame = textured_wall();
  frame.depth_m.pop_back();
  const NodeCreation c = create_image_node(frame, {}, ImageNodeOptions{});
  EXPECT_EQ(c.check, NodeCheck::kInconsistentFrame);
}

TEST(ImageNode, OptionsAreValidated) {
  EXPECT_FALSE(validate(ImageNodeOptions{}));
  ImageNodeOptions o;
  o.min_depth_m = 5.0;
  EXPECT_TRUE(validate(o));
  o = {};
  o.max_features = 0;
  EXPECT_TRUE(validate(o));
}

}  // namespace
}  // namespace tessera::fusion
