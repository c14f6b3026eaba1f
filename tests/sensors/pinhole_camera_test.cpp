#include "tessera/sensors/pinhole_camera.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tessera {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

TEST(PinholeCamera, KinectV1HasTheThesisFieldOfView) {
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  EXPECT_EQ(k.width_px, 640);
  EXPECT_EQ(k.height_px, 480);
  // fx = 320 / tan(28.5 deg), fy = 240 / tan(21.5 deg); the centre of pixels 0..639 and 0..479.
  EXPECT_NEAR(k.fx_px, 589.3666835307065, 1e-9);
  EXPECT_NEAR(k.fy_px, 609.2754949594338, 1e-9);
  EXPECT_EQ(k.cx_px, 319.5);
  EXPECT_EQ(k.cy_px, 239.5);
}

TEST(PinholeCamera, KinectV1ImageEdgesAreHalfTheFieldOfViewOffAxis) {
  // Pixel centres are at integers, so the image's outer edges are at -0.5 and width - 0.5.
  const PinholeIntrinsics k = PinholeIntrinsics::kinect_v1();
  const CameraPoint left = back_project(k, -0.5, k.cy_px, 1.0);
  const CameraPoint right = back_project(k, 639.5, k.cy_px, 1.0);
  const CameraPoint top = back_project(k, k.cx_px, -0.5, 1.0);
  const CameraPoint bottom = back_project(k, k.cx_px, 479.5, 1.0);
  EXPECT_NEAR(std::atan2(left.x_m, left.z_m), -28.5 * kDegToRad, 1e-12);
  EXPECT_NEAR(std::atan2(right.x_m, right.z_m), 28.5 * kDegToRad, 1e-12);
  EXPECT_NEAR(std::atan2(top.y_m, top.z_m), -21.5 * kDegToRad, 1e-12);
  EXPECT_NEAR(std::atan2(bottom.y_m, bottom.z_m), 21.5 * kDegToRad, 1e-12);
}

TEST(PinholeCamera, PrincipalPointLooksAlongTheOpticalAxis) {
  const PinholeIntrinsics k = PinholeIntrinsics::tum_freiburg1();
  const CameraPoint p = back_project(k, 318.6, 255.3, 2.5);
  EXPECT_EQ(p.x_m, 0.0);
  EXPECT_EQ(p.y_m, 0.0);
  EXPECT_EQ(p.z_m, 2.5);
}

TEST(PinholeCamera, BackProjectsInTheOpticalConvention) {
  // freiburg1: fx 517.3, fy 516.5, cx 318.6, cy 255.3. A pixel 51.73 px right of and 103.3 px
  // above the principal point at 2 m depth: x = 51.73 * 2 / 517.3 = 0.2 m (right),
  // y = -103.3 * 2 / 516.5 = -0.4 m (y points down, so up is negative).
  const PinholeIntrinsics k = PinholeIntrinsics::tum_freiburg1();
  const CameraPoint p = back_project(k, 318.6 + 51.73, 255.3 - 103.3, 2.0);
  EXPECT_NEAR(p.x_m, 0.2, 1e-12);
  EXPECT_NEAR(p.y_m, -0.4, 1e-12);
  EXPECT_EQ(p.z_m, 2.0);
}

TEST(PinholeCamera, PointScalesWithDepthAlongTheRay) {
  const PinholeIntrinsics k = PinholeIntrinsics::tum_freiburg2();
  const CameraPoint one = back_project(k, 100.0, 400.0, 1.0);
  const CameraPoint three = back_project(k, 100.0, 400.0, 3.0);
  EXPECT_NEAR(three.x_m, 3.0 * one.x_m, 1e-12);
  EXPECT_NEAR(three.y_m, 3.0 * one.y_m, 1e-12);
  const CameraPoint zero = back_project(k, 100.0, 400.0, 0.0);
  EXPECT_EQ(zero.x_m, 0.0);
  EXPECT_EQ(zero.y_m, 0.0);
  EXPECT_EQ(zero.z_m, 0.0);
}

TEST(PinholeCamera, BackProjectionInvertsThePinholeProjection) {
  // u = fx x / z + cx, v = fy y / z + cy (Sturm et al. 2012) applied to the back-projected point
  // gives the pixel again, for every preset, pixels at the image corners and inside.
  for (const PinholeIntrinsics& k :
       {PinholeIntrinsics::kinect_v1(), PinholeIntrinsics::tum_freiburg1(),
        PinholeIntrinsics::tum_freiburg2(), PinholeIntrinsics::tum_freiburg3()}) {
    for (const double u : {0.0, 123.25, 639.0}) {
      for (const double v : {0.0, 300.5, 479.0}) {
        const CameraPoint p = back_project(k, u, v, 1.7);
        EXPECT_NEAR(k.fx_px * p.x_m / p.z_m + k.cx_px, u, 1e-9);
        EXPECT_NEAR(k.fy_px * p.y_m / p.z_m + k.cy_px, v, 1e-9);
      }
    }
  }
}

}  // namespace
}  // namespace tessera
