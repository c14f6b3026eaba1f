#pragma once
// The part the ROS 1 and the CDR message readers share: a position in one serialized message, a
// sticky first failure ("byte 40: string of 4000 bytes runs past the end of the message, 12
// left") and checked copies. Reads after a failure return zeros; decoders check ok() once.
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>

#include "internal/byte_cursor.hpp"

namespace tessera::io_internal {

class MessageReaderBase {
 public:
  [[nodiscard]] bool ok() const { return error_.empty(); }
  /// The first failure, naming the byte offset in the message.
  [[nodiscard]] const std::string& error() const { return error_; }
  [[nodiscard]] std::size_t position() const { return pos_; }
  [[nodiscard]] std::size_t remaining() const { return bytes_.size() - pos_; }

  void fail(const std::string& what) {
    if (error_.empty()) error_ = "byte " + std::to_string(pos_) + ": " + what;
  }

 protected:
  explicit MessageReaderBase(Bytes bytes) : bytes_(bytes) {}

  /// Copies n raw bytes (n <= 8), swapping them when `swap`; fails naming `what` when short.
  template <typename T>
  T raw(const char* what, bool swap) {
    static_assert(std::is_trivially_copyable_v<T> && sizeof(T) <= 8);
    if (!ok()) return T{};
    if (sizeof(T) > remaining()) {
      fail(std::string(what) + " needs " + std::to_string(sizeof(T)) + " bytes, " +
           std::to_string(remaining()) + " left in the message");
      return T{};
    }
    unsigned char b[sizeof(T)];
    std::memcpy(b, bytes_.data() + pos_, sizeof(T));
    if (swap) {
      for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(b[i], b[sizeof(T) - 1 - i]);
    }
    T v;
    std::memcpy(&v, b, sizeof(T));
    pos_ += sizeof(T);
    return v;
  }

  /// Checks that `count` elements of `element_bytes` each fit in what is left (no overflow).
  bool fits(std::uint64_t count, std::size_t element_bytes, const char* what) {
    if (!ok()) return false;
    if (element_bytes != 0 && count > remaining() / element_bytes) {
      fail(std::string(what) + " of " + std::to_string(count) + " elements runs past the end " +
           "of the message (" + std::to_string(remaining()) + " bytes left)");
      return false;
    }
    return true;
  }

  Bytes bytes_;
  std::size_t pos_ = 0;
  std::string error_;
};

}  // namespace tessera::io_internal
