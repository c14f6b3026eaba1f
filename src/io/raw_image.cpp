#include "internal/raw_image.hpp"

#include <array>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "internal/cv_image.hpp"
#include "internal/file_util.hpp"
#include "internal/image_header.hpp"
#include "tessera/io/pgm.hpp"

namespace tessera::io_internal {
namespace {

bool looks_like_pgm(const std::string& bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' && (bytes[1] == '5' || bytes[1] == '2');
}

// CRC-32 as PNG uses it (ISO 3309 / ITU-T V.42, PNG specification section 5.5).
std::uint32_t crc32(const unsigned char* data, std::size_t n) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < n; ++i) c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t big_endian_32(const unsigned char* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) |
         std::uint32_t{p[3]};
}

std::uint8_t to_8_bit(const cv::Mat& m, int row, int col, int channel) {
  const int channels = m.channels();
  if (m.depth() == CV_16U) {
    const auto v = m.ptr<std::uint16_t>(row)[col * channels + channel];
    return static_cast<std::uint8_t>((static_cast<unsigned>(v) * 255u + 32767u) / 65535u);
  }
  return m.ptr<std::uint8_t>(row)[col * channels + channel];
}

}  // namespace

// Walks the PNG chunk structure (PNG specification section 5) and checks every chunk's CRC, so that
// truncated or damaged files are reported here instead of by libpng, whose default error handler
// (used by OpenCV's decoder) prints to stderr. Empty when the structure is sound.
std::string png_structure_problem(const std::string& bytes) {
  const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
  std::size_t pos = 8;
  bool first = true;
  while (true) {
    if (bytes.size() - pos < 12) {
      return "truncated PNG: no IEND chunk (file ends at byte " + std::to_string(bytes.size()) +
             ")";
    }
    const std::uint32_t length = big_endian_32(data + pos);
    const std::string type(bytes, pos + 4, 4);
    if (length > bytes.size() - pos - 12) {
      return "truncated PNG: chunk '" + type + "' at byte " + std::to_string(pos) + " needs " +
             std::to_string(length + 12) + " bytes, " + std::to_string(bytes.size() - pos) +
             " remain";
    }
    if (first && type != "IHDR") return "damaged PNG: first chunk is '" + type + "', not 'IHDR'";
    first = false;
    if (crc32(data + pos + 4, length + 4) != big_endian_32(data + pos + 8 + length)) {
      return "damaged PNG: CRC mismatch in chunk '" + type + "' at byte " + std::to_string(pos);
    }
    if (type == "IEND") return {};
    pos += length + 12;
  }
}

Result<RawImage> read_raw_image(const std::filesystem::path& path) {
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return decode_raw_image(*bytes, path.string());
}

Result<RawImage> decode_raw_image(const std::string& bytes, const std::string& name) {
  RawImage image;
  if (looks_like_pgm(bytes)) {
    Result<GrayImage> gray = decode_pgm(bytes, name);
    if (!gray) return gray.error();
    image.width = gray->width;
    image.height = gray->height;
    image.rgb_sum.resize(gray->pixels.size());
    for (std::size_t i = 0; i < gray->pixels.size(); ++i) {
      image.rgb_sum[i] = static_cast<std::uint16_t>(3 * gray->pixels[i]);
    }
    return image;
  }
  if (looks_like_png(bytes)) {
    if (const std::string problem = png_structure_problem(bytes); !problem.empty()) {
      return input_error(name + ": cannot decode image: " + problem);
    }
  }
  if (const std::string problem = image_header_problem(bytes); !problem.empty()) {
    return input_error(name + ": cannot decode image: " + problem);
  }
  const cv::Mat m = imdecode_or_empty(bytes, cv::IMREAD_UNCHANGED);
  if (m.empty() || m.dims != 2 || (m.depth() != CV_8U && m.depth() != CV_16U) || m.channels() < 1 ||
      m.channels() > 4) {
    return input_error(name + ": cannot decode image (expected a PNG or PGM file)");
  }
  image.width = m.cols;
  image.height = m.rows;
  const std::size_t n = static_cast<std::size_t>(m.cols) * static_cast<std::size_t>(m.rows);
  image.rgb_sum.resize(n);
  const int channels = m.channels();
  // OpenCV orders colour channels B, G, R(, A); grey+alpha (2 channels) is G, A.
  const bool alpha = channels == 2 || channels == 4;
  if (alpha) image.alpha.resize(n);
  std::size_t i = 0;
  for (int row = 0; row < m.rows; ++row) {
    for (int col = 0; col < m.cols; ++col, ++i) {
      if (channels <= 2) {
        image.rgb_sum[i] = static_cast<std::uint16_t>(3 * to_8_bit(m, row, col, 0));
      } else {
        image.rgb_sum[i] = static_cast<std::uint16_t>(
            to_8_bit(m, row, col, 0) + to_8_bit(m, row, col, 1) + to_8_bit(m, row, col, 2));
      }
      if (alpha) image.alpha[i] = to_8_bit(m, row, col, channels - 1);
    }
  }
  return image;
}

