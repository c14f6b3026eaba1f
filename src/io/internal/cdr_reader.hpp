#pragma once
// Reads one ROS 2 message in CDR (OMG DDS-XTypes 1.3, 7.4.3 "XCDR1", plain CDR as rmw_fastrtps
// and rmw_cyclonedds write it): a 4-byte encapsulation header (0x00 0x01 little endian, 0x00 0x00
// big endian, then two option bytes), then the fields, each aligned to its own size (1, 2, 4, 8)
// relative to the first byte after the header. Strings are a uint32 length that counts the
// terminating NUL, the bytes and the NUL; sequences are a uint32 count and the elements.
// builtin_interfaces/Time is int32 sec + uint32 nanosec; std_msgs/Header has no seq in ROS 2.
#include <bit>
#include <cstdint>
#include <string>
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

  std::uint32_t u32(const char* what) { return aligned<std::uint32_t>(what); }
  std::int32_t i32(const char* what) { return aligned<std::int32_t>(what); }
  float f32(const char* what) { return aligned<float>(what); }
  double f64(const char* what) { return aligned<double>(what); }

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

  std::vector<float> f32_sequence(const char* what) {
    const std::uint32_t n = u32(what);
    if (!ok()) return {};
    if (n > 0 && !align(4, what)) return {};
    if (!fits(n, 4, what)) return {};
    std::vector<float> out(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + pos_, std::size_t{n} * 4);
    if (swap_) {
      for (float& f : out) {
        const auto u = std::bit_cast<std::uint32_t>(f);
        f = std::bit_cast<float>((u >> 24) | ((u >> 8) & 0xff00u) | ((u << 8) & 0xff0000u) |
                                 (u << 24));
      }
    }
    pos_ += std::size_t{n} * 4;
    return out;
  }

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

  bool swap_ = false;
  std::size_t origin_ = 0;
};

}  // namespace tessera::io_internal
