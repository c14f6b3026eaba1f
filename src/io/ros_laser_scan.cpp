// sensor_msgs/LaserScan in ROS 1 serialization and CDR (the .msg definition: Header, seven
// float32 fields, float32[] ranges, float32[] intensities).
#include "internal/cdr_reader.hpp"
#include "internal/ros1_reader.hpp"
#include "internal/ros_message_fields.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera {
namespace {

template <typename Reader>
Result<LaserScanMessage> decode(Reader r) {
  LaserScanMessage m;
  m.header = io_internal::read_header(r);
  m.angle_min_rad = r.f32("angle_min");
  m.angle_max_rad = r.f32("angle_max");
  m.angle_increment_rad = r.f32("angle_increment");
  m.time_increment_s = r.f32("time_increment");
  m.scan_time_s = r.f32("scan_time");
  m.range_min_m = r.f32("range_min");
  m.range_max_m = r.f32("range_max");
  m.ranges_m = r.f32_sequence("ranges");
  m.intensities = r.f32_sequence("intensities");
  if (!r.ok()) return io_internal::decode_error(r, kLaserScanType);
  return m;
}

}  // namespace

Result<LaserScanMessage> decode_laser_scan(std::span<const std::uint8_t> bytes,
                                           RosEncoding encoding) {
  if (encoding == RosEncoding::kRos1) return decode(io_internal::Ros1Reader(bytes));
  return decode(io_internal::CdrReader(bytes));
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
