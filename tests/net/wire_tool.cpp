// Issue 14's wire compatibility check against an implementation we did not write (npm's
// @foxglove/rosmsg2-serialization, driven by wire_compat_test.sh and wire_check.cjs). For each of
// the 14 message types tessera sends, one sample message in which every field has a distinctive
// value:
//   wire_tool capture OUT_DIR: publishes each sample with one DDS participant and receives it with
//     a second; writes the bytes received (the wire bytes) to OUT_DIR/<pkg>__<Type>.cdr, the ROS 2
//     definition to <pkg>__<Type>.msg and the message as @foxglove/rosmsg2-serialization decodes
//     it (ROS 2 field names, header.stamp {sec, nanosec}, float32 as the double of the float) to
//     <pkg>__<Type>.json.
//   wire_tool check IN_DIR: decodes each <pkg>__<Type>.foxglove.cdr (what foxglove's MessageWriter
//     made of the .json) with tessera's decoder and compares it field for field with the sample
//     (naming the first field that differs); requires the bytes to be the ones tessera's encoder
//     writes for the sample; then sends them through DDS (publishing validates them against the
//     IDL type) and compares what a second participant receives. Prints "ok <type>" per type and
//     "FAIL <type>: <what>" per mismatch; every one of the 14 files must be there.
// capture exits 1 with one line on the first problem (a message not received within 10 s); check
// exits 1 after reporting every mismatch; both exit 2 on a usage error.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "support/dds_isolation.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/dds_transport.hpp"

