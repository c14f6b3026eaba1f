#pragma once
// Netpbm PGM ("portable graymap", netpbm pgm(5) manual): magic P5 (binary) or P2 (ASCII), then
// width, height and maxval as ASCII decimals separated by whitespace, '#' comments allowed in the
// header, one whitespace character, then the raster, top row first. maxval <= 255: one byte per
// sample; maxval up to 65535: two bytes, most significant first.
#include <filesystem>
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"
#include "tessera/io/gray_image.hpp"

namespace tessera {

/// Reads a P5 or P2 file. Samples are scaled to 8 bits: round(v * 255 / maxval), so 16-bit and
/// low-maxval files read as ordinary 0..255 images. kInput errors name the file and, in the header,
/// the line: "not a PGM file", "bad PGM header", "truncated pixel data: expected W*H bytes, got N".
[[nodiscard]] Result<GrayImage> read_pgm(const std::filesystem::path& path);

/// As read_pgm, from bytes already in memory; `name` is used in error messages.
[[nodiscard]] Result<GrayImage> decode_pgm(std::string_view bytes, const std::string& name);

/// A binary (P5) PGM with maxval 255.
[[nodiscard]] std::string encode_pgm(const GrayImage& image);

}  // namespace tessera
