#pragma once
// Reads one message in ROS 1 serialization (wiki.ros.org/msg, "Serialization"): little endian,
// no padding; strings and variable arrays are a uint32 count followed by the elements; time is
// uint32 secs + uint32 nsecs; std_msgs/Header is uint32 seq, time stamp, string frame_id.
#include <cstdint>
#include <string>
#include <vector>

#include "internal/message_reader_base.hpp"

namespace tessera::io_internal {

class Ros1Reader : public MessageReaderBase {
 public:
  static constexpr bool kHasHeaderSeq = true;
  explicit Ros1Reader(Bytes message) : MessageReaderBase(message) {}

  std::uint32_t u32(const char* what) { return raw<std::uint32_t>(what, false); }
  float f32(const char* what) { return raw<float>(what, false); }
  double f64(const char* what) { return raw<double>(what, false); }

  /// ROS time: uint32 secs, uint32 nsecs, as nanoseconds.
  std::int64_t stamp_ns(const char* what) {
    const std::uint32_t sec = u32(what);
    const std::uint32_t nsec = u32(what);
    return static_cast<std::int64_t>(sec) * 1'000'000'000 + nsec;
  }

  std::string string(const char* what) {
    const std::uint32_t n = u32(what);
    if (!fits(n, 1, what)) return {};
    std::string s(reinterpret_cast<const char*>(bytes_.data() + pos_), n);
    pos_ += n;
    return s;
  }

  /// float32[]: uint32 count, then the values.
  std::vector<float> f32_sequence(const char* what) {
    const std::uint32_t n = u32(what);
    if (!fits(n, 4, what)) return {};
    std::vector<float> out(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + pos_, std::size_t{n} * 4);
    pos_ += std::size_t{n} * 4;
    return out;
  }

  /// The element count of a variable-length array whose elements take at least
  /// `min_element_bytes` each (checked against what is left, so a bad count cannot allocate).
  std::uint32_t sequence_count(std::size_t min_element_bytes, const char* what) {
    const std::uint32_t n = u32(what);
    return fits(n, min_element_bytes, what) ? n : 0;
  }
};

}  // namespace tessera::io_internal
