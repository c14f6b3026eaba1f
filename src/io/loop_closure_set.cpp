#include "tessera/io/loop_closure_set.hpp"

#include <algorithm>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "internal/cv_image.hpp"

namespace tessera {
namespace {

/// Decodes an image file with OpenCV (`flags` as for cv::imdecode) and requires one 8-bit channel;
/// `what` names the expected content in the error. kInput errors name the file.
Result<cv::Mat> decode_8bit(const std::filesystem::path& path, int flags, const std::string& what) {
  Result<cv::Mat> m = io_internal::read_image_file(path, flags, io_internal::PngCheck::kNone);
  if (m && (m->depth() != CV_8U || m->channels() != 1)) {
    return input_error(path.string() + ": expected an 8-bit " + what + ", got " +
                       io_internal::describe_pixels(*m));
  }
  return m;
}

}  // namespace

bool LoopGroundTruth::is_loop(int query, int earlier) const {
  TESSERA_ASSERT(0 <= query && query < size && 0 <= earlier && earlier < size);
  return loop[static_cast<std::size_t>(query) * static_cast<std::size_t>(size) +
              static_cast<std::size_t>(earlier)] != 0;
}

bool LoopGroundTruth::has_loop(int query) const {
  TESSERA_ASSERT(0 <= query && query < size);
  const auto row = loop.begin() + static_cast<std::ptrdiff_t>(query) * size;
  return std::any_of(row, row + size, [](std::uint8_t v) { return v != 0; });
}

int LoopGroundTruth::queries_with_loop() const {
  int n = 0;
  for (int i = 0; i < size; ++i) n += has_loop(i) ? 1 : 0;
  return n;
}

Result<LoopGroundTruth> read_loop_ground_truth(const std::filesystem::path& path,
                                               int expected_images) {
  TESSERA_ASSERT(expected_images > 0);
  Result<cv::Mat> decoded = decode_8bit(path, cv::IMREAD_UNCHANGED, "grey matrix");
  if (!decoded) return decoded.error();
  const cv::Mat& m = *decoded;
  if (m.rows != expected_images || m.cols != expected_images) {
    return input_error(path.string() + ": expected an " + std::to_string(expected_images) + " x " +
                       std::to_string(expected_images) +
                       " matrix (one row and column per image), got " + std::to_string(m.cols) +
                       " x " + std::to_string(m.rows));
  }
  LoopGroundTruth gt;
  gt.size = expected_images;
  gt.loop.resize(static_cast<std::size_t>(gt.size) * static_cast<std::size_t>(gt.size));
  for (int r = 0; r < m.rows; ++r) {
    const auto* p = m.ptr<std::uint8_t>(r);
    for (int c = 0; c < m.cols; ++c) {
      if (p[c] != 0 && p[c] != 255) {
        return input_error(path.string() + ": row " + std::to_string(r) + ", column " +
                           std::to_string(c) + ": expected 0 (no loop) or 255 (loop), got " +
                           std::to_string(p[c]));
      }
      gt.loop[static_cast<std::size_t>(r) * static_cast<std::size_t>(gt.size) +
              static_cast<std::size_t>(c)] = p[c] != 0 ? 1 : 0;
    }
  }
  return gt;
}

Result<std::vector<GrayImage>> read_loop_closure_images(const std::filesystem::path& folder,
                                                        int count) {
  TESSERA_ASSERT(count > 0);
  std::error_code ec;
  if (!std::filesystem::is_directory(folder, ec)) {
    return input_error(folder.string() + ": not a folder (expected images 1.jpg .. " +
                       std::to_string(count) + ".jpg)");
  }
  std::vector<GrayImage> images;
  images.reserve(static_cast<std::size_t>(count));
  for (int i = 1; i <= count; ++i) {
    const std::filesystem::path path = folder / (std::to_string(i) + ".jpg");
    Result<cv::Mat> decoded = decode_8bit(path, cv::IMREAD_GRAYSCALE, "image");
    if (!decoded) return decoded.error();
    const cv::Mat& m = *decoded;
    GrayImage g(m.cols, m.rows);
    for (int r = 0; r < m.rows; ++r) {
      std::copy_n(m.ptr<std::uint8_t>(r), m.cols,
                  g.pixels.begin() + static_cast<std::ptrdiff_t>(r) * m.cols);
    }
    images.push_back(std::move(g));
  }
  return images;
}

}  // namespace tessera