namespace tessera {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
using Json = nlohmann::ordered_json;  // keeps the fields in definition order in the .json files

// ---- The messages as @foxglove/rosmsg2-serialization decodes them -------------------------------

// builtin_interfaces/Time and Duration as CdrWriter::stamp writes them: floor division, so that
// nanosec stays in [0, 1e9).
Json time_json(std::int64_t ns) {
  std::int64_t sec = ns / 1'000'000'000;
  std::int64_t nanosec = ns % 1'000'000'000;
  if (nanosec < 0) {
    nanosec += 1'000'000'000;
    --sec;
  }
  return {{"sec", static_cast<std::int32_t>(sec)},
          {"nanosec", static_cast<std::uint32_t>(nanosec)}};
}

// float32 fields: the exact double of the float, as foxglove's reader returns them.
double f32(float v) { return static_cast<double>(v); }

Json to_json(const RosHeader& h) {
  return {{"stamp", time_json(h.stamp_ns)}, {"frame_id", h.frame_id}};
}

Json xyz(double x, double y, double z) { return {{"x", x}, {"y", y}, {"z", z}}; }

Json to_json(const RosPoint& p) { return xyz(p.x_m, p.y_m, p.z_m); }

Json quaternion(const RosTransform& t) {
  return {{"x", t.qx}, {"y", t.qy}, {"z", t.qz}, {"w", t.qw}};
}

// geometry_msgs/Pose.
Json pose_json(const RosTransform& t) {
  return {{"position", xyz(t.x_m, t.y_m, t.z_m)}, {"orientation", quaternion(t)}};
}

// geometry_msgs/Transform.
Json transform_json(const RosTransform& t) {
  return {{"translation", xyz(t.x_m, t.y_m, t.z_m)}, {"rotation", quaternion(t)}};
}

Json to_json(const RosTwist& t) {
  return {{"linear", xyz(t.linear_x_mps, t.linear_y_mps, t.linear_z_mps)},
          {"angular", xyz(t.angular_x_radps, t.angular_y_radps, t.angular_z_radps)}};
}

Json to_json(const RosCovariance& c) { return Json(std::vector<double>(c.begin(), c.end())); }

Json to_json(const RosColor& c) {
  return {{"r", f32(c.r)}, {"g", f32(c.g)}, {"b", f32(c.b)}, {"a", f32(c.a)}};
}

Json f32_array(const std::vector<float>& v) {
  Json out = Json::array();
  for (const float f : v) out.push_back(f32(f));
  return out;
}

Json to_json(const LaserScanMessage& m) {
  return {{"header", to_json(m.header)},
          {"angle_min", f32(m.angle_min_rad)},
          {"angle_max", f32(m.angle_max_rad)},
          {"angle_increment", f32(m.angle_increment_rad)},
          {"time_increment", f32(m.time_increment_s)},
          {"scan_time", f32(m.scan_time_s)},
          {"range_min", f32(m.range_min_m)},
          {"range_max", f32(m.range_max_m)},
          {"ranges", f32_array(m.ranges_m)},
          {"intensities", f32_array(m.intensities)}};
}

Json to_json(const OdometryMessage& m) {
  return {{"header", to_json(m.header)},
          {"child_frame_id", m.child_frame_id},
          {"pose", {{"pose", pose_json(m.pose)}, {"covariance", to_json(m.pose_covariance)}}},
          {"twist", {{"twist", to_json(m.twist)}, {"covariance", to_json(m.twist_covariance)}}}};
}

Json to_json(const TransformStampedMessage& m) {
  return {{"header", to_json(m.header)},
          {"child_frame_id", m.child_frame_id},
          {"transform", transform_json(m.transform)}};
}

Json to_json(const TfMessage& m) {
  Json transforms = Json::array();
  for (const TransformStampedMessage& t : m.transforms) transforms.push_back(to_json(t));
  return {{"transforms", transforms}};
}

Json to_json(const OccupancyGridMessage& m) {
  return {{"header", to_json(m.header)},
          {"info",
           {{"map_load_time", time_json(m.map_load_time_ns)},
            {"resolution", f32(m.resolution_m)},
            {"width", m.width},
            {"height", m.height},
            {"origin", pose_json(m.origin)}}},
          {"data", m.data}};
}

Json to_json(const PoseStampedMessage& m) {
  return {{"header", to_json(m.header)}, {"pose", pose_json(m.pose)}};
}

Json to_json(const PathMessage& m) {
  Json poses = Json::array();
  for (const PoseStampedMessage& p : m.poses) poses.push_back(to_json(p));
  return {{"header", to_json(m.header)}, {"poses", poses}};
}

// visualization_msgs/Marker with every field of the definition: tessera writes the texture, UV
// coordinates and mesh empty.
Json to_json(const MarkerMessage& k) {
  Json points = Json::array();
  for (const RosPoint& p : k.points) points.push_back(to_json(p));
  Json colors = Json::array();
  for (const RosColor& c : k.colors) colors.push_back(to_json(c));
  return {{"header", to_json(k.header)},
          {"ns", k.ns},
          {"id", k.id},
          {"type", k.type},
          {"action", k.action},
          {"pose", pose_json(k.pose)},
          {"scale", to_json(k.scale)},
          {"color", to_json(k.color)},
          {"lifetime", time_json(k.lifetime_ns)},
          {"frame_locked", k.frame_locked},
          {"points", points},
          {"colors", colors},
          {"texture_resource", ""},
          {"texture", {{"header", to_json(RosHeader{})}, {"format", ""}, {"data", Json::array()}}},
          {"uv_coordinates", Json::array()},
          {"text", k.text},
          {"mesh_resource", ""},
          {"mesh_file", {{"filename", ""}, {"data", Json::array()}}},
          {"mesh_use_embedded_materials", false}};
}

Json to_json(const MarkerArrayMessage& m) {
  Json markers = Json::array();
  for (const MarkerMessage& k : m.markers) markers.push_back(to_json(k));
  return {{"markers", markers}};
}

Json to_json(const ClockMessage& m) { return {{"clock", time_json(m.clock_ns)}}; }

Json to_json(const PoseWithCovarianceStampedMessage& m) {
  return {{"header", to_json(m.header)},
          {"pose", {{"pose", pose_json(m.pose)}, {"covariance", to_json(m.covariance)}}}};
}

Json to_json(const FrontierClaimMessage& m) {
  return {{"header", to_json(m.header)}, {"robot_id", m.robot_id},
          {"claim_id", m.claim_id},      {"target", to_json(m.target)},
          {"radius_m", f32(m.radius_m)}, {"path_length_m", f32(m.path_length_m)},
          {"active", m.active}};
}

// The uint64 counters are written as JSON integers (wire_check.cjs turns them into the BigInts
// foxglove reads); the samples keep them below 2^53 so that JavaScript parses them exactly.
Json to_json(const RobotStatusMessage& m) {
  return {{"header", to_json(m.header)},
          {"robot_id", m.robot_id},
          {"state", m.state},
          {"reason", m.reason},
          {"pose", pose_json(m.pose)},
          {"explored_area_m2", f32(m.explored_area_m2)},
          {"messages_sent", m.messages_sent},
          {"bytes_sent", m.bytes_sent},
          {"messages_dropped", m.messages_dropped}};
}

Json to_json(const TeamCommandMessage& m) {
  return {{"header", to_json(m.header)}, {"robot_id", m.robot_id}, {"command", m.command}};
}

// ---- The samples: every field set, none to its default ------------------------------------------

RosHeader header(std::int64_t stamp_ns, std::string frame_id) {
  return {stamp_ns, std::move(frame_id)};
}

// A pose with every component distinct and non-zero, so that two fields swapped show: the
// quaternion's x, y, z as given (|q_xyz| < 1) and w making it a unit quaternion.
RosTransform transform(double x_m, double y_m, double z_m, double qx, double qy, double qz) {
  return {x_m, y_m, z_m, qx, qy, qz, std::sqrt(1.0 - qx * qx - qy * qy - qz * qz)};
}

LaserScanMessage laser_scan() {
  LaserScanMessage m;
  m.header = header(1'712'345'678'987'654'321, "r1/laser_front");
  m.angle_min_rad = -1.25F;
  m.angle_max_rad = 1.0F;
  m.angle_increment_rad = 0.75F;
  m.time_increment_s = 1.5e-5F;
  m.scan_time_s = 0.1F;
  m.range_min_m = 0.12F;
  m.range_max_m = 25.5F;
  m.ranges_m = {0.5F, 1.75F, 25.5F, 3.1415927F};
  m.intensities = {100.0F, 0.25F, -3.5F, 47.0F};
  return m;
}

RosCovariance covariance(double scale) {
  RosCovariance c{};
  for (std::size_t i = 0; i < c.size(); ++i) {
    c[i] = scale * static_cast<double>(i + 1) * (i % 3 == 1 ? -1.0 : 1.0);
  }
  return c;
}

OdometryMessage odometry() {
  OdometryMessage m;
  m.header = header(1'712'345'679'000'000'123, "r1/odom");
  m.child_frame_id = "r1/base_link";
  m.pose = transform(-3.25, 12.5, 0.125, 0.18, -0.36, 0.48);
  m.pose_covariance = covariance(0.001);
  m.twist = {0.75, -0.125, 0.0625, -0.01, 0.02, -1.5};
  m.twist_covariance = covariance(-0.0025);
  return m;
}

TransformStampedMessage transform_stamped() {
  TransformStampedMessage m;
  m.header = header(1'712'345'680'500'000'001, "map");
  m.child_frame_id = "r2/odom";
  m.transform = transform(7.5, -2.25, 0.0625, -0.02, 0.03, -0.38);
  return m;
}

TfMessage tf_message() {
  TfMessage m;
  m.transforms.push_back(transform_stamped());
  TransformStampedMessage second;
  second.header = header(1'712'345'680'499'999'999, "r2/odom");
  second.child_frame_id = "r2/base_link";
  second.transform = transform(-0.5, 1.25, -0.03125, 0.1, -0.2, 0.3);
  m.transforms.push_back(second);
  return m;
}

OccupancyGridMessage occupancy_grid() {
  OccupancyGridMessage m;
  m.header = header(1'712'345'681'250'000'000, "map");
  m.map_load_time_ns = 1'712'345'000'000'000'777;
  m.resolution_m = 0.05F;
  m.width = 3;
  m.height = 2;
  m.origin = transform(-10.25, -5.5, 0.25, 0.01, -0.015, 0.2588);
  m.data = {-1, 0, 100, 50, -1, 100};
  return m;
}

PoseStampedMessage pose_stamped() {
  PoseStampedMessage m;
  m.header = header(1'712'345'682'000'000'456, "map");
  m.pose = transform(3.5, -4.75, 0.5, -0.04, 0.05, 0.7);
  return m;
}

PathMessage path() {
  PathMessage m;
  m.header = header(1'712'345'683'000'000'789, "map");
  m.poses.push_back(pose_stamped());
  PoseStampedMessage second;
  second.header = header(1'712'345'683'100'000'000, "map_alt");
  second.pose = transform(-1.0, 2.0, -3.0, 0.5, 0.4, -0.3);
  m.poses.push_back(second);
  return m;
}

MarkerArrayMessage marker_array() {
  MarkerArrayMessage m;
  MarkerMessage spheres;
  spheres.header = header(1'712'345'684'000'000'012, "map");
  spheres.ns = "frontiers";
  spheres.id = 7;
  spheres.type = MarkerMessage::kSphereList;
  spheres.action = MarkerMessage::kAdd;
  spheres.pose = transform(0.5, -0.25, 0.125, 0.06, -0.07, 0.08);
  spheres.scale = {0.2, 0.3, 0.4};
  spheres.color = {0.1F, 0.8F, 0.25F, 0.5F};
  spheres.lifetime_ns = 2'500'000'001;
  spheres.frame_locked = true;
  spheres.text = "3 frontiers";
  spheres.points = {{1.0, -2.0, 0.75}, {-3.5, 4.25, 0.5}, {6.0, 7.0, -8.0}};
  spheres.colors = {
      {0.9F, 0.05F, 0.15F, 1.0F}, {0.3F, 0.5F, 0.7F, 0.75F}, {0.2F, 0.4F, 0.6F, 0.8F}};
  m.markers.push_back(spheres);
  MarkerMessage text;
  text.header = header(1'712'345'684'000'000'013, "r2/base_link");
  text.ns = "goals";
  text.id = -3;
  text.type = MarkerMessage::kText;
  text.action = MarkerMessage::kDeleteAll;
  text.pose = transform(-1.5, 0.625, 2.0, -0.09, 0.11, 0.6);
  text.scale = {0.05, 0.06, 0.35};
  text.color = {0.95F, 0.85F, 0.1F, 0.65F};
  text.lifetime_ns = 30'000'000'000;
  text.frame_locked = false;
  text.points = {{-0.5, 0.5, 1.5}};
  text.text = "goal of r2: (3.5, -4.75)";
  m.markers.push_back(text);
  return m;
}

ClockMessage clock_message() { return {1'712'345'685'000'000'042}; }

TwistMessage twist() { return {0.35, -0.05, 0.01, 0.02, -0.03, -0.8}; }

PoseWithCovarianceStampedMessage pose_with_covariance_stamped() {
  PoseWithCovarianceStampedMessage m;
  m.header = header(1'712'345'686'123'000'000, "map");
  m.pose = transform(2.5, 3.5, -0.25, 0.12, -0.13, -0.2588);
  m.covariance = covariance(0.015);
  return m;
}

FrontierClaimMessage frontier_claim() {
  FrontierClaimMessage m;
  m.header = header(1'712'345'687'000'000'999, "team_map");
  m.robot_id = "r2";
  m.claim_id = 4'000'000'007;  // above 2^31
  m.target = {4.5, -7.25, 0.5};
  m.radius_m = 1.25F;
  m.path_length_m = 17.375F;
  m.active = true;
  return m;
}

RobotStatusMessage robot_status() {
  RobotStatusMessage m;
  m.header = header(1'712'345'688'000'000'321, "team_map");
  m.robot_id = "r3";
  m.state = RobotStatusMessage::kReturningHome;
  m.reason = "battery at 18 %, going home";
  m.pose = transform(-6.5, 8.25, 0.375, -0.14, 0.16, 0.9);
  m.explored_area_m2 = 123.456F;
  m.messages_sent = 5'000'000'123;     // above 2^32
  m.bytes_sent = 987'654'321'098'765;  // above 2^32, below 2^53
  m.messages_dropped = 4'294'967'301;  // 2^32 + 5
  return m;
}

TeamCommandMessage team_command() {
  TeamCommandMessage m;
  m.header = header(1'712'345'689'000'000'654, "team_map");
  m.robot_id = "r1";
  m.command = TeamCommandMessage::kReturnHome;
  return m;
}

// ---- The table ----------------------------------------------------------------------------------

struct Decoded {
  Json json;
  Bytes cdr;  // encode_cdr of the decoded message
};

struct WireType {
  std::string_view ros_type;  // "sensor_msgs/msg/LaserScan"
  Bytes cdr;                  // encode_cdr(sample)
  Json expected;              // the sample as foxglove decodes it
  std::function<Result<Decoded>(std::span<const std::uint8_t>)> decode;  // tessera's decoder
};

template <typename Message, typename Decode>
WireType wire_type(std::string_view ros_type, const Message& sample, Decode decode) {
  return {ros_type, encode_cdr(sample), to_json(sample),
          [decode](std::span<const std::uint8_t> bytes) -> Result<Decoded> {
            Result<Message> m = decode(bytes);
            if (!m.ok()) return m.error();
            return Decoded{to_json(*m), encode_cdr(*m)};
          }};
}

std::vector<WireType> wire_types() {
  const auto cdr = [](auto decoder) {
    return [decoder](std::span<const std::uint8_t> b) { return decoder(b, RosEncoding::kCdr); };
  };
  std::vector<WireType> out;
  out.push_back(wire_type(kRos2LaserScan, laser_scan(), cdr(decode_laser_scan)));
  out.push_back(wire_type(kRos2Odometry, odometry(), cdr(decode_odometry)));
  out.push_back(wire_type(kRos2TfMessage, tf_message(), cdr(decode_tf_message)));
  out.push_back(
      wire_type(kRos2TransformStamped, transform_stamped(), decode_cdr_transform_stamped));
  out.push_back(wire_type(kRos2OccupancyGrid, occupancy_grid(), decode_cdr_occupancy_grid));
  out.push_back(wire_type(kRos2Path, path(), decode_cdr_path));
  out.push_back(wire_type(kRos2PoseStamped, pose_stamped(), decode_cdr_pose_stamped));
  out.push_back(wire_type(kRos2MarkerArray, marker_array(), decode_cdr_marker_array));
  out.push_back(wire_type(kRos2Clock, clock_message(), decode_cdr_clock));
  out.push_back(wire_type(kRos2Twist, twist(), decode_cdr_twist));
  out.push_back(wire_type(kRos2PoseWithCovarianceStamped, pose_with_covariance_stamped(),
                          decode_cdr_pose_with_covariance_stamped));
  out.push_back(wire_type(kRos2FrontierClaim, frontier_claim(), decode_cdr_frontier_claim));
  out.push_back(wire_type(kRos2RobotStatus, robot_status(), decode_cdr_robot_status));
  out.push_back(wire_type(kRos2TeamCommand, team_command(), decode_cdr_team_command));
  return out;
}

// "sensor_msgs/msg/LaserScan" -> "sensor_msgs__LaserScan", the files' stem.
std::string file_stem(std::string_view ros_type) {
  const std::size_t slash = ros_type.find('/');
  return std::string(ros_type.substr(0, slash)) + "__" +
         std::string(ros_type.substr(ros_type.rfind('/') + 1));
}

// ---- Comparison ---------------------------------------------------------------------------------

// Where `actual` first differs from `expected`, as "markers[1].points[0].x: expected 6, got 7";
// empty when they are equal.
std::string first_difference(const Json& expected, const Json& actual, const std::string& path) {
  const std::string at = path.empty() ? "(message)" : path;
  if (expected.type() != actual.type() && !(expected.is_number() && actual.is_number())) {
    return at + ": expected " + expected.dump() + ", got " + actual.dump();
  }
  if (expected.is_object()) {
    for (const auto& [key, value] : expected.items()) {
      const std::string field = path.empty() ? key : path + "." + key;
      if (!actual.contains(key)) return field + ": missing";
      std::string d = first_difference(value, actual.at(key), field);
      if (!d.empty()) return d;
    }
    for (const auto& item : actual.items()) {
      const std::string& key = item.key();
      if (!expected.contains(key)) return (path.empty() ? key : path + "." + key) + ": unexpected";
    }
    return {};
  }
  if (expected.is_array()) {
    if (expected.size() != actual.size()) {
      return at + ": " + std::to_string(actual.size()) + " elements, expected " +
             std::to_string(expected.size());
    }
    for (std::size_t i = 0; i < expected.size(); ++i) {
      std::string d =
          first_difference(expected[i], actual[i], path + "[" + std::to_string(i) + "]");
      if (!d.empty()) return d;
    }
    return {};
  }
  if (expected != actual) return at + ": expected " + expected.dump() + ", got " + actual.dump();
  return {};
}

// The first byte where `a` and `b` differ, or their common length when one is a prefix.
std::size_t first_different_byte(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
  std::size_t i = 0;
  while (i < a.size() && i < b.size() && a[i] == b[i]) ++i;
  return i;
}

// Decodes `bytes` with tessera's decoder and compares with the sample; empty when they agree.
std::string check_decoded(const WireType& type, std::span<const std::uint8_t> bytes) {
  const Result<Decoded> decoded = type.decode(bytes);
  if (!decoded.ok()) return "tessera cannot decode it: " + decoded.error().message;
  std::string d = first_difference(type.expected, decoded->json, "");
  if (!d.empty()) return d;
  if (decoded->cdr != type.cdr) {
    return "re-encoded, it differs from the sample's encoding at byte " +
           std::to_string(first_different_byte(decoded->cdr, type.cdr));
  }
  return {};
}

// ---- DDS and files ------------------------------------------------------------------------------

Result<std::unique_ptr<net::Transport>> participant() {
  return net::make_dds_transport({.domain_id = support::test_dds_domain()});
}

// Publishes `cdr` from `from` on `spec` until `to` receives it (a DDS writer and reader match a
// few milliseconds after both exist; what is sent before that is lost); the bytes received. A
// runtime error after 10 s; publish's own error (bytes that do not fit the type) at once.
Result<Bytes> send_over_dds(net::Transport& from, net::Transport& to, const net::TopicSpec& spec,
                            std::span<const std::uint8_t> cdr) {
  // Shared with the handler, which stays subscribed after this returns.
  auto received = std::make_shared<std::optional<Bytes>>();
  const auto reader = to.subscribe(spec, [received](std::span<const std::uint8_t> bytes) {
    if (!received->has_value()) *received = Bytes(bytes.begin(), bytes.end());
  });
  if (!reader.ok()) return reader.error();
  const auto writer = from.advertise(spec);
  if (!writer.ok()) return writer.error();
  const double timeout_s = 10.0;
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < end) {
    const Status sent = from.publish(*writer, cdr);
    if (!sent.ok()) return sent.error();
    to.wait(0.05);
    to.poll();
    if (received->has_value()) return std::move(**received);
  }
  return runtime_error("not received on " + spec.name + " within 10 s");
}

