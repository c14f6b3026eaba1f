// CDR encoders and ros2msg definitions of the messages tessera writes (ros_message_encoders.hpp).
// Field order and types follow the ROS 2 Humble message definitions (common_interfaces,
// geometry2, rcl_interfaces' builtin_interfaces and rosgraph_msgs) and, for tessera_msgs, the
// definitions in the table below.
#include "tessera/io/ros_message_encoders.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "internal/cdr_writer.hpp"

namespace tessera {
namespace {

using io_internal::CdrWriter;

void header(CdrWriter& w, const RosHeader& h) {
  w.stamp(h.stamp_ns);
  w.string(h.frame_id);
}

void point(CdrWriter& w, const RosPoint& p) {
  w.f64(p.x_m);
  w.f64(p.y_m);
  w.f64(p.z_m);
}

// geometry_msgs/Pose and geometry_msgs/Transform have the same layout: 3 + 4 float64.
void pose(CdrWriter& w, const RosTransform& t) {
  for (const double d : {t.x_m, t.y_m, t.z_m, t.qx, t.qy, t.qz, t.qw}) w.f64(d);
}

void twist(CdrWriter& w, const RosTwist& t) {
  for (const double d : {t.linear_x_mps, t.linear_y_mps, t.linear_z_mps, t.angular_x_radps,
                         t.angular_y_radps, t.angular_z_radps}) {
    w.f64(d);
  }
}

void covariance(CdrWriter& w, const RosCovariance& c) {
  for (const double d : c) w.f64(d);
}

void transform_stamped(CdrWriter& w, const TransformStampedMessage& t) {
  header(w, t.header);
  w.string(t.child_frame_id);
  pose(w, t.transform);
}

void pose_stamped(CdrWriter& w, const PoseStampedMessage& p) {
  header(w, p.header);
  pose(w, p.pose);
}

void color(CdrWriter& w, const RosColor& c) {
  for (const float f : {c.r, c.g, c.b, c.a}) w.f32(f);
}

void f32_sequence(CdrWriter& w, const std::vector<float>& v) {
  w.count(v.size());
  for (const float f : v) w.f32(f);
}

// The definitions, one per type, fields only (no constants or comments), nested types by their
// full "pkg/Type" names as ros2msg's "MSG:" sections name them.
const std::map<std::string, std::string, std::less<>>& definitions() {
  static const std::map<std::string, std::string, std::less<>> kDefinitions = {
      {"builtin_interfaces/Time", "int32 sec\nuint32 nanosec\n"},
      {"builtin_interfaces/Duration", "int32 sec\nuint32 nanosec\n"},
      {"std_msgs/Header", "builtin_interfaces/Time stamp\nstring frame_id\n"},
      {"std_msgs/ColorRGBA", "float32 r\nfloat32 g\nfloat32 b\nfloat32 a\n"},
      {"geometry_msgs/Point", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Vector3", "float64 x\nfloat64 y\nfloat64 z\n"},
      {"geometry_msgs/Quaternion", "float64 x\nfloat64 y\nfloat64 z\nfloat64 w\n"},
      {"geometry_msgs/Pose",
       "geometry_msgs/Point position\ngeometry_msgs/Quaternion orientation\n"},
      {"geometry_msgs/PoseStamped", "std_msgs/Header header\ngeometry_msgs/Pose pose\n"},
      {"geometry_msgs/PoseWithCovariance", "geometry_msgs/Pose pose\nfloat64[36] covariance\n"},
      {"geometry_msgs/Twist", "geometry_msgs/Vector3 linear\ngeometry_msgs/Vector3 angular\n"},
      {"geometry_msgs/TwistWithCovariance", "geometry_msgs/Twist twist\nfloat64[36] covariance\n"},
      {"geometry_msgs/Transform",
       "geometry_msgs/Vector3 translation\ngeometry_msgs/Quaternion rotation\n"},
      {"geometry_msgs/TransformStamped",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/Transform transform\n"},
      {"sensor_msgs/LaserScan",
       "std_msgs/Header header\nfloat32 angle_min\nfloat32 angle_max\nfloat32 angle_increment\n"
       "float32 time_increment\nfloat32 scan_time\nfloat32 range_min\nfloat32 range_max\n"
       "float32[] ranges\nfloat32[] intensities\n"},
      {"sensor_msgs/CompressedImage", "std_msgs/Header header\nstring format\nuint8[] data\n"},
      {"nav_msgs/Odometry",
       "std_msgs/Header header\nstring child_frame_id\ngeometry_msgs/PoseWithCovariance pose\n"
       "geometry_msgs/TwistWithCovariance twist\n"},
      {"nav_msgs/MapMetaData",
       "builtin_interfaces/Time map_load_time\nfloat32 resolution\nuint32 width\nuint32 height\n"
       "geometry_msgs/Pose origin\n"},
      {"nav_msgs/OccupancyGrid",
       "std_msgs/Header header\nnav_msgs/MapMetaData info\nint8[] data\n"},
      {"nav_msgs/Path", "std_msgs/Header header\ngeometry_msgs/PoseStamped[] poses\n"},
      {"tf2_msgs/TFMessage", "geometry_msgs/TransformStamped[] transforms\n"},
      {"visualization_msgs/UVCoordinate", "float32 u\nfloat32 v\n"},
      {"visualization_msgs/MeshFile", "string filename\nuint8[] data\n"},
      {"visualization_msgs/Marker",
       "std_msgs/Header header\nstring ns\nint32 id\nint32 type\nint32 action\n"
       "geometry_msgs/Pose pose\ngeometry_msgs/Vector3 scale\nstd_msgs/ColorRGBA color\n"
       "builtin_interfaces/Duration lifetime\nbool frame_locked\ngeometry_msgs/Point[] points\n"
       "std_msgs/ColorRGBA[] colors\nstring texture_resource\n"
       "sensor_msgs/CompressedImage texture\nvisualization_msgs/UVCoordinate[] uv_coordinates\n"
       "string text\nstring mesh_resource\nvisualization_msgs/MeshFile mesh_file\n"
       "bool mesh_use_embedded_materials\n"},
      {"visualization_msgs/MarkerArray", "visualization_msgs/Marker[] markers\n"},
      {"rosgraph_msgs/Clock", "builtin_interfaces/Time clock\n"},
      {"geometry_msgs/PoseWithCovarianceStamped",
       "std_msgs/Header header\ngeometry_msgs/PoseWithCovariance pose\n"},
      // tessera's own: the meaning of each field is in ros_message_encoders.hpp.
      {"tessera_msgs/FrontierClaim",
       "std_msgs/Header header\nstring robot_id\nuint32 claim_id\ngeometry_msgs/Point target\n"
       "float32 radius_m\nfloat32 path_length_m\nbool active\n"},
      {"tessera_msgs/RobotStatus",
       "std_msgs/Header header\nstring robot_id\nuint8 state\nstring reason\n"
       "geometry_msgs/Pose pose\nfloat32 explored_area_m2\nuint64 messages_sent\n"
       "uint64 bytes_sent\nuint64 messages_dropped\n"},
      {"tessera_msgs/TeamCommand", "std_msgs/Header header\nstring robot_id\nuint8 command\n"},
  };
  return kDefinitions;
}

// The nested "pkg/Type" names a definition's fields use, in field order.
std::vector<std::string> nested_types(const std::string& definition) {
  std::vector<std::string> out;
  std::size_t at = 0;
  while (at < definition.size()) {
    const std::size_t end = definition.find('\n', at);
    const std::string line = definition.substr(at, end - at);
    at = end == std::string::npos ? definition.size() : end + 1;
    std::string type = line.substr(0, line.find(' '));
    type = type.substr(0, type.find('['));
    if (type.find('/') != std::string::npos) out.push_back(type);
  }
  return out;
}

}  // namespace

RosTransform planar_transform(double x_m, double y_m, double yaw_rad) {
  RosTransform t;
  t.x_m = x_m;
  t.y_m = y_m;
  t.qz = std::sin(0.5 * yaw_rad);
  t.qw = std::cos(0.5 * yaw_rad);
  return t;
}

std::string ros2msg_definition(std::string_view type) {
  // "pkg/msg/Type" -> "pkg/Type", the key of the table and of the MSG: sections.
  std::string key(type);
  if (const std::size_t m = key.find("/msg/"); m != std::string::npos) key.erase(m, 4);
  const auto& table = definitions();
  const auto root = table.find(key);
  if (root == table.end()) return {};
  std::string out = root->second;
  // Every type used, depth first in field order, each once.
  std::set<std::string> seen{key};
  std::vector<std::string> todo = nested_types(root->second);
  std::reverse(todo.begin(), todo.end());
  while (!todo.empty()) {
    const std::string t = todo.back();
    todo.pop_back();
    if (!seen.insert(t).second) continue;
    const std::string& definition = table.find(t)->second;
    out += std::string(80, '=') + "\nMSG: " + t + "\n" + definition;
    std::vector<std::string> nested = nested_types(definition);
    todo.insert(todo.end(), nested.rbegin(), nested.rend());
  }
  return out;
}

std::vector<std::uint8_t> encode_cdr(const LaserScanMessage& m) {
  CdrWriter w;
  header(w, m.header);
  for (const float f : {m.angle_min_rad, m.angle_max_rad, m.angle_increment_rad, m.time_increment_s,
                        m.scan_time_s, m.range_min_m, m.range_max_m}) {
    w.f32(f);
  }
  f32_sequence(w, m.ranges_m);
  f32_sequence(w, m.intensities);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const OdometryMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.string(m.child_frame_id);
  pose(w, m.pose);
  covariance(w, m.pose_covariance);
  twist(w, m.twist);
  covariance(w, m.twist_covariance);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const TfMessage& m) {
  CdrWriter w;
  w.count(m.transforms.size());
  for (const TransformStampedMessage& t : m.transforms) transform_stamped(w, t);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const TransformStampedMessage& m) {
  CdrWriter w;
  transform_stamped(w, m);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const OccupancyGridMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.stamp(m.map_load_time_ns);
  w.f32(m.resolution_m);
  w.u32(m.width);
  w.u32(m.height);
  pose(w, m.origin);
  w.count(m.data.size());
  w.i8s(m.data);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const PathMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.count(m.poses.size());
  for (const PoseStampedMessage& p : m.poses) pose_stamped(w, p);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const PoseStampedMessage& m) {
  CdrWriter w;
  pose_stamped(w, m);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const MarkerArrayMessage& m) {
  CdrWriter w;
  w.count(m.markers.size());
  for (const MarkerMessage& k : m.markers) {
    header(w, k.header);
    w.string(k.ns);
    w.i32(k.id);
    w.i32(k.type);
    w.i32(k.action);
    pose(w, k.pose);
    point(w, k.scale);
    color(w, k.color);
    w.stamp(k.lifetime_ns);
    w.boolean(k.frame_locked);
    w.count(k.points.size());
    for (const RosPoint& p : k.points) point(w, p);
    w.count(k.colors.size());
    for (const RosColor& c : k.colors) color(w, c);
    w.string("");            // texture_resource
    header(w, RosHeader{});  // texture: sensor_msgs/CompressedImage, empty
    w.string("");
    w.count(0);
    w.count(0);  // uv_coordinates
    w.string(k.text);
    w.string("");  // mesh_resource
    w.string("");  // mesh_file: filename, data
    w.count(0);
    w.boolean(false);  // mesh_use_embedded_materials
  }
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const ClockMessage& m) {
  CdrWriter w;
  w.stamp(m.clock_ns);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const TwistMessage& m) {
  CdrWriter w;
  twist(w, m);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const PoseWithCovarianceStampedMessage& m) {
  CdrWriter w;
  header(w, m.header);
  pose(w, m.pose);
  covariance(w, m.covariance);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const FrontierClaimMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.string(m.robot_id);
  w.u32(m.claim_id);
  point(w, m.target);
  w.f32(m.radius_m);
  w.f32(m.path_length_m);
  w.boolean(m.active);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const RobotStatusMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.string(m.robot_id);
  w.u8(m.state);
  w.string(m.reason);
  pose(w, m.pose);
  w.f32(m.explored_area_m2);
  w.u64(m.messages_sent);
  w.u64(m.bytes_sent);
  w.u64(m.messages_dropped);
  return std::move(w).take();
}

std::vector<std::uint8_t> encode_cdr(const TeamCommandMessage& m) {
  CdrWriter w;
  header(w, m.header);
  w.string(m.robot_id);
  w.u8(m.command);
  return std::move(w).take();
}

}  // namespace tessera
