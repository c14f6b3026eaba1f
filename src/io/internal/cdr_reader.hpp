#pragma once
// Reads one ROS 2 message in CDR (OMG DDS-XTypes 1.3, 7.4.3 "XCDR1", plain CDR as rmw_fastrtps
// and rmw_cyclonedds write it): a 4-byte encapsulation header (0x00 0x01 little endian, 0x00 0x00
// big endian, then two option bytes), then the fields, each aligned to its own size (1, 2, 4, 8)
// relative to the first byte after the header. Strings are a uint32 length that counts the
// terminating NUL, the bytes and the NUL; sequences are a uint32 count and the elements.
// builtin_interfaces/Time is int32 sec + uint32 nanosec; std_msgs/Header has no seq in ROS 2.
#include <algorithm>
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "internal/message_reader_base.hpp"

namespace tessera::io_internal {

class CdrReader : public MessageReaderBase {
 public:
  static constexpr bool kHasHeaderSeq = false;

  /// Reads the encapsulation header; a message shorter than it or with another representation
  /// (XCDR2, parameter lists) fails.
  explicit CdrReader(Bytes message) : MessageReaderBase(message) {
    if (message.size() < 4) {
      fail("CDR message of " + std::to_string(message.size()) +
           " bytes has no 4-byte encapsulation header");
      return;
    }
    if (message[0] != 0x00 || (message[1] != 0x00 && message[1] != 0x01)) {
      fail("CDR encapsulation " + std::to_string(message[0]) + "," + std::to_string(message[1]) +
           " is not plain CDR (expected 0,1 little endian or 0,0 big endian)");
      return;
    }
    swap_ = (message[1] == 0x01) != (std::endian::native == std::endian::little);
    origin_ = 4;
    pos_ = 4;
  }

  std::uint8_t u8(const char* what) { return aligned<std::uint8_t>(what); }
  std::int8_t i8(const char* what) { return aligned<std::int8_t>(what); }
  std::uint32_t u32(const char* what) { return aligned<std::uint32_t>(what); }
  std::int32_t i32(const char* what) { return aligned<std::int32_t>(what); }
  std::uint64_t u64(const char* what) { return aligned<std::uint64_t>(what); }
  float f32(const char* what) { return aligned<float>(what); }
  double f64(const char* what) { return aligned<double>(what); }

  /// A bool: one byte, 0 or 1; any other value fails, as Fast CDR refuses it.
  bool boolean(const char* what) {
    if (ok() && remaining() > 0 && bytes_[pos_] > 1) {
      fail(std::string(what) + ": bool of value " + std::to_string(bytes_[pos_]) +
           " is neither 0 nor 1");
      return false;
    }
    return u8(what) != 0;
  }

  /// builtin_interfaces/Time as nanoseconds.
  std::int64_t stamp_ns(const char* what) {
    const std::int32_t sec = i32(what);
    const std::uint32_t nsec = u32(what);
    return static_cast<std::int64_t>(sec) * 1'000'000'000 + nsec;
  }

  /// A CDR string: the length includes the NUL, which must be there.
  std::string string(const char* what) {
    const std::uint32_t n = u32(what);
    if (!fits(n, 1, what)) return {};
    if (n == 0) {  // some writers encode the empty string as length 0
      return {};
    }
    if (bytes_[pos_ + n - 1] != 0) {
      fail(std::string(what) + ": string of " + std::to_string(n) +
           " bytes has no terminating NUL");
      return {};
    }
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n - 1);
    pos_ += n;
    return s;
  }

  /// float32[], uint8[], int8[]: a uint32 count, then the values; a count that runs past the
  /// message fails before anything is allocated.
  std::vector<float> f32_sequence(const char* what) { return sequence<float>(what); }
  std::vector<std::uint8_t> u8_sequence(const char* what) { return sequence<std::uint8_t>(what); }
  std::vector<std::int8_t> i8_sequence(const char* what) { return sequence<std::int8_t>(what); }

  std::uint32_t sequence_count(std::size_t min_element_bytes, const char* what) {
    const std::uint32_t n = u32(what);
    return fits(n, min_element_bytes, what) ? n : 0;
  }

 private:
  /// Moves to the next multiple of `n` from the origin; the padding must be in the message.
  bool align(std::size_t n, const char* what) {
    const std::size_t offset = (pos_ - origin_) % n;
    if (offset == 0) return true;
    const std::size_t pad = n - offset;
    if (pad > remaining()) {
      fail(std::string(what) + ": alignment padding runs past the end of the message");
      return false;
    }
    pos_ += pad;
    return true;
  }

  template <typename T>
  T aligned(const char* what) {
    if (!ok() || !align(sizeof(T), what)) return T{};
    return raw<T>(what, swap_);
  }

  /// A sequence of a fixed-size type: the count, then (when there are elements) padding to the
  /// element's alignment and the elements, swapped to native order.
  template <typename T>
  std::vector<T> sequence(const char* what) {
    static_assert(std::is_trivially_copyable_v<T>);
    const std::uint32_t n = u32(what);
    if (!ok()) return {};
    if (n > 0 && !align(sizeof(T), what)) return {};
    if (!fits(n, sizeof(T), what)) return {};
    std::vector<T> out(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + pos_, std::size_t{n} * sizeof(T));
    if (swap_ && sizeof(T) > 1) {
      for (T& v : out) {
        unsigned char b[sizeof(T)];
        std::memcpy(b, &v, sizeof(T));
        std::reverse(b, b + sizeof(T));
        std::memcpy(&v, b, sizeof(T));
      }
    }
    pos_ += std::size_t{n} * sizeof(T);
    return out;
  }

  bool swap_ = false;
  std::size_t origin_ = 0;
};

}  // namespace tessera::io_internal
