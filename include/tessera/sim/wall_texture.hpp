#pragma once
// A photograph to hang on a simulated wall (sim/rgbd_camera.hpp): a plain RGB buffer, so that sim
// stays free of image files and OpenCV. render/wall_textures.hpp loads real photos into it.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tessera {

struct WallTexture {
  int width = 0;
  int height = 0;
  /// 3 * width * height bytes, row-major, row 0 is the TOP row, R, G, B order (as RgbdFrame::rgb).
  std::vector<std::uint8_t> rgb;
  /// Where the picture came from (a file name), for reports; may be empty.
  std::string name;

  /// True when the buffer matches width x height and the picture is not empty.
  [[nodiscard]] bool consistent() const {
    return width > 0 && height > 0 &&
           rgb.size() == 3 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  }
};

}  // namespace tessera
