#pragma once
// A bounds-checked reader over a byte buffer, shared by the binary bag formats (ROS bag 2.0,
// MCAP) and the message decoders. Every read checks the remaining length first, so a malformed
// length can never read past the buffer; a failed read leaves the cursor where it was.
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <span>
#include <string_view>

namespace tessera::io_internal {

using Bytes = std::span<const std::uint8_t>;

/// Little-endian reads at a position; the caller checks each bool.
class ByteCursor {
 public:
  explicit ByteCursor(Bytes bytes) : bytes_(bytes) {}

  [[nodiscard]] std::size_t position() const { return pos_; }
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }
  [[nodiscard]] bool at_end() const { return pos_ == bytes_.size(); }
  [[nodiscard]] Bytes rest() const { return bytes_.subspan(pos_); }

  [[nodiscard]] bool skip(std::size_t n) {
    if (n > remaining()) return false;
    pos_ += n;
    return true;
  }
  /// The next n bytes as a view into the buffer.
  [[nodiscard]] bool take(std::size_t n, Bytes& out) {
    if (n > remaining()) return false;
    out = bytes_.subspan(pos_, n);
    pos_ += n;
    return true;
  }
  [[nodiscard]] bool u8(std::uint8_t& v) { return fixed(v); }
  [[nodiscard]] bool u16(std::uint16_t& v) { return fixed(v); }
  [[nodiscard]] bool u32(std::uint32_t& v) { return fixed(v); }
  [[nodiscard]] bool u64(std::uint64_t& v) { return fixed(v); }

 private:
  /// Little-endian unsigned integer of sizeof(T) bytes.
  template <typename T>
  [[nodiscard]] bool fixed(T& v) {
    if (sizeof(T) > remaining()) return false;
    T r = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      r = static_cast<T>(r | static_cast<T>(static_cast<T>(bytes_[pos_ + i]) << (8 * i)));
    }
    v = r;
    pos_ += sizeof(T);
    return true;
  }

  Bytes bytes_;
  std::size_t pos_ = 0;
};

[[nodiscard]] inline std::string_view as_text(Bytes b) {
  return {reinterpret_cast<const char*>(b.data()), b.size()};
}
[[nodiscard]] inline Bytes as_bytes(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

}  // namespace tessera::io_internal
