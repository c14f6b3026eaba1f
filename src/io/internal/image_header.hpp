#pragma once
// A look at an image file's header before OpenCV decodes it: OpenCV allocates the whole matrix as
// soon as it has read the header, so a 20-byte file that claims 2223 x 22222222 pixels would cost
// gigabytes before the decoder notices that the pixels are missing (found by fuzz/image_fuzz.cpp).
#include <string>

namespace tessera::io_internal {

/// True when `bytes` start like a PNG, JPEG, BMP or Netpbm (P1 to P6) file: the image formats the
/// readers hand to OpenCV. OpenCV would decode many more (TIFF, WebP, JPEG 2000 and, through GDAL,
/// dozens of others, some of which print to stderr and write temporary files); fuzzing found them
/// all reachable from a map image, so the readers refuse them.
[[nodiscard]] bool is_supported_image(const std::string& bytes);

/// Empty when the header of a PNG (IHDR, PNG specification section 11.2.2), Netpbm (P1 to P6,
/// netpbm.sourceforge.net/doc) or BMP (BITMAPINFOHEADER) image is plausible, else what is wrong:
/// more than kMaxCells pixels, or (for the uncompressed formats) fewer bytes than the pixels need.
/// Other formats are left to OpenCV (whose own limit is 2^30 pixels).
[[nodiscard]] std::string image_header_problem(const std::string& bytes);

}  // namespace tessera::io_internal
