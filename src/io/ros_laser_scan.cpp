// sensor_msgs/LaserScan in ROS 1 serialization and CDR (the .msg definition: Header, seven
// float32 fields, float32[] ranges, float32[] intensities), and sensor_msgs/MultiEchoLaserScan
// (the same with LaserEcho[] ranges and intensities, a LaserEcho being a float32[] echoes).
#include <limits>
#include <vector>

#include "internal/cdr_reader.hpp"
#include "internal/ros1_reader.hpp"
#include "internal/ros_message_fields.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera {
namespace {

/// The fields before the ranges, the same in both types.
template <typename Reader>
LaserScanMessage read_scan_fields(Reader& r) {
  LaserScanMessage m;
  m.header = io_internal::read_header(r);
  m.angle_min_rad = r.f32("angle_min");
  m.angle_max_rad = r.f32("angle_max");
  m.angle_increment_rad = r.f32("angle_increment");
  m.time_increment_s = r.f32("time_increment");
  m.scan_time_s = r.f32("scan_time");
  m.range_min_m = r.f32("range_min");
  m.range_max_m = r.f32("range_max");
  return m;
}

template <typename Reader>
Result<LaserScanMessage> decode(Reader r) {
  LaserScanMessage m = read_scan_fields(r);
  m.ranges_m = r.f32_sequence("ranges");
  m.intensities = r.f32_sequence("intensities");
  if (!r.ok()) return io_internal::decode_error(r, kLaserScanType);
  return m;
}

/// A LaserEcho[]: per beam its first echo (`none` when it has no echo).
template <typename Reader>
std::vector<float> first_echoes(Reader& r, const char* what, float none) {
  std::vector<float> out;
  const std::uint32_t n = r.sequence_count(4, what);  // each LaserEcho holds at least its count
  out.reserve(n);
  for (std::uint32_t i = 0; i < n && r.ok(); ++i) {
    const std::vector<float> echoes = r.f32_sequence(what);
    out.push_back(echoes.empty() ? none : echoes.front());
  }
  return out;
}

template <typename Reader>
Result<LaserScanMessage> decode_multi_echo(Reader r) {
  LaserScanMessage m = read_scan_fields(r);
  m.ranges_m = first_echoes(r, "ranges", std::numeric_limits<float>::quiet_NaN());
  m.intensities = first_echoes(r, "intensities", 0.0F);
  if (!r.ok()) return io_internal::decode_error(r, kMultiEchoLaserScanType);
  return m;
}

}  // namespace

Result<LaserScanMessage> decode_laser_scan(std::span<const std::uint8_t> bytes,
                                           RosEncoding encoding) {
  if (encoding == RosEncoding::kRos1) return decode(io_internal::Ros1Reader(bytes));
  return decode(io_internal::CdrReader(bytes));
}

Result<LaserScanMessage> decode_multi_echo_laser_scan(std::span<const std::uint8_t> bytes,
                                                      RosEncoding encoding) {
  if (encoding == RosEncoding::kRos1) return decode_multi_echo(io_internal::Ros1Reader(bytes));
  return decode_multi_echo(io_internal::CdrReader(bytes));
}

bool is_laser_scan_type(std::string_view type) {
  return ros_type_is(type, kLaserScanType) || ros_type_is(type, kMultiEchoLaserScanType);
}

bool ros_type_is(std::string_view type, std::string_view ros1_name) {
  if (type == ros1_name) return true;
  // ROS 2 spells "pkg/msg/Name" for ROS 1's "pkg/Name".
  const std::size_t slash = ros1_name.find('/');
  if (slash == std::string_view::npos) return false;
  const std::string_view pkg = ros1_name.substr(0, slash);
  const std::string_view name = ros1_name.substr(slash + 1);
  return type.size() == pkg.size() + 5 + name.size() && type.substr(0, pkg.size()) == pkg &&
         type.substr(pkg.size(), 5) == "/msg/" && type.substr(pkg.size() + 5) == name;
}

}  // namespace tessera
