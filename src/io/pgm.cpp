#include "tessera/io/pgm.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <string>

#include "internal/file_util.hpp"

namespace tessera {
namespace {

// Cursor over a PGM that skips whitespace and '#' comments (netpbm pgm(5)) and knows its line for
// error messages.
class PgmReader {
 public:
  PgmReader(std::string_view bytes, const std::string& name) : bytes_(bytes), name_(name) {}

  void skip_space_and_comments() {
    while (pos_ < bytes_.size()) {
      const char c = bytes_[pos_];
      if (c == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        if (c == '\n') ++line_;
        ++pos_;
      } else {
        return;
      }
    }
  }

  // An unsigned decimal after whitespace/comments; false with `error_` set when there is none.
  bool number(const char* what, const char* context, std::uint64_t& out) {
    skip_space_and_comments();
    const std::size_t start = pos_;
    std::uint64_t v = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_]))) {
      v = v * 10 + static_cast<std::uint64_t>(bytes_[pos_] - '0');
      if (v > 0xFFFFFFFFull) {
        error_ = error(std::string(context) + what + " is too large");
        return false;
      }
      ++pos_;
    }
    if (pos_ == start) {
      error_ = error(std::string(context) + "expected " + what + ", got " + token_here());
      return false;
    }
    out = v;
    return true;
  }

  [[nodiscard]] Error error(const std::string& what) const {
    return input_error(name_ + ":" + std::to_string(line_) + ": " + what);
  }

  [[nodiscard]] std::string token_here() const {
    if (pos_ >= bytes_.size()) return "end of file";
    std::string token;
    for (std::size_t i = pos_; i < bytes_.size() && token.size() < 12; ++i) {
      const unsigned char c = static_cast<unsigned char>(bytes_[i]);
      if (std::isspace(c)) break;
      token += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    return "'" + token + "'";
  }

  [[nodiscard]] bool at_space() const {
    return pos_ < bytes_.size() && std::isspace(static_cast<unsigned char>(bytes_[pos_]));
  }

  std::string_view bytes_;
  const std::string& name_;
  std::size_t pos_ = 0;
  int line_ = 1;
  Error error_;
};

std::uint8_t scale_to_8_bit(std::uint64_t v, std::uint64_t maxval) {
  if (maxval == 255) return static_cast<std::uint8_t>(v);
  return static_cast<std::uint8_t>((v * 255 + maxval / 2) / maxval);
}

// Images above this many pixels are refused before anything is allocated (2^31: a 46 000-pixel
// square; far beyond any floor plan).
constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 31;

}  // namespace

Result<GrayImage> decode_pgm(std::string_view bytes, const std::string& name) {
  if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '5' && bytes[1] != '2')) {
    std::string magic;
    for (std::size_t i = 0; i < 2 && i < bytes.size(); ++i) {
      const unsigned char c = static_cast<unsigned char>(bytes[i]);
      magic += std::isprint(c) ? static_cast<char>(c) : '?';
    }
    return input_error(name + ": not a PGM file (starts with '" + magic +
                       "', expected 'P5' or 'P2')");
  }
  const bool binary = bytes[1] == '5';
  PgmReader in(bytes, name);
  in.pos_ = 2;
  if (!in.at_space() && !(in.pos_ < bytes.size() && bytes[in.pos_] == '#')) {
    return in.error("bad PGM header: expected whitespace after the magic number, got " +
                    in.token_here());
  }
  std::uint64_t width = 0, height = 0, maxval = 0;
  constexpr const char* kHeader = "bad PGM header: ";
  if (!in.number("width", kHeader, width)) return in.error_;
  if (!in.number("height", kHeader, height)) return in.error_;
  if (!in.number("maxval", kHeader, maxval)) return in.error_;
  if (width == 0 || height == 0) {
    return in.error(std::string(kHeader) + "width and height must be > 0, got " +
                    std::to_string(width) + " x " + std::to_string(height));
  }
  if (maxval == 0 || maxval > 65535) {
    return in.error(std::string(kHeader) + "maxval must be in 1..65535, got " +
                    std::to_string(maxval));
  }
  if (width * height > kMaxPixels) {
    return in.error(std::string(kHeader) + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels is too large");
  }
  const std::size_t count = static_cast<std::size_t>(width * height);

  if (binary) {
    // Exactly one whitespace character separates maxval from the raster.
    if (!in.at_space()) {
      return in.error(std::string(kHeader) + "expected whitespace after maxval, got " +
                      in.token_here());
    }
    ++in.pos_;
    const std::size_t bytes_per_sample = maxval > 255 ? 2 : 1;
    const std::size_t expected = count * bytes_per_sample;
    const std::size_t available = bytes.size() - in.pos_;
    if (available < expected) {
      return input_error(name + ": truncated pixel data: expected " + std::to_string(width) + "*" +
                         std::to_string(height) + (bytes_per_sample == 2 ? "*2" : "") + " = " +
                         std::to_string(expected) + " bytes, got " + std::to_string(available));
    }
    GrayImage image(static_cast<int>(width), static_cast<int>(height));
    const auto* raster = reinterpret_cast<const unsigned char*>(bytes.data() + in.pos_);
    for (std::size_t i = 0; i < count; ++i) {
      std::uint64_t v = bytes_per_sample == 2
                            ? (std::uint64_t{raster[2 * i]} << 8) | raster[2 * i + 1]
                            : std::uint64_t{raster[i]};
      if (v > maxval) v = maxval;  // out-of-range samples saturate (netpbm tools do the same)
      image.pixels[i] = scale_to_8_bit(v, maxval);
    }
    return image;
  }

  // Plain PGM: every value takes a digit and a separator, so the rest of the file bounds the
  // count before the image is allocated (a 20-byte header must not allocate gigabytes).
  if (const std::size_t room = (bytes.size() - std::min(in.pos_, bytes.size()) + 1) / 2;
      count > room) {
    return input_error(name + ": truncated pixel data: expected " + std::to_string(width) + "*" +
                       std::to_string(height) + " = " + std::to_string(count) +
                       " values, the file has room for at most " + std::to_string(room));
  }
  GrayImage image(static_cast<int>(width), static_cast<int>(height));
  for (std::size_t i = 0; i < count; ++i) {
    in.skip_space_and_comments();
    if (in.pos_ >= bytes.size()) {
      return input_error(name + ":" + std::to_string(in.line_) +
                         ": truncated pixel data: expected " + std::to_string(width) + "*" +
                         std::to_string(height) + " = " + std::to_string(count) + " values, got " +
                         std::to_string(i));
    }
    std::uint64_t v = 0;
    if (!in.number("a pixel value", "bad PGM pixel data: ", v)) return in.error_;
    if (v > maxval) {
      return in.error("bad PGM pixel data: value " + std::to_string(v) + " exceeds maxval " +
                      std::to_string(maxval));
    }
    image.pixels[i] = scale_to_8_bit(v, maxval);
  }
  return image;
}

Result<GrayImage> read_pgm(const std::filesystem::path& path) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  return decode_pgm(*bytes, path.string());
}

std::string encode_pgm(const GrayImage& image) {
  std::string out =
      "P5\n" + std::to_string(image.width) + " " + std::to_string(image.height) + "\n255\n";
  out.append(reinterpret_cast<const char*>(image.pixels.data()), image.pixels.size());
  return out;
}

}  // namespace tessera
