#pragma once
// OpenCV matrices at the io module's edge: decoding image files for the readers (RGB-D pairs, wall
// textures, loop-closure matrices, map images) in one place that catches OpenCV's exceptions, keeps
// libpng quiet on damaged PNGs and names the file in the error the same way; and handing a drawn
// picture (render.cpp, hex_map_svg.cpp) over as an RgbImage.
#include <filesystem>
#include <opencv2/core.hpp>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/io/rgb_image.hpp"

namespace tessera::io_internal {

/// True when `bytes` start with the PNG signature (PNG specification section 5.2).
[[nodiscard]] bool looks_like_png(const std::string& bytes);

/// cv::imdecode(bytes, flags) with OpenCV's exceptions caught and its log silenced: an empty
/// matrix when it cannot decode the bytes or they are no PNG, JPEG, BMP or Netpbm file
/// (is_supported_image, image_header.hpp).
[[nodiscard]] cv::Mat imdecode_or_empty(const std::string& bytes, int flags);

/// Whether read_image_file checks a PNG's chunk structure (png_structure_problem, raw_image.hpp)
/// before OpenCV decodes it.
enum class PngCheck { kNone, kStructure };

/// Reads and decodes an image file, `flags` as for cv::imdecode. kInput errors name the file: those
/// of read_file_bytes; "<file>: cannot decode image: <problem>" for a PNG whose chunk structure is
/// damaged (PngCheck::kStructure only; libpng then never sees it, so it never prints); and
/// "<file>: cannot decode image" when OpenCV cannot decode it into a 2-D matrix.
[[nodiscard]] Result<cv::Mat> read_image_file(const std::filesystem::path& path, int flags,
                                              PngCheck png_check);

/// cv::imencode(".png", m) with OpenCV's exceptions caught: the file's bytes, or a kRuntime error
/// "PNG encoder failed[: <what OpenCV said>]".
[[nodiscard]] Result<std::string> encode_png_bytes(const cv::Mat& m);

/// A matrix's samples for error messages: "8-bit with 3 channels", "16-bit with 1 channel",
/// "unusual-depth with 2 channels" (depths other than 8, 16 and 32 bits).
[[nodiscard]] std::string describe_pixels(const cv::Mat& m);

/// A copy of an 8-bit, 3-channel matrix whose channels are already in R, G, B order (as the
/// renderers draw them). Precondition: m.type() == CV_8UC3.
[[nodiscard]] RgbImage to_rgb_image(const cv::Mat& m);

}  // namespace tessera::io_internal
