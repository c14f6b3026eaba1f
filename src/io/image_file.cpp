#include "tessera/io/image_file.hpp"

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "internal/cv_image.hpp"
#include "internal/raw_image.hpp"

namespace tessera {
Result<GrayImage> read_gray_image(const std::filesystem::path& path) {
  Result<io_internal::RawImage> raw = io_internal::read_raw_image(path);
  if (!raw) return raw.error();
  return io_internal::to_gray(*raw);
}

Result<std::string> encode_png(const GrayImage& image) {
  if (image.width == 0 || image.height == 0) return runtime_error("cannot encode an empty image");
  // cv::Mat does not write through the pointer here; imencode only reads.
  const cv::Mat m(image.height, image.width, CV_8UC1,
                  const_cast<std::uint8_t*>(image.pixels.data()));
  return io_internal::encode_png_bytes(m);
}

Result<std::string> encode_png(const RgbImage& image) {
  if (image.width == 0 || image.height == 0) return runtime_error("cannot encode an empty image");
  cv::Mat bgr(image.height, image.width, CV_8UC3);
  for (int row = 0; row < image.height; ++row) {
    auto* out = bgr.ptr<std::uint8_t>(row);
    for (int x = 0; x < image.width; ++x) {
      const Rgb c = image.at(x, row);
      out[3 * x] = c.b;
      out[3 * x + 1] = c.g;
      out[3 * x + 2] = c.r;
    }
  }
  return io_internal::encode_png_bytes(bgr);
}

}  // namespace tessera