net::TopicSpec topic_for(const WireType& type, std::string_view mode, std::size_t index) {
  return {support::test_topic_prefix() + "/wire_" + std::string(mode) + std::to_string(index),
          std::string(type.ros_type), net::Qos::reliable(10)};
}

bool write_file(const fs::path& path, std::span<const char> bytes) {
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  return static_cast<bool>(out);
}

bool write_file(const fs::path& path, const std::string& text) {
  return write_file(path, std::span<const char>(text.data(), text.size()));
}

bool write_file(const fs::path& path, const Bytes& bytes) {
  return write_file(
      path, std::span<const char>(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
}

std::optional<Bytes> read_file(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return std::nullopt;
  return Bytes(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

int fail(const std::string& message) {
  std::fprintf(stderr, "wire_tool: %s\n", message.c_str());
  return 1;
}

// ---- The modes ----------------------------------------------------------------------------------

int capture(const fs::path& out_dir) {
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  auto a = participant();
  if (!a.ok()) return fail("DDS: " + a.error().message);
  auto b = participant();
  if (!b.ok()) return fail("DDS: " + b.error().message);
  const std::vector<WireType> types = wire_types();
  for (std::size_t i = 0; i < types.size(); ++i) {
    const WireType& type = types[i];
    const Result<Bytes> wire = send_over_dds(**a, **b, topic_for(type, "capture", i), type.cdr);
    if (!wire.ok()) return fail(std::string(type.ros_type) + ": " + wire.error().message);
    const std::string definition = ros2msg_definition(type.ros_type);
    if (definition.empty()) return fail(std::string(type.ros_type) + ": no ros2msg definition");
    const fs::path stem = out_dir / file_stem(type.ros_type);
    if (!write_file(fs::path(stem).concat(".cdr"), *wire) ||
        !write_file(fs::path(stem).concat(".msg"), definition) ||
        !write_file(fs::path(stem).concat(".json"), type.expected.dump(2) + "\n")) {
      return fail("cannot write " + stem.string() + ".*");
    }
    std::printf("captured %s: %zu bytes from DDS\n", std::string(type.ros_type).c_str(),
                wire->size());
  }
  return 0;
}

int check(const fs::path& in_dir) {
  auto a = participant();
  if (!a.ok()) return fail("DDS: " + a.error().message);
  auto b = participant();
  if (!b.ok()) return fail("DDS: " + b.error().message);
  const std::vector<WireType> types = wire_types();
  std::set<std::string> known;
  int failures = 0;
  const auto report = [&](const WireType& type, const std::string& problem) {
    std::printf("FAIL %s: %s\n", std::string(type.ros_type).c_str(), problem.c_str());
    ++failures;
  };
  for (std::size_t i = 0; i < types.size(); ++i) {
    const WireType& type = types[i];
    const std::string name = file_stem(type.ros_type) + ".foxglove.cdr";
    known.insert(name);
    const std::optional<Bytes> foxglove = read_file(in_dir / name);
    if (!foxglove) {
      report(type, "no " + (in_dir / name).string());
      continue;
    }
    if (std::string d = check_decoded(type, *foxglove); !d.empty()) {
      report(type, "foxglove's bytes: " + d);
      continue;
    }
    if (*foxglove != type.cdr) {
      report(type, "foxglove's bytes differ from tessera's encoding at byte " +
                       std::to_string(first_different_byte(*foxglove, type.cdr)) +
                       " (tessera decodes them right: its encoder writes another layout)");
      continue;
    }
    const Result<Bytes> wire = send_over_dds(**a, **b, topic_for(type, "check", i), *foxglove);
    if (!wire.ok()) {
      report(type, "foxglove's bytes over DDS: " + wire.error().message);
      continue;
    }
    if (std::string d = check_decoded(type, *wire); !d.empty()) {
      report(type, "foxglove's bytes received from DDS: " + d);
      continue;
    }
    std::printf("ok %s\n", std::string(type.ros_type).c_str());
  }
  std::error_code ec;
  for (const fs::directory_entry& e : fs::directory_iterator(in_dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.ends_with(".foxglove.cdr") && !known.contains(name)) {
      std::printf("FAIL %s: a type the check does not know\n", name.c_str());
      ++failures;
    }
  }
  if (ec) return fail("cannot list " + in_dir.string() + ": " + ec.message());
  return failures == 0 ? 0 : 1;
}

}  // namespace
}  // namespace tessera

int main(int argc, char** argv) {
  const std::string mode = argc == 3 ? argv[1] : "";
  if (mode == "capture") return tessera::capture(argv[2]);
  if (mode == "check") return tessera::check(argv[2]);
  std::fprintf(stderr, "usage: wire_tool capture OUT_DIR | wire_tool check IN_DIR\n");
  return 2;
}