GrayImage to_gray(const RawImage& image) {
  GrayImage gray(image.width, image.height);
  for (std::size_t i = 0; i < image.rgb_sum.size(); ++i) {
    gray.pixels[i] = static_cast<std::uint8_t>((image.rgb_sum[i] + 1) / 3);
  }
  return gray;
}

int map_cell_value(const RawImage& image, std::size_t i, const PixelRules& rules) {
  // nav2_map_server map_io.cpp loadMapFromFile: channels R, G, B, plus (trinary only) alpha when
  // the image has one; shade = mean of the channels on [0, 1].
  double shade = 0.0;
  if (rules.mode == PixelMode::kTrinary && image.has_alpha()) {
    shade = (image.rgb_sum[i] + image.alpha[i]) / (4.0 * 255.0);
  } else {
    shade = image.rgb_sum[i] / (3.0 * 255.0);
  }
  const double occ = rules.negate ? shade : 1.0 - shade;
  switch (rules.mode) {
    case PixelMode::kTrinary:
      if (rules.occupied_thresh < occ) return 100;
      if (occ < rules.free_thresh) return 0;
      return -1;
    case PixelMode::kScale:
      if (image.has_alpha() && image.alpha[i] != 255) return -1;
      if (rules.occupied_thresh < occ) return 100;
      if (occ < rules.free_thresh) return 0;
      if (rules.occupied_thresh <= rules.free_thresh) return -1;  // occ == both: no scale
      return static_cast<int>(std::rint((occ - rules.free_thresh) /
                                        (rules.occupied_thresh - rules.free_thresh) * 100.0));
    case PixelMode::kRaw: {
      const double v = std::round(shade * 255.0);
      return (0.0 <= v && v <= 100.0) ? static_cast<int>(v) : -1;
    }
  }
  return -1;
}

OccupancyGrid grid_from_image(const RawImage& image, Vec2 origin, double resolution_m,
                              const PixelRules& rules) {
  OccupancyGrid grid(GridGeometry(origin, resolution_m, image.width, image.height));
  std::size_t i = 0;
  for (int row = 0; row < image.height; ++row) {
    const int y = image.height - 1 - row;
    for (int x = 0; x < image.width; ++x, ++i) {
      const int v = map_cell_value(image, i, rules);
      if (v >= 0) grid.set_probability({x, y}, v / 100.0);
    }
  }
  return grid;
}

std::string threshold_problem(double occupied_thresh, double free_thresh) {
  if (!(0.0 <= occupied_thresh && occupied_thresh <= 1.0)) {
    return "occupied_thresh must be in [0, 1], got " + format_double(occupied_thresh);
  }
  if (!(0.0 <= free_thresh && free_thresh <= 1.0)) {
    return "free_thresh must be in [0, 1], got " + format_double(free_thresh);
  }
  if (free_thresh > occupied_thresh) {
    return "free_thresh (" + format_double(free_thresh) + ") must not exceed occupied_thresh (" +
           format_double(occupied_thresh) + ")";
  }
  return {};
}

}  // namespace tessera::io_internal
