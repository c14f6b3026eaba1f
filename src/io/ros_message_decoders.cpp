// CDR decoders of the messages ros_message_encoders.hpp declares beside their encoders: the same
// ROS 2 Humble layouts (and tessera_msgs' table there) read back with CdrReader, whose length
// checks refuse a message cut short or corrupted on a link before anything is allocated for it.
#include <cstdint>
#include <span>
#include <string_view>

#include "internal/cdr_reader.hpp"
#include "internal/ros_message_fields.hpp"
#include "tessera/io/ros_message_encoders.hpp"

namespace tessera {
namespace {

using io_internal::CdrReader;
using io_internal::read_covariance;
using io_internal::read_header;
using io_internal::read_transform;

/// The fewest bytes a sequence's element takes (strings and sequences empty, with a 0 length, no
/// padding), so that a corrupt count is refused before anything is allocated.
constexpr std::size_t kMinHeaderBytes = 8 + 4;  // stamp, frame_id's length
constexpr std::size_t kMinPoseStampedBytes = kMinHeaderBytes + 7 * 8;
/// visualization_msgs/Marker: header, ns, id, type, action, pose, scale, color, lifetime,
/// frame_locked, points, colors, texture_resource, texture (header, format, data),
/// uv_coordinates, text, mesh_resource, mesh_file (filename, data), mesh_use_embedded_materials.
constexpr std::size_t kMinMarkerBytes = kMinHeaderBytes + 4 + 3 * 4 + 7 * 8 + 3 * 8 + 4 * 4 + 8 +
                                        1 + 4 + 4 + 4 + (kMinHeaderBytes + 4 + 4) + 4 + 4 + 4 +
                                        (4 + 4) + 1;

/// geometry_msgs/Point or Vector3 in metres.
RosPoint read_point(CdrReader& r, const char* what) {
  RosPoint p;
  p.x_m = r.f64(what);
  p.y_m = r.f64(what);
  p.z_m = r.f64(what);
  return p;
}

RosColor read_color(CdrReader& r, const char* what) {
  RosColor c;
  c.r = r.f32(what);
  c.g = r.f32(what);
  c.b = r.f32(what);
  c.a = r.f32(what);
  return c;
}

PoseStampedMessage read_pose_stamped(CdrReader& r) {
  PoseStampedMessage p;
  p.header = read_header(r);
  p.pose = read_transform(r);
  return p;
}

/// visualization_msgs/Marker: every field of Humble's definition is read, the texture, UV
/// coordinates and mesh only to step over them.
MarkerMessage read_marker(CdrReader& r) {
  MarkerMessage k;
  k.header = read_header(r);
  k.ns = r.string("ns");
  k.id = r.i32("id");
  k.type = r.i32("type");
  k.action = r.i32("action");
  k.pose = read_transform(r);
  k.scale = read_point(r, "scale");
  k.color = read_color(r, "color");
  k.lifetime_ns = r.stamp_ns("lifetime");
  k.frame_locked = r.boolean("frame_locked");
  const std::uint32_t points = r.sequence_count(3 * 8, "points");
  k.points.reserve(points);
  for (std::uint32_t i = 0; i < points && r.ok(); ++i) k.points.push_back(read_point(r, "points"));
  const std::uint32_t colors = r.sequence_count(4 * 4, "colors");
  k.colors.reserve(colors);
  for (std::uint32_t i = 0; i < colors && r.ok(); ++i) k.colors.push_back(read_color(r, "colors"));
  r.string("texture_resource");
  read_header(r);  // texture: sensor_msgs/CompressedImage
  r.string("texture.format");
  r.u8_sequence("texture.data");
  const std::uint32_t uvs = r.sequence_count(2 * 4, "uv_coordinates");
  for (std::uint32_t i = 0; i < uvs && r.ok(); ++i) {
    r.f32("uv_coordinates.u");
    r.f32("uv_coordinates.v");
  }
  k.text = r.string("text");
  r.string("mesh_resource");
  r.string("mesh_file.filename");
  r.u8_sequence("mesh_file.data");
  r.boolean("mesh_use_embedded_materials");
  return k;
}

/// Reads one message with `read` (which may go on after a failure: reads then return zeros) and
/// returns it, or the reader's first failure.
template <typename Message, typename Read>
Result<Message> decode(std::span<const std::uint8_t> bytes, std::string_view type, Read read) {
  CdrReader r(bytes);
  Message m = read(r);
  if (!r.ok()) return io_internal::decode_error(r, type);
  return m;
}

}  // namespace

Result<TransformStampedMessage> decode_cdr_transform_stamped(std::span<const std::uint8_t> bytes) {
  return decode<TransformStampedMessage>(bytes, kRos2TransformStamped, [](CdrReader& r) {
    return io_internal::read_transform_stamped(r);
  });
}

Result<OccupancyGridMessage> decode_cdr_occupancy_grid(std::span<const std::uint8_t> bytes) {
  return decode<OccupancyGridMessage>(bytes, kRos2OccupancyGrid, [](CdrReader& r) {
    OccupancyGridMessage m;
    m.header = read_header(r);
    m.map_load_time_ns = r.stamp_ns("info.map_load_time");
    m.resolution_m = r.f32("info.resolution");
    m.width = r.u32("info.width");
    m.height = r.u32("info.height");
    m.origin = read_transform(r);
    m.data = r.i8_sequence("data");
    return m;
  });
}

Result<PathMessage> decode_cdr_path(std::span<const std::uint8_t> bytes) {
  return decode<PathMessage>(bytes, kRos2Path, [](CdrReader& r) {
    PathMessage m;
    m.header = read_header(r);
    const std::uint32_t n = r.sequence_count(kMinPoseStampedBytes, "poses");
    m.poses.reserve(n);
    for (std::uint32_t i = 0; i < n && r.ok(); ++i) m.poses.push_back(read_pose_stamped(r));
    return m;
  });
}

Result<PoseStampedMessage> decode_cdr_pose_stamped(std::span<const std::uint8_t> bytes) {
  return decode<PoseStampedMessage>(bytes, kRos2PoseStamped,
                                    [](CdrReader& r) { return read_pose_stamped(r); });
}

Result<MarkerArrayMessage> decode_cdr_marker_array(std::span<const std::uint8_t> bytes) {
  return decode<MarkerArrayMessage>(bytes, kRos2MarkerArray, [](CdrReader& r) {
    MarkerArrayMessage m;
    const std::uint32_t n = r.sequence_count(kMinMarkerBytes, "markers");
    m.markers.reserve(n);
    for (std::uint32_t i = 0; i < n && r.ok(); ++i) m.markers.push_back(read_marker(r));
    return m;
  });
}

Result<ClockMessage> decode_cdr_clock(std::span<const std::uint8_t> bytes) {
  return decode<ClockMessage>(bytes, kRos2Clock,
                              [](CdrReader& r) { return ClockMessage{r.stamp_ns("clock")}; });
}

Result<TwistMessage> decode_cdr_twist(std::span<const std::uint8_t> bytes) {
  return decode<TwistMessage>(bytes, kRos2Twist,
                              [](CdrReader& r) { return io_internal::read_twist(r); });
}

Result<PoseWithCovarianceStampedMessage> decode_cdr_pose_with_covariance_stamped(
    std::span<const std::uint8_t> bytes) {
  return decode<PoseWithCovarianceStampedMessage>(
      bytes, kRos2PoseWithCovarianceStamped, [](CdrReader& r) {
        PoseWithCovarianceStampedMessage m;
        m.header = read_header(r);
        m.pose = read_transform(r);
        m.covariance = read_covariance(r, "pose.covariance");
        return m;
      });
}

Result<FrontierClaimMessage> decode_cdr_frontier_claim(std::span<const std::uint8_t> bytes) {
  return decode<FrontierClaimMessage>(bytes, kRos2FrontierClaim, [](CdrReader& r) {
    FrontierClaimMessage m;
    m.header = read_header(r);
    m.robot_id = r.string("robot_id");
    m.claim_id = r.u32("claim_id");
    m.target = read_point(r, "target");
    m.radius_m = r.f32("radius_m");
    m.path_length_m = r.f32("path_length_m");
    m.active = r.boolean("active");
    return m;
  });
}

Result<RobotStatusMessage> decode_cdr_robot_status(std::span<const std::uint8_t> bytes) {
  return decode<RobotStatusMessage>(bytes, kRos2RobotStatus, [](CdrReader& r) {
    RobotStatusMessage m;
    m.header = read_header(r);
    m.robot_id = r.string("robot_id");
    m.state = r.u8("state");
    m.reason = r.string("reason");
    m.pose = read_transform(r);
    m.explored_area_m2 = r.f32("explored_area_m2");
    m.messages_sent = r.u64("messages_sent");
    m.bytes_sent = r.u64("bytes_sent");
    m.messages_dropped = r.u64("messages_dropped");
    return m;
  });
}

Result<TeamCommandMessage> decode_cdr_team_command(std::span<const std::uint8_t> bytes) {
  return decode<TeamCommandMessage>(bytes, kRos2TeamCommand, [](CdrReader& r) {
    TeamCommandMessage m;
    m.header = read_header(r);
    m.robot_id = r.string("robot_id");
    m.command = r.u8("command");
    return m;
  });
}

}  // namespace tessera
