#include "internal/image_header.hpp"

#include <cctype>
#include <cstdint>
#include <string_view>

#include "internal/file_util.hpp"

namespace tessera::io_internal {
namespace {

std::uint32_t big_endian_32(const std::string& b, std::size_t at) {
  return (std::uint32_t{static_cast<unsigned char>(b[at])} << 24) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 1])} << 16) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 2])} << 8) |
         std::uint32_t{static_cast<unsigned char>(b[at + 3])};
}

std::uint32_t little_endian_32(const std::string& b, std::size_t at) {
  return std::uint32_t{static_cast<unsigned char>(b[at])} |
         (std::uint32_t{static_cast<unsigned char>(b[at + 1])} << 8) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 2])} << 16) |
         (std::uint32_t{static_cast<unsigned char>(b[at + 3])} << 24);
}

std::string too_large(std::uint64_t width, std::uint64_t height) {
  return std::to_string(width) + " x " + std::to_string(height) + " pixels is too large";
}

std::string truncated(std::uint64_t needed, std::size_t available) {
  return "truncated image: its header needs at least " + std::to_string(needed) +
         " bytes of pixels, the file has " + std::to_string(available);
}

// Netpbm header fields as OpenCV reads them (modules/imgcodecs/src/grfmt_pxm.cpp ReadNumber):
// whitespace and '#' comments before a decimal, and the one character after its digits, whatever
// it is, taken as its end.
class NetpbmHeader {
 public:
  explicit NetpbmHeader(const std::string& bytes) : b_(bytes), pos_(2) {}

  bool number(std::uint64_t& out) {
    while (pos_ < b_.size()) {
      const unsigned char c = static_cast<unsigned char>(b_[pos_]);
      if (c == '#') {
        while (pos_ < b_.size() && b_[pos_] != '\n' && b_[pos_] != '\r') ++pos_;
      } else if (std::isspace(c)) {
        ++pos_;
      } else {
        break;
      }
    }
    const std::size_t start = pos_;
    std::uint64_t v = 0;
    while (pos_ < b_.size() && std::isdigit(static_cast<unsigned char>(b_[pos_])) &&
           v <= 0xFFFFFFFFull) {
      v = v * 10 + static_cast<std::uint64_t>(b_[pos_] - '0');
      ++pos_;
    }
    if (pos_ == start) return false;
    ++pos_;  // the character that ends the number
    out = v;
    return true;
  }

  // Bytes after the header.
  [[nodiscard]] std::size_t remaining() const { return pos_ >= b_.size() ? 0 : b_.size() - pos_; }

 private:
  const std::string& b_;
  std::size_t pos_;
};

std::string netpbm_problem(const std::string& bytes) {
  const char kind = bytes[1];
  NetpbmHeader header(bytes);
  std::uint64_t width = 0, height = 0, maxval = 1;
  if (!header.number(width) || !header.number(height)) return {};  // OpenCV will refuse it
  if (kind != '1' && kind != '4' && !header.number(maxval)) return {};
  if (width > kMaxCells || height > kMaxCells || width * height > kMaxCells) {
    return too_large(width, height);
  }
  const std::uint64_t channels = kind == '3' || kind == '6' ? 3 : 1;
  const std::uint64_t samples = width * height * channels;
  // Least bytes of pixels: P1 one character per pixel, P2/P3 digits and separators, P4 one bit
  // per pixel, P5/P6 one or two bytes per sample.
  const std::uint64_t needed = kind == '1'                  ? samples
                               : kind == '2' || kind == '3' ? samples * 2 - 1
                               : kind == '4'                ? (width + 7) / 8 * height
                                                            : samples * (maxval > 255 ? 2 : 1);
  if (samples > 0 && header.remaining() < needed) return truncated(needed, header.remaining());
  return {};
}

std::string bmp_problem(const std::string& bytes) {
  // BITMAPFILEHEADER (14 bytes), then BITMAPINFOHEADER: width at 18, height at 22 (negative: top
  // row first), bit count at 28, compression at 30 (0: BI_RGB, uncompressed).
  if (bytes.size() < 34) return {};
  const auto width = static_cast<std::int32_t>(little_endian_32(bytes, 18));
  const auto height = static_cast<std::int32_t>(little_endian_32(bytes, 22));
  const std::uint64_t w =
      width < 0 ? 0u - static_cast<std::uint64_t>(width) : static_cast<std::uint64_t>(width);
  const std::uint64_t h =
      height < 0 ? 0u - static_cast<std::uint64_t>(height) : static_cast<std::uint64_t>(height);
  if (w * h > kMaxCells) return too_large(w, h);
  const std::uint32_t bits =
      static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[28])) |
      (static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[29])) << 8);
  if (little_endian_32(bytes, 30) == 0 && bits > 0) {
    const std::uint64_t row_bytes = (w * bits + 31) / 32 * 4;
    if (row_bytes * h > bytes.size()) return truncated(row_bytes * h, bytes.size());
  }
  return {};
}

}  // namespace

bool is_supported_image(const std::string& bytes) {
  if (bytes.size() >= 8 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0) return true;
  if (bytes.size() >= 3 && bytes.compare(0, 3, "\xff\xd8\xff") == 0) return true;  // JPEG SOI
  if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return true;
  // OpenCV's Netpbm decoder wants whitespace after the magic number (PxMDecoder::checkSignature);
  // without it OpenCV offers the bytes to its other decoders, GDCM's DICOM reader among them,
  // which aborts on an assertion (found by fuzz/image_fuzz.cpp).
  return bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6' &&
         std::isspace(static_cast<unsigned char>(bytes[2]));
}

std::string image_header_problem(const std::string& bytes) {
  if (bytes.size() >= 24 && bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") == 0 &&
      bytes.compare(12, 4, "IHDR") == 0) {
    const std::uint64_t width = big_endian_32(bytes, 16), height = big_endian_32(bytes, 20);
    if (width * height > kMaxCells) return too_large(width, height);
    return {};
  }
  if (bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6') {
    return netpbm_problem(bytes);
  }
  if (bytes.size() >= 2 && bytes[0] == 'B' && bytes[1] == 'M') return bmp_problem(bytes);
  return {};
}

}  // namespace tessera::io_internal
