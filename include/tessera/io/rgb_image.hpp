#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tessera/core/assert.hpp"

namespace tessera {

/// An 8-bit RGB colour.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;
  [[nodiscard]] constexpr bool operator==(const Rgb&) const = default;
};

/// An 8-bit RGB raster: row-major, image row 0 is the TOP row, 3 bytes per pixel in R, G, B order.
struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgb;  // 3 * width * height, top row first

  RgbImage() = default;
  /// Precondition: width >= 0, height >= 0.
  RgbImage(int width_px, int height_px, Rgb fill = {}) : width(width_px), height(height_px) {
    TESSERA_ASSERT(width_px >= 0 && height_px >= 0);
    rgb.resize(3 * static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px));
    for (std::size_t i = 0; i < rgb.size(); i += 3) {
      rgb[i] = fill.r;
      rgb[i + 1] = fill.g;
      rgb[i + 2] = fill.b;
    }
  }

  /// Precondition: 0 <= x < width, 0 <= row < height.
  [[nodiscard]] Rgb at(int x, int row) const {
    const std::size_t i = offset(x, row);
    return {rgb[i], rgb[i + 1], rgb[i + 2]};
  }
  void set(int x, int row, Rgb c) {
    const std::size_t i = offset(x, row);
    rgb[i] = c.r;
    rgb[i + 1] = c.g;
    rgb[i + 2] = c.b;
  }

 private:
  [[nodiscard]] std::size_t offset(int x, int row) const {
    TESSERA_ASSERT(0 <= x && x < width && 0 <= row && row < height);
    return 3 * (static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x));
  }
};

}  // namespace tessera
