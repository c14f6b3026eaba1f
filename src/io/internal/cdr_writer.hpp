#pragma once
// Writes one ROS 2 message in plain little-endian CDR, the layout cdr_reader.hpp reads: the
// encapsulation header 0x00 0x01 0x00 0x00, then the fields, each aligned to its own size relative
// to the first byte after the header; strings as a uint32 length counting the NUL, the bytes and
// the NUL; sequences as a uint32 count and the elements.
#include <bit>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>
#include <vector>

namespace tessera::io_internal {

static_assert(std::endian::native == std::endian::little,
              "CdrWriter writes native bytes as little endian");

class CdrWriter {
 public:
  CdrWriter() : bytes_{0x00, 0x01, 0x00, 0x00} {}

  void u8(std::uint8_t v) { bytes_.push_back(v); }
  void i8(std::int8_t v) { bytes_.push_back(static_cast<std::uint8_t>(v)); }
  /// A sequence's bytes, appended at once (a map's cells: one insert instead of one push each).
  void i8s(std::span<const std::int8_t> v) {
    const auto* first = reinterpret_cast<const std::uint8_t*>(v.data());
    bytes_.insert(bytes_.end(), first, first + v.size());
  }
  /// A bool: one byte, 1 or 0.
  void boolean(bool v) { u8(v ? 1 : 0); }
  void u32(std::uint32_t v) { put(v); }
  void i32(std::int32_t v) { put(v); }
  void u64(std::uint64_t v) { put(v); }
  void f32(float v) { put(v); }
  void f64(double v) { put(v); }
  void string(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    bytes_.push_back(0);
  }
  /// builtin_interfaces/Time from nanoseconds since the epoch (floor division: a negative time
  /// keeps nanosec in [0, 1e9)).
  void stamp(std::int64_t ns) {
    std::int64_t sec = ns / 1'000'000'000;
    std::int64_t nsec = ns % 1'000'000'000;
    if (nsec < 0) {
      nsec += 1'000'000'000;
      --sec;
    }
    i32(static_cast<std::int32_t>(sec));
    u32(static_cast<std::uint32_t>(nsec));
  }
  /// A sequence's element count.
  void count(std::size_t n) { u32(static_cast<std::uint32_t>(n)); }
  [[nodiscard]] std::vector<std::uint8_t> take() && { return std::move(bytes_); }

 private:
  template <typename T>
  void put(T v) {
    while ((bytes_.size() - 4) % sizeof(T) != 0) bytes_.push_back(0);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
  }
  std::vector<std::uint8_t> bytes_;
};

}  // namespace tessera::io_internal
