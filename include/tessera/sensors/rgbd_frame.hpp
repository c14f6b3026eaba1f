#pragma once
// One RGB-D frame, the event type that both the TUM reader (io/) and the simulated camera (sim/)
// produce and the fusion SLAM (fusion/) consumes (../shared/DESIGN.md, "events"). Plain buffers,
// so that sensors and sim stay free of OpenCV; fusion wraps them in cv::Mat without copying.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tessera/sensors/pinhole_camera.hpp"

namespace tessera {

/// Colour and depth registered to the same pinhole camera (the TUM release registers depth to the
/// colour camera, and the simulator renders both from one camera).
struct RgbdFrame {
  double t_s = 0.0;
  int width = 0;
  int height = 0;
  /// 3 * width * height bytes, row-major, image row 0 is the TOP row, R, G, B order.
  std::vector<std::uint8_t> rgb;
  /// width * height depths along the optical axis (z, not the ray length) in metres, same layout;
  /// 0 means no reading (TUM's convention for the raw value 0).
  std::vector<float> depth_m;
  PinholeIntrinsics intrinsics;

  [[nodiscard]] std::size_t pixel_count() const {
    return static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
  /// True when both buffers match width x height and the intrinsics describe the same size.
  [[nodiscard]] bool consistent() const {
    return width > 0 && height > 0 && rgb.size() == 3 * pixel_count() &&
           depth_m.size() == pixel_count() && intrinsics.width_px == width &&
           intrinsics.height_px == height;
  }
};

}  // namespace tessera
