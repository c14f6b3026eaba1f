#pragma once
// The pinhole camera model of an RGB-D sensor (../shared/DESIGN.md sensors/), in the optical
// convention: x right, y down, z forward (the TUM RGB-D benchmark's camera frame).
#include <cmath>
#include <numbers>

namespace tessera {

/// Focal lengths and principal point in pixels for an image of width_px x height_px.
struct PinholeIntrinsics {
  double fx_px = 525.0;
  double fy_px = 525.0;
  double cx_px = 319.5;
  double cy_px = 239.5;
  int width_px = 640;
  int height_px = 480;

  /// Kinect v1 as the thesis (section 3.1.3) and the simulator use it: 640 x 480 with a field of
  /// view of 57 x 43 degrees, principal point at the image centre.
  [[nodiscard]] static PinholeIntrinsics kinect_v1() {
    PinholeIntrinsics k;
    const double h_fov_rad = 57.0 * std::numbers::pi / 180.0;
    const double v_fov_rad = 43.0 * std::numbers::pi / 180.0;
    k.fx_px = 0.5 * k.width_px / std::tan(0.5 * h_fov_rad);
    k.fy_px = 0.5 * k.height_px / std::tan(0.5 * v_fov_rad);
    k.cx_px = 0.5 * (k.width_px - 1);
    k.cy_px = 0.5 * (k.height_px - 1);
    return k;
  }
  /// TUM RGB-D freiburg1 (Sturm et al. 2012; ../shared/data/rgbd/tum_fr1_xyz_pairs/SOURCES.md).
  [[nodiscard]] static PinholeIntrinsics tum_freiburg1() { return {517.3, 516.5, 318.6, 255.3, 640, 480}; }
  /// TUM RGB-D freiburg2.
  [[nodiscard]] static PinholeIntrinsics tum_freiburg2() { return {520.9, 521.0, 325.1, 249.7, 640, 480}; }
  /// TUM RGB-D freiburg3.
  [[nodiscard]] static PinholeIntrinsics tum_freiburg3() { return {535.4, 539.2, 320.1, 247.6, 640, 480}; }
};

/// A 3D point in the camera frame, metres.
struct CameraPoint {
  double x_m = 0.0;
  double y_m = 0.0;
  double z_m = 0.0;
};

/// The point seen at pixel (u, v) (column, row; pixel centres at integers) with depth z_m.
[[nodiscard]] inline CameraPoint back_project(const PinholeIntrinsics& k, double u_px, double v_px,
                                              double z_m) {
  return {(u_px - k.cx_px) * z_m / k.fx_px, (v_px - k.cy_px) * z_m / k.fy_px, z_m};
}

}  // namespace tessera
