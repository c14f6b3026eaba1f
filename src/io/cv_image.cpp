#include "internal/cv_image.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <vector>

#include "internal/file_util.hpp"
#include "internal/image_header.hpp"
#include "internal/raw_image.hpp"
#include "tessera/core/assert.hpp"

namespace tessera::io_internal {

bool looks_like_png(const std::string& bytes) {
  return bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0;
}

namespace {

// Silences OpenCV's own log while it decodes: its decoders log their complaints about damaged
// files to stderr ("OpenJPEG2000: Stream too short", found by fuzz/image_fuzz.cpp), and the library
// never prints; the reader reports the file instead.
class QuietOpenCvLog {
 public:
  QuietOpenCvLog()
      : previous_(cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT)) {}
  ~QuietOpenCvLog() { cv::utils::logging::setLogLevel(previous_); }
  QuietOpenCvLog(const QuietOpenCvLog&) = delete;
  QuietOpenCvLog& operator=(const QuietOpenCvLog&) = delete;

 private:
  cv::utils::logging::LogLevel previous_;
};

}  // namespace

cv::Mat imdecode_or_empty(const std::string& bytes, int flags) {
  cv::Mat m;
  if (!is_supported_image(bytes)) return m;
  const QuietOpenCvLog quiet;
  try {
    // cv::Mat does not write through the pointer here; imdecode only reads.
    const cv::Mat buffer(1, static_cast<int>(bytes.size()), CV_8UC1,
                         const_cast<char*>(bytes.data()));
    m = cv::imdecode(buffer, flags);
  } catch (const std::exception&) {
    m.release();
  }
  return m;
}

Result<cv::Mat> read_image_file(const std::filesystem::path& path, int flags, PngCheck png_check) {
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  if (png_check == PngCheck::kStructure && looks_like_png(*bytes)) {
    if (const std::string problem = png_structure_problem(*bytes); !problem.empty()) {
      return input_error(path.string() + ": cannot decode image: " + problem);
    }
  }
  if (const std::string problem = image_header_problem(*bytes); !problem.empty()) {
    return input_error(path.string() + ": cannot decode image: " + problem);
  }
  cv::Mat m = imdecode_or_empty(*bytes, flags);
  if (m.empty() || m.dims != 2) return input_error(path.string() + ": cannot decode image");
  return m;
}

std::string describe_pixels(const cv::Mat& m) {
  const int bits = m.depth() == CV_8U ? 8 : m.depth() == CV_16U ? 16 : m.depth() == CV_32F ? 32 : 0;
  return (bits > 0 ? std::to_string(bits) + "-bit" : std::string("unusual-depth")) + " with " +
         std::to_string(m.channels()) + (m.channels() == 1 ? " channel" : " channels");
}

RgbImage to_rgb_image(const cv::Mat& m) {
  TESSERA_ASSERT(m.type() == CV_8UC3);
  RgbImage out(m.cols, m.rows);
  for (int row = 0; row < m.rows; ++row) {
    const auto* src = m.ptr<std::uint8_t>(row);
    std::copy(src, src + 3 * m.cols,
              out.rgb.begin() + 3 * static_cast<std::ptrdiff_t>(row) * m.cols);
  }
  return out;
}

Result<std::string> encode_png_bytes(const cv::Mat& m) {
  std::vector<unsigned char> buffer;
  bool ok = false;
  try {
    ok = cv::imencode(".png", m, buffer);
  } catch (const std::exception& e) {
    return runtime_error(std::string("PNG encoder failed: ") + e.what());
  }
  if (!ok) return runtime_error("PNG encoder failed");
  return std::string(buffer.begin(), buffer.end());
}

}  // namespace tessera::io_internal
