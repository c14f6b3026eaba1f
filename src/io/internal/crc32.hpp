#pragma once
// CRC-32 (IEEE 802.3, reflected, polynomial 0xEDB88320: zlib's crc32, Python's zlib.crc32), as the
// MCAP spec and tessera's session files use it. Incremental: start from kCrc32Init, feed pieces
// with crc32_update, end with crc32_final.
#include <array>
#include <cstdint>
#include <string_view>

namespace tessera::io_internal {

inline constexpr std::uint32_t kCrc32Init = 0xFFFFFFFFU;

[[nodiscard]] inline std::uint32_t crc32_update(std::uint32_t state, std::string_view bytes) {
  static const std::array<std::uint32_t, 256> kTable = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t i = 0; i < 256; ++i) {
      std::uint32_t c = i;
      for (int k = 0; k < 8; ++k) c = (c & 1U) != 0 ? 0xEDB88320U ^ (c >> 1) : c >> 1;
      t[i] = c;
    }
    return t;
  }();
  for (const char ch : bytes) {
    state = kTable[(state ^ static_cast<std::uint8_t>(ch)) & 0xFFU] ^ (state >> 8);
  }
  return state;
}

[[nodiscard]] inline std::uint32_t crc32_final(std::uint32_t state) { return state ^ 0xFFFFFFFFU; }

/// The CRC-32 of `bytes` in one call.
[[nodiscard]] inline std::uint32_t crc32(std::string_view bytes) {
  return crc32_final(crc32_update(kCrc32Init, bytes));
}

}  // namespace tessera::io_internal
