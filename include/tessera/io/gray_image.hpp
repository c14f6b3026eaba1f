#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "tessera/core/assert.hpp"

namespace tessera {

/// An 8-bit greyscale raster as image files store it: row-major, image row 0 is the TOP row
/// (so image row r shows grid cell row y = height - 1 - r), 0 black, 255 white.
struct GrayImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height, top row first

  GrayImage() = default;
  /// Precondition: width >= 0, height >= 0.
  GrayImage(int width_px, int height_px, std::uint8_t fill = 0)
      : width(width_px),
        height(height_px),
        pixels(static_cast<std::size_t>(width_px) * static_cast<std::size_t>(height_px), fill) {
    TESSERA_ASSERT(width_px >= 0 && height_px >= 0);
  }

  /// Precondition: 0 <= x < width, 0 <= row < height.
  [[nodiscard]] std::uint8_t at(int x, int row) const {
    TESSERA_ASSERT(0 <= x && x < width && 0 <= row && row < height);
    return pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
  void set(int x, int row, std::uint8_t value) {
    TESSERA_ASSERT(0 <= x && x < width && 0 <= row && row < height);
    pixels[static_cast<std::size_t>(row) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(x)] = value;
  }
  [[nodiscard]] bool operator==(const GrayImage&) const = default;
};

}  // namespace tessera
