#pragma once
// Image files for maps and pictures: PGM through the project's own reader (pgm.hpp), PNG and the
// other formats OpenCV's imgcodecs decodes. OpenCV stays out of this header.
#include <filesystem>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/io/gray_image.hpp"
#include "tessera/io/rgb_image.hpp"

namespace tessera {

/// Reads a PGM or PNG (format sniffed from the first bytes, not the extension) as 8-bit grey.
/// Colour pixels become the mean of R, G and B, as ROS map_server does; alpha is dropped (the map
/// readers that need it, map_yaml.hpp, read it themselves). 16-bit samples are scaled to 8 bits.
/// kInput error "<file>: no such file" or "<file>: cannot decode image ..." otherwise.
[[nodiscard]] Result<GrayImage> read_gray_image(const std::filesystem::path& path);

/// PNG bytes of an 8-bit grey image. kRuntime error if the encoder fails.
[[nodiscard]] Result<std::string> encode_png(const GrayImage& image);
/// PNG bytes of an RGB image. kRuntime error if the encoder fails.
[[nodiscard]] Result<std::string> encode_png(const RgbImage& image);

}  // namespace tessera
