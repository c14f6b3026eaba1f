#pragma once
// Writes small ROS bags for tests and benchmarks: messages in ROS 1 serialization or CDR, ROS 1
// bags (format 2.0, chunks none / bz2 / lz4, with index data, connection and chunk info records
// as rosbag writes them) and MCAP files (chunks none / zstd / lz4). Test support only: tessera
// itself reads bags and never writes them. Link BZip2, LZ4 and ZSTD.
#include <bzlib.h>
#include <lz4frame.h>
#include <zstd.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

#include "tessera/io/ros_messages.hpp"

namespace tessera::support {

/// Serializes fields in ROS 1 form (packed) or CDR (little endian, aligned, NUL-terminated
/// strings, with the 4-byte encapsulation header).
class MessageWriter {
 public:
  explicit MessageWriter(RosEncoding encoding) : encoding_(encoding) {
    if (encoding_ == RosEncoding::kCdr) bytes_ = {0x00, 0x01, 0x00, 0x00};
  }
  void u32(std::uint32_t v) { put(v); }
  void f32(float v) { put(v); }
  void f64(double v) { put(v); }
  void stamp(std::int64_t ns) {
    put(static_cast<std::uint32_t>(ns / 1'000'000'000));
    put(static_cast<std::uint32_t>(ns % 1'000'000'000));
  }
  void string(const std::string& s) {
    if (encoding_ == RosEncoding::kRos1) {
      put(static_cast<std::uint32_t>(s.size()));
      bytes_.insert(bytes_.end(), s.begin(), s.end());
    } else {
      put(static_cast<std::uint32_t>(s.size() + 1));
      bytes_.insert(bytes_.end(), s.begin(), s.end());
      bytes_.push_back(0);
    }
  }
  void header(const RosHeader& h) {
    if (encoding_ == RosEncoding::kRos1) u32(0);  // seq
    stamp(h.stamp_ns);
    string(h.frame_id);
  }
  void f32_sequence(const std::vector<float>& v) {
    u32(static_cast<std::uint32_t>(v.size()));
    for (float f : v) f32(f);
  }
  void transform(const RosTransform& t) {
    for (double d : {t.x_m, t.y_m, t.z_m, t.qx, t.qy, t.qz, t.qw}) f64(d);
  }
  [[nodiscard]] std::vector<std::uint8_t> take() && { return std::move(bytes_); }

 private:
  template <typename T>
  void put(T v) {
    if (encoding_ == RosEncoding::kCdr) {
      while ((bytes_.size() - 4) % sizeof(T) != 0) bytes_.push_back(0);
    }
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
  }
  RosEncoding encoding_;
  std::vector<std::uint8_t> bytes_;
};

inline std::vector<std::uint8_t> encode_laser_scan(const LaserScanMessage& m, RosEncoding e) {
  MessageWriter w(e);
  w.header(m.header);
  for (float f : {m.angle_min_rad, m.angle_max_rad, m.angle_increment_rad, m.time_increment_s,
                  m.scan_time_s, m.range_min_m, m.range_max_m}) {
    w.f32(f);
  }
  w.f32_sequence(m.ranges_m);
  w.f32_sequence(m.intensities);
  return std::move(w).take();
}

/// The same scan as a sensor_msgs/MultiEchoLaserScan: per beam `echoes` echoes, the first the
/// range (none where it is NaN), the others 1 m beyond it.
inline std::vector<std::uint8_t> encode_multi_echo_laser_scan(const LaserScanMessage& m,
                                                              RosEncoding e, int echoes = 2) {
  MessageWriter w(e);
  w.header(m.header);
  for (float f : {m.angle_min_rad, m.angle_max_rad, m.angle_increment_rad, m.time_increment_s,
                  m.scan_time_s, m.range_min_m, m.range_max_m}) {
    w.f32(f);
  }
  w.u32(static_cast<std::uint32_t>(m.ranges_m.size()));
  for (float r : m.ranges_m) {
    std::vector<float> beam;
    if (!std::isnan(r)) {
      for (int k = 0; k < echoes; ++k) beam.push_back(r + static_cast<float>(k));
    }
    w.f32_sequence(beam);
  }
  w.u32(static_cast<std::uint32_t>(m.ranges_m.size()));
  for (std::size_t i = 0; i < m.ranges_m.size(); ++i) w.f32_sequence({100.0F});
  return std::move(w).take();
}

inline std::vector<std::uint8_t> encode_odometry(const OdometryMessage& m, RosEncoding e) {
  MessageWriter w(e);
  w.header(m.header);
  w.string(m.child_frame_id);
  w.transform(m.pose);
  for (int i = 0; i < 36 + 6 + 36; ++i) w.f64(0.0);
  return std::move(w).take();
}

inline std::vector<std::uint8_t> encode_tf_message(const TfMessage& m, RosEncoding e) {
  MessageWriter w(e);
  w.u32(static_cast<std::uint32_t>(m.transforms.size()));
  for (const TransformStampedMessage& t : m.transforms) {
    w.header(t.header);
    w.string(t.child_frame_id);
    w.transform(t.transform);
  }
  return std::move(w).take();
}

struct TopicToWrite {
  std::string name;
  std::string type;  // "sensor_msgs/LaserScan" (ROS 1 bags) or "sensor_msgs/msg/LaserScan"
};
struct MessageToWrite {
  std::size_t topic = 0;
  std::int64_t t_ns = 0;
  std::vector<std::uint8_t> data;
};

namespace bag_writer_detail {

inline void put_u8(std::string& out, std::uint8_t v) { out.push_back(static_cast<char>(v)); }
template <typename T>
void put_le(std::string& out, T v) {
  for (std::size_t i = 0; i < sizeof(T); ++i)
    out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
inline std::string bin_u32(std::uint32_t v) {
  std::string s;
  put_le(s, v);
  return s;
}
inline std::string bin_u64(std::uint64_t v) {
  std::string s;
  put_le(s, v);
  return s;
}
/// ROS bag time: secs u32 then nsecs u32.
inline std::string bin_time(std::int64_t ns) {
  return bin_u32(static_cast<std::uint32_t>(ns / 1'000'000'000)) +
         bin_u32(static_cast<std::uint32_t>(ns % 1'000'000'000));
}

/// A ROS 1 record: header fields (name, value) and data.
inline std::string ros1_record(const std::vector<std::pair<std::string, std::string>>& fields,
                               const std::string& data) {
  std::string header;
  for (const auto& [name, value] : fields) {
    put_le(header, static_cast<std::uint32_t>(name.size() + 1 + value.size()));
    header += name + "=" + value;
  }
  std::string out;
  put_le(out, static_cast<std::uint32_t>(header.size()));
  out += header;
  put_le(out, static_cast<std::uint32_t>(data.size()));
  return out + data;
}

inline std::string compress(const std::string& method, const std::string& in) {
  if (method == "bz2") {
    std::string out(in.size() + in.size() / 100 + 600, '\0');
    auto n = static_cast<unsigned int>(out.size());
    BZ2_bzBuffToBuffCompress(out.data(), &n, const_cast<char*>(in.data()),
                             static_cast<unsigned int>(in.size()), 9, 0, 0);
    out.resize(n);
    return out;
  }
  if (method == "lz4") {
    std::string out(LZ4F_compressFrameBound(in.size(), nullptr), '\0');
    out.resize(LZ4F_compressFrame(out.data(), out.size(), in.data(), in.size(), nullptr));
    return out;
  }
  if (method == "zstd") {
    std::string out(ZSTD_compressBound(in.size()), '\0');
    out.resize(ZSTD_compress(out.data(), out.size(), in.data(), in.size(), 3));
    return out;
  }
  return in;  // "none", "" and names the reader must refuse are written uncompressed
}

}  // namespace bag_writer_detail

/// A ROS 1 bag 2.0 as rosbag writes it: bag header (padded to 4096 bytes), chunks of
/// `per_chunk` messages each followed by its index data records, then the connection and chunk
/// info records at index_pos. `compression` goes into each chunk's header as is.
inline std::string write_ros1_bag(const std::vector<TopicToWrite>& topics,
                                  const std::vector<MessageToWrite>& messages,
                                  const std::string& compression = "none",
                                  std::size_t per_chunk = 50) {
  using namespace bag_writer_detail;
  auto connection = [&](std::size_t i) {
    std::string data;
    for (const auto& [k, v] :
         std::vector<std::pair<std::string, std::string>>{{"topic", topics[i].name},
                                                          {"type", topics[i].type},
                                                          {"md5sum", "*"},
                                                          {"message_definition", ""}}) {
      put_le(data, static_cast<std::uint32_t>(k.size() + 1 + v.size()));
      data += k + "=" + v;
    }
    return ros1_record({{"op", "\x07"},
                        {"conn", bin_u32(static_cast<std::uint32_t>(i))},
                        {"topic", topics[i].name}},
                       data);
  };
  std::string body;  // everything after the bag header record
  const std::size_t header_end = 13 + 4096;
  std::string chunk_infos;
  std::uint32_t chunk_count = 0;
  for (std::size_t first = 0; first < messages.size(); first += per_chunk) {
    const std::size_t last = std::min(messages.size(), first + per_chunk);
    std::string inner;
    std::vector<bool> written(topics.size(), false);
    std::map<std::size_t, std::vector<std::pair<std::int64_t, std::uint32_t>>> index;
    for (std::size_t i = first; i < last; ++i) {
      const MessageToWrite& m = messages[i];
      if (!written[m.topic]) inner += connection(m.topic);
      written[m.topic] = true;
      index[m.topic].emplace_back(m.t_ns, static_cast<std::uint32_t>(inner.size()));
      inner += ros1_record({{"op", "\x02"},
                            {"conn", bin_u32(static_cast<std::uint32_t>(m.topic))},
                            {"time", bin_time(m.t_ns)}},
                           std::string(m.data.begin(), m.data.end()));
    }
    const std::size_t chunk_pos = header_end + body.size();
    body += ros1_record({{"op", "\x05"},
                         {"compression", compression},
                         {"size", bin_u32(static_cast<std::uint32_t>(inner.size()))}},
                        compress(compression, inner));
    std::string counts;
    for (const auto& [conn, entries] : index) {
      std::string data;
      for (const auto& [t, offset] : entries) data += bin_time(t) + bin_u32(offset);
      body += ros1_record({{"op", "\x04"},
                           {"ver", bin_u32(1)},
                           {"conn", bin_u32(static_cast<std::uint32_t>(conn))},
                           {"count", bin_u32(static_cast<std::uint32_t>(entries.size()))}},
                          data);
      counts += bin_u32(static_cast<std::uint32_t>(conn)) +
                bin_u32(static_cast<std::uint32_t>(entries.size()));
    }
    chunk_infos += ros1_record({{"op", "\x06"},
                                {"ver", bin_u32(1)},
                                {"chunk_pos", bin_u64(chunk_pos)},
                                {"start_time", bin_time(messages[first].t_ns)},
                                {"end_time", bin_time(messages[last - 1].t_ns)},
                                {"count", bin_u32(static_cast<std::uint32_t>(index.size()))}},
                               counts);
    ++chunk_count;
  }
  const std::size_t index_pos = header_end + body.size();
  for (std::size_t i = 0; i < topics.size(); ++i) body += connection(i);
  body += chunk_infos;
  std::string header =
      ros1_record({{"op", "\x03"},
                   {"index_pos", bin_u64(index_pos)},
                   {"conn_count", bin_u32(static_cast<std::uint32_t>(topics.size()))},
                   {"chunk_count", bin_u32(chunk_count)}},
                  "");
  // Pad the bag header record's data with spaces to 4096 bytes in all.
  const std::size_t pad = 4096 - header.size();
  header = ros1_record({{"op", "\x03"},
                        {"index_pos", bin_u64(index_pos)},
                        {"conn_count", bin_u32(static_cast<std::uint32_t>(topics.size()))},
                        {"chunk_count", bin_u32(chunk_count)}},
                       std::string(pad, ' '));
  return "#ROSBAG V2.0\n" + header + body;
}

/// An MCAP file: header, one chunk per `per_chunk` messages holding the schemas and channels
/// first used in it and the messages, data end, footer without summary. `encoding` is the
/// channels' message_encoding ("cdr" or "ros1").
inline std::string write_mcap(const std::vector<TopicToWrite>& topics,
                              const std::vector<MessageToWrite>& messages,
                              const std::string& compression, const std::string& encoding = "cdr",
                              std::size_t per_chunk = 50) {
  using namespace bag_writer_detail;
  auto string = [](const std::string& s) {
    return bin_u32(static_cast<std::uint32_t>(s.size())) + s;
  };
  auto record = [](std::uint8_t op, const std::string& content) {
    std::string out;
    put_u8(out, op);
    put_le(out, static_cast<std::uint64_t>(content.size()));
    return out + content;
  };
  std::string out = std::string("\x89MCAP0\r\n", 8);
  out += record(0x01, string("ros2") + string("tessera-test"));
  std::vector<bool> defined(topics.size(), false);
  for (std::size_t first = 0; first < messages.size(); first += per_chunk) {
    const std::size_t last = std::min(messages.size(), first + per_chunk);
    std::string inner;
    for (std::size_t i = first; i < last; ++i) {
      const MessageToWrite& m = messages[i];
      const auto id = static_cast<std::uint16_t>(m.topic + 1);
      if (!defined[m.topic]) {
        std::string schema;
        put_le(schema, id);
        schema += string(topics[m.topic].type) + string(encoding == "cdr" ? "ros2msg" : "ros1msg") +
                  string("");
        inner += record(0x03, schema);
        std::string channel;
        put_le(channel, id);
        put_le(channel, id);
        channel += string(topics[m.topic].name) + string(encoding) + bin_u32(0);
        inner += record(0x04, channel);
        defined[m.topic] = true;
      }
      std::string message;
      put_le(message, id);
      put_le(message, static_cast<std::uint32_t>(i));
      put_le(message, static_cast<std::uint64_t>(m.t_ns));
      put_le(message, static_cast<std::uint64_t>(m.t_ns));
      message.append(m.data.begin(), m.data.end());
      inner += record(0x05, message);
    }
    const std::string compressed = compress(compression.empty() ? "none" : compression, inner);
    std::string chunk;
    put_le(chunk, static_cast<std::uint64_t>(messages[first].t_ns));
    put_le(chunk, static_cast<std::uint64_t>(messages[last - 1].t_ns));
    put_le(chunk, static_cast<std::uint64_t>(inner.size()));
    put_le(chunk, std::uint32_t{0});
    chunk += string(compression);
    put_le(chunk, static_cast<std::uint64_t>(compressed.size()));
    chunk += compressed;
    out += record(0x06, chunk);
  }
  out += record(0x0F, bin_u32(0));
  std::string footer;
  put_le(footer, std::uint64_t{0});
  put_le(footer, std::uint64_t{0});
  put_le(footer, std::uint32_t{0});
  out += record(0x02, footer);
  return out + std::string("\x89MCAP0\r\n", 8);
}

}  // namespace tessera::support
