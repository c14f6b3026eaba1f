// The CDR encoders read back with tessera's decoders (ros_messages.hpp, which read real ROS 2
// bags, and the CDR decoders of ros_message_encoders.hpp) field for field; the byte layout of a few
// messages against bytes computed by hand; every truncation and every impossible count refused;
// the ros2msg definitions name every nested type once. The third-party decoding of every type
// against these definitions is tests/record/mcap_recording_test.sh.
#include "tessera/io/ros_message_encoders.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tessera {
namespace {

using ::testing::HasSubstr;

int occurrences(const std::string& text, const std::string& what) {
  int n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
    ++n;
  }
  return n;
}

TEST(RosMessageEncoders, LaserScanReadsBackWithTheDecoder) {
  LaserScanMessage m;
  m.header = {1'700'000'000'123'456'789, "robot0/laser"};
  m.angle_min_rad = -1.5F;
  m.angle_max_rad = 1.5F;
  m.angle_increment_rad = 1.0F;
  m.range_min_m = 0.1F;
  m.range_max_m = 30.0F;
  m.ranges_m = {1.0F, 2.5F, std::numeric_limits<float>::infinity(), 4.0F};
  m.intensities = {7.0F};
  Result<LaserScanMessage> back = decode_laser_scan(encode_cdr(m), RosEncoding::kCdr);
  ASSERT_TRUE(back.ok()) << back.error().message;
  EXPECT_EQ(back->header.stamp_ns, m.header.stamp_ns);
  EXPECT_EQ(back->header.frame_id, m.header.frame_id);
  EXPECT_EQ(back->angle_increment_rad, 1.0F);
  EXPECT_EQ(back->range_max_m, 30.0F);
  EXPECT_EQ(back->ranges_m, m.ranges_m);
  EXPECT_EQ(back->intensities, m.intensities);
}

TEST(RosMessageEncoders, OdometryAndTfReadBackWithTheDecoders) {
  OdometryMessage odom;
  odom.header = {42, "odom"};
  odom.child_frame_id = "robot0/base_link";
  odom.pose = planar_transform(1.5, -2.0, 0.3);
  Result<OdometryMessage> o = decode_odometry(encode_cdr(odom), RosEncoding::kCdr);
  ASSERT_TRUE(o.ok()) << o.error().message;
  EXPECT_EQ(o->child_frame_id, "robot0/base_link");
  EXPECT_DOUBLE_EQ(o->pose.x_m, 1.5);
  EXPECT_DOUBLE_EQ(2.0 * std::atan2(o->pose.qz, o->pose.qw), 0.3);

  TfMessage tf;
  tf.transforms.push_back({{-1'500'000'000, "map"}, "robot0/base_link", planar_transform(1, 2, 3)});
  tf.transforms.push_back({{7, "robot0/base_link"}, "robot0/laser", planar_transform(0.1, 0, 0)});
  Result<TfMessage> t = decode_tf_message(encode_cdr(tf), RosEncoding::kCdr);
  ASSERT_TRUE(t.ok()) << t.error().message;
  ASSERT_EQ(t->transforms.size(), 2U);
  EXPECT_EQ(t->transforms[0].header.stamp_ns, -1'500'000'000);  // negative stamps keep their sign
  EXPECT_EQ(t->transforms[1].child_frame_id, "robot0/laser");
  EXPECT_DOUBLE_EQ(t->transforms[1].transform.x_m, 0.1);
}

TEST(RosMessageEncoders, OccupancyGridLaysOutHeaderInfoAndCells) {
  OccupancyGridMessage m;
  m.header = {0, "map"};
  m.resolution_m = 0.05F;
  m.width = 3;
  m.height = 2;
  m.data = {-1, 0, 100, 50, -1, 7};
  const std::vector<std::uint8_t> bytes = encode_cdr(m);
  // encapsulation 4 + stamp 8 + frame "map" (4 + 4) + load time 8 + resolution 4 + width 4 +
  // height 4 + padding 4 + pose 56 + count 4 + 6 cells.
  ASSERT_EQ(bytes.size(), 4U + 8 + 8 + 8 + 4 + 4 + 4 + 4 + 56 + 4 + 6);
  EXPECT_EQ(static_cast<std::int8_t>(bytes[bytes.size() - 6]), -1);
  EXPECT_EQ(static_cast<std::int8_t>(bytes[bytes.size() - 4]), 100);
}

TEST(RosMessageEncoders, DefinitionsListEveryNestedTypeOnce) {
  const std::string markers = ros2msg_definition(kRos2MarkerArray);
  EXPECT_EQ(markers.rfind("visualization_msgs/Marker[] markers\n", 0), 0U);
  for (const char* type :
       {"visualization_msgs/Marker", "std_msgs/Header", "builtin_interfaces/Time",
        "builtin_interfaces/Duration", "geometry_msgs/Pose", "geometry_msgs/Point",
        "std_msgs/ColorRGBA", "sensor_msgs/CompressedImage", "visualization_msgs/MeshFile"}) {
    EXPECT_EQ(occurrences(markers, std::string("\nMSG: ") + type + "\n"), 1) << type;
  }
  EXPECT_EQ(occurrences(markers, std::string(80, '=') + "\n"), occurrences(markers, "MSG: "));
  EXPECT_THAT(ros2msg_definition(kRos2OccupancyGrid), HasSubstr("MSG: nav_msgs/MapMetaData\n"));
  EXPECT_THAT(ros2msg_definition("nav_msgs/msg/OccupancyGrid"),
              HasSubstr("nav_msgs/MapMetaData info\nint8[] data\n"));
  EXPECT_EQ(ros2msg_definition("sensor_msgs/msg/Image"), "");
}

// Field-for-field comparisons; a round trip must give back exactly what was encoded.
void expect_same(const RosHeader& a, const RosHeader& b) {
  EXPECT_EQ(a.stamp_ns, b.stamp_ns);
  EXPECT_EQ(a.frame_id, b.frame_id);
}

void expect_same(const RosTransform& a, const RosTransform& b) {
  EXPECT_EQ(a.x_m, b.x_m);
  EXPECT_EQ(a.y_m, b.y_m);
  EXPECT_EQ(a.z_m, b.z_m);
  EXPECT_EQ(a.qx, b.qx);
  EXPECT_EQ(a.qy, b.qy);
  EXPECT_EQ(a.qz, b.qz);
  EXPECT_EQ(a.qw, b.qw);
}

void expect_same(const RosPoint& a, const RosPoint& b) {
  EXPECT_EQ(a.x_m, b.x_m);
  EXPECT_EQ(a.y_m, b.y_m);
  EXPECT_EQ(a.z_m, b.z_m);
}

void expect_same(const RosColor& a, const RosColor& b) {
  EXPECT_EQ(a.r, b.r);
  EXPECT_EQ(a.g, b.g);
  EXPECT_EQ(a.b, b.b);
  EXPECT_EQ(a.a, b.a);
}

void expect_same(const RosTwist& a, const RosTwist& b) {
  EXPECT_EQ(a.linear_x_mps, b.linear_x_mps);
  EXPECT_EQ(a.linear_y_mps, b.linear_y_mps);
  EXPECT_EQ(a.linear_z_mps, b.linear_z_mps);
  EXPECT_EQ(a.angular_x_radps, b.angular_x_radps);
  EXPECT_EQ(a.angular_y_radps, b.angular_y_radps);
  EXPECT_EQ(a.angular_z_radps, b.angular_z_radps);
}

void expect_same(const TransformStampedMessage& a, const TransformStampedMessage& b) {
  expect_same(a.header, b.header);
  EXPECT_EQ(a.child_frame_id, b.child_frame_id);
  expect_same(a.transform, b.transform);
}

void expect_same(const PoseStampedMessage& a, const PoseStampedMessage& b) {
  expect_same(a.header, b.header);
  expect_same(a.pose, b.pose);
}

void expect_same(const MarkerMessage& a, const MarkerMessage& b) {
  expect_same(a.header, b.header);
  EXPECT_EQ(a.ns, b.ns);
  EXPECT_EQ(a.id, b.id);
  EXPECT_EQ(a.type, b.type);
  EXPECT_EQ(a.action, b.action);
  expect_same(a.pose, b.pose);
  expect_same(a.scale, b.scale);
  expect_same(a.color, b.color);
  EXPECT_EQ(a.lifetime_ns, b.lifetime_ns);
  EXPECT_EQ(a.frame_locked, b.frame_locked);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t i = 0; i < a.points.size(); ++i) expect_same(a.points[i], b.points[i]);
  ASSERT_EQ(a.colors.size(), b.colors.size());
  for (std::size_t i = 0; i < a.colors.size(); ++i) expect_same(a.colors[i], b.colors[i]);
  EXPECT_EQ(a.text, b.text);
}

// Sample messages with a distinct value in every field; frames of odd lengths, so that CDR pads.
RosCovariance sample_covariance(double scale) {
  RosCovariance c{};
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = scale * (static_cast<double>(i) - 17.5);
  return c;
}

RosTwist sample_twist() { return {0.4, -0.1, 0.05, 0.01, -0.02, 0.7}; }

TransformStampedMessage sample_transform_stamped() {
  return {{1'700'000'000'000'000'001, "map"}, "robot1/base_link", {1, -2, 0.5, 0.1, 0.2, 0.3, 0.9}};
}

OccupancyGridMessage sample_grid() {
  OccupancyGridMessage m;
  m.header = {-2'500'000'000, "team/map"};
  m.map_load_time_ns = 1'000'000'123;
  m.resolution_m = 0.05F;
  m.width = 3;
  m.height = 2;
  m.origin = {-10.0, -5.0, 0.0, 0.0, 0.0, 0.6, 0.8};
  m.data = {-1, 0, 100, 50, -1, 7};
  return m;
}

PathMessage sample_path() {
  PathMessage m;
  m.header = {11, "map"};
  m.poses.push_back({{12, "map"}, planar_transform(1, 2, 0.5)});
  m.poses.push_back({{13, "odom1"}, {3, 4, 5, 0.5, 0.5, 0.5, 0.5}});
  return m;
}

MarkerArrayMessage sample_markers() {
  MarkerArrayMessage m;
  MarkerMessage a;
  a.header = {99, "map"};
  a.ns = "frontiers";
  a.id = -3;
  a.type = MarkerMessage::kLineStrip;
  a.action = MarkerMessage::kAdd;
  a.pose = planar_transform(0.5, 0.25, 1.0);
  a.scale = {0.1, 0.2, 0.3};
  a.color = {0.1F, 0.2F, 0.3F, 0.4F};
  a.lifetime_ns = 1'500'000'000;
  a.frame_locked = true;
  a.points = {{1, 2, 3}, {-4, 5.5, 0}};
  a.colors = {{1, 0, 0, 1}, {0, 1, 0, 0.5F}};
  a.text = "claimed by r2";
  m.markers.push_back(a);
  MarkerMessage b;
  b.header = {100, "m"};
  b.type = MarkerMessage::kText;
  b.action = MarkerMessage::kDeleteAll;
  m.markers.push_back(b);
  return m;
}

PoseWithCovarianceStampedMessage sample_pose_with_covariance() {
  return {{5'000'000'001, "map"}, planar_transform(-1, 2, -0.5), sample_covariance(0.25)};
}

FrontierClaimMessage sample_claim() {
  FrontierClaimMessage m;
  m.header = {2'000'000'007, "map"};
  m.robot_id = "r1";
  m.claim_id = 7;
  m.target = {2.0, -1.5, 0.0};
  m.radius_m = 1.5F;
  m.path_length_m = 12.0F;
  m.active = true;
  return m;
}

RobotStatusMessage sample_status() {
  RobotStatusMessage m;
  m.header = {3'000'000'000, "map"};
  m.robot_id = "r1";
  m.state = RobotStatusMessage::kFailed;
  m.reason = "localisation lost";
  m.pose = planar_transform(4, -3, 2);
  m.explored_area_m2 = 123.25F;
  m.messages_sent = 5'000'000'000ULL;  // above 32 bits
  m.bytes_sent = 0xFEDC'BA98'7654'3210ULL;
  m.messages_dropped = 3;
  return m;
}

TeamCommandMessage sample_command() {
  TeamCommandMessage m;
  m.header = {4, "map"};
  m.robot_id = "r2";
  m.command = TeamCommandMessage::kReturnHome;
  return m;
}

TEST(RosMessageEncoders, TransformStampedRoundTripsEveryField) {
  const TransformStampedMessage m = sample_transform_stamped();
  Result<TransformStampedMessage> back = decode_cdr_transform_stamped(encode_cdr(m));
  ASSERT_TRUE(back.ok()) << back.error().message;
  expect_same(*back, m);
}

TEST(RosMessageEncoders, OdometryRoundTripsTwistAndCovariances) {
  OdometryMessage m;
  m.header = {-7, "odom"};
  m.child_frame_id = "base";
  m.pose = {1, 2, 3, 0.1, 0.2, 0.3, 0.9};
  m.pose_covariance = sample_covariance(0.5);
  m.twist = sample_twist();
  m.twist_covariance = sample_covariance(-2.0);
  Result<OdometryMessage> back = decode_odometry(encode_cdr(m), RosEncoding::kCdr);
  ASSERT_TRUE(back.ok()) << back.error().message;
  expect_same(back->header, m.header);
  EXPECT_EQ(back->child_frame_id, "base");
  expect_same(back->pose, m.pose);
  EXPECT_EQ(back->pose_covariance, m.pose_covariance);
  expect_same(back->twist, m.twist);
  EXPECT_EQ(back->twist_covariance, m.twist_covariance);
}

TEST(RosMessageEncoders, OccupancyGridRoundTripsEveryField) {
  const OccupancyGridMessage m = sample_grid();
  Result<OccupancyGridMessage> back = decode_cdr_occupancy_grid(encode_cdr(m));
  ASSERT_TRUE(back.ok()) << back.error().message;
  expect_same(back->header, m.header);
  EXPECT_EQ(back->map_load_time_ns, m.map_load_time_ns);
  EXPECT_EQ(back->resolution_m, m.resolution_m);
  EXPECT_EQ(back->width, 3U);
  EXPECT_EQ(back->height, 2U);
  expect_same(back->origin, m.origin);
  EXPECT_EQ(back->data, m.data);
}

TEST(RosMessageEncoders, PathAndPoseStampedRoundTripEveryField) {
  const PathMessage m = sample_path();
  Result<PathMessage> back = decode_cdr_path(encode_cdr(m));
  ASSERT_TRUE(back.ok()) << back.error().message;
  expect_same(back->header, m.header);
  ASSERT_EQ(back->poses.size(), 2U);
  expect_same(back->poses[0], m.poses[0]);
  expect_same(back->poses[1], m.poses[1]);

  Result<PoseStampedMessage> pose = decode_cdr_pose_stamped(encode_cdr(m.poses[1]));
  ASSERT_TRUE(pose.ok()) << pose.error().message;
  expect_same(*pose, m.poses[1]);

  Result<PathMessage> empty = decode_cdr_path(encode_cdr(PathMessage{}));
  ASSERT_TRUE(empty.ok()) << empty.error().message;
  EXPECT_TRUE(empty->poses.empty());
}

TEST(RosMessageEncoders, MarkerArrayRoundTripsEveryField) {
  const MarkerArrayMessage m = sample_markers();
  Result<MarkerArrayMessage> back = decode_cdr_marker_array(encode_cdr(m));
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->markers.size(), 2U);
  expect_same(back->markers[0], m.markers[0]);
  expect_same(back->markers[1], m.markers[1]);
}

TEST(RosMessageEncoders, ClockTwistAndPoseWithCovarianceRoundTripEveryField) {
  for (const std::int64_t ns : {std::int64_t{0}, std::int64_t{1'700'000'000'123'456'789},
                                std::int64_t{-1}, std::int64_t{-1'000'000'000}}) {
    Result<ClockMessage> clock = decode_cdr_clock(encode_cdr(ClockMessage{ns}));
    ASSERT_TRUE(clock.ok()) << clock.error().message;
    EXPECT_EQ(clock->clock_ns, ns);
  }

  const TwistMessage twist = sample_twist();
  Result<TwistMessage> t = decode_cdr_twist(encode_cdr(twist));
  ASSERT_TRUE(t.ok()) << t.error().message;
  expect_same(*t, twist);

  const PoseWithCovarianceStampedMessage pose = sample_pose_with_covariance();
  Result<PoseWithCovarianceStampedMessage> p =
      decode_cdr_pose_with_covariance_stamped(encode_cdr(pose));
  ASSERT_TRUE(p.ok()) << p.error().message;
  expect_same(p->header, pose.header);
  expect_same(p->pose, pose.pose);
  EXPECT_EQ(p->covariance, pose.covariance);
}

TEST(RosMessageEncoders, TeamMessagesRoundTripEveryField) {
  for (const bool active : {true, false}) {
    FrontierClaimMessage m = sample_claim();
    m.active = active;
    Result<FrontierClaimMessage> back = decode_cdr_frontier_claim(encode_cdr(m));
    ASSERT_TRUE(back.ok()) << back.error().message;
    expect_same(back->header, m.header);
    EXPECT_EQ(back->robot_id, "r1");
    EXPECT_EQ(back->claim_id, 7U);
    expect_same(back->target, m.target);
    EXPECT_EQ(back->radius_m, 1.5F);
    EXPECT_EQ(back->path_length_m, 12.0F);
    EXPECT_EQ(back->active, active);
  }

  const RobotStatusMessage s = sample_status();
  Result<RobotStatusMessage> status = decode_cdr_robot_status(encode_cdr(s));
  ASSERT_TRUE(status.ok()) << status.error().message;
  expect_same(status->header, s.header);
  EXPECT_EQ(status->robot_id, "r1");
  EXPECT_EQ(status->state, RobotStatusMessage::kFailed);
  EXPECT_EQ(status->reason, "localisation lost");
  expect_same(status->pose, s.pose);
  EXPECT_EQ(status->explored_area_m2, 123.25F);
  EXPECT_EQ(status->messages_sent, 5'000'000'000ULL);
  EXPECT_EQ(status->bytes_sent, 0xFEDC'BA98'7654'3210ULL);
  EXPECT_EQ(status->messages_dropped, 3U);

  const TeamCommandMessage c = sample_command();
  Result<TeamCommandMessage> command = decode_cdr_team_command(encode_cdr(c));
  ASSERT_TRUE(command.ok()) << command.error().message;
  expect_same(command->header, c.header);
  EXPECT_EQ(command->robot_id, "r2");
  EXPECT_EQ(command->command, TeamCommandMessage::kReturnHome);
}

TEST(RosMessageEncoders, ClockLayoutIsSecThenNanosec) {
  // 1'700'000'000 s = 0x6553F100, 123'456'789 ns = 0x075BCD15.
  EXPECT_EQ(encode_cdr(ClockMessage{1'700'000'000'123'456'789}),
            (std::vector<std::uint8_t>{0x00, 0x01, 0x00, 0x00,     // encapsulation: CDR_LE
                                       0x00, 0xF1, 0x53, 0x65,     // sec
                                       0x15, 0xCD, 0x5B, 0x07}));  // nanosec
  // -1 ns is sec -1, nanosec 999'999'999 = 0x3B9AC9FF.
  EXPECT_EQ(encode_cdr(ClockMessage{-1}),
            (std::vector<std::uint8_t>{0x00, 0x01, 0x00, 0x00, 0xFF, 0xFF, 0xFF, 0xFF, 0xFF, 0xC9,
                                       0x9A, 0x3B}));
}

TEST(RosMessageEncoders, TwistLayoutIsSixFloat64) {
  TwistMessage t;
  t.linear_x_mps = 1.0;      // 0x3FF0000000000000
  t.linear_y_mps = -2.0;     // 0xC000000000000000
  t.angular_y_radps = 0.5;   // 0x3FE0000000000000
  t.angular_z_radps = 0.25;  // 0x3FD0000000000000
  const std::vector<std::uint8_t> expected = {
      0x00, 0x01, 0x00, 0x00,                          // encapsulation
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF0, 0x3F,  // linear.x
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC0,  // linear.y
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // linear.z
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // angular.x
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xE0, 0x3F,  // angular.y
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xD0, 0x3F,  // angular.z
  };
  EXPECT_EQ(encode_cdr(t), expected);
}

TEST(RosMessageEncoders, FrontierClaimLayoutPadsBeforeClaimIdAndTarget) {
  // Offsets after the encapsulation: stamp 0, frame_id 8, robot_id 16 ("r1\0" ends at 23, one
  // byte of padding), claim_id 24, four bytes of padding, target 32, radius 56, path length 60,
  // active 64: 65 bytes.
  const std::vector<std::uint8_t> expected = {
      0x00, 0x01, 0x00, 0x00,                          // encapsulation
      0x02, 0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00,  // stamp: 2 s, 7 ns
      0x04, 0x00, 0x00, 0x00, 'm',  'a',  'p',  0x00,  // frame_id
      0x03, 0x00, 0x00, 0x00, 'r',  '1',  0x00,        // robot_id
      0x00,                                            // padding to 4
      0x07, 0x00, 0x00, 0x00,                          // claim_id
      0x00, 0x00, 0x00, 0x00,                          // padding to 8
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40,  // target.x 2.0
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xF8, 0xBF,  // target.y -1.5
      0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00,  // target.z 0.0
      0x00, 0x00, 0xC0, 0x3F,                          // radius_m 1.5F
      0x00, 0x00, 0x40, 0x41,                          // path_length_m 12.0F
      0x01,                                            // active
  };
  EXPECT_EQ(encode_cdr(sample_claim()), expected);
}

TEST(RosMessageEncoders, RobotStatusAlignsItsCountersToEightBytes) {
  // After the encapsulation: stamp 0, "map" 8, "r1" 16..23, state 23, reason "" 24..29 (length
  // 1, the NUL), pose 32..88, explored area 88..92, padding, the counters 96, 104, 112.
  RobotStatusMessage m = sample_status();
  m.reason = "";
  const std::vector<std::uint8_t> bytes = encode_cdr(m);
  ASSERT_EQ(bytes.size(), 4U + 120);
  EXPECT_EQ(bytes[4 + 23], RobotStatusMessage::kFailed);
  std::uint64_t sent = 0, bytes_sent = 0, dropped = 0;
  std::memcpy(&sent, bytes.data() + 4 + 96, 8);
  std::memcpy(&bytes_sent, bytes.data() + 4 + 104, 8);
  std::memcpy(&dropped, bytes.data() + 4 + 112, 8);
  EXPECT_EQ(sent, m.messages_sent);
  EXPECT_EQ(bytes_sent, m.bytes_sent);
  EXPECT_EQ(dropped, m.messages_dropped);
}

// A little-endian CDR writer written again for the tests, independent of the encoders: builds
// the fields the encoders leave out (a marker's texture, UV coordinates and mesh).
class HandCdr {
 public:
  HandCdr& u8(std::uint8_t v) {
    bytes_.push_back(v);
    return *this;
  }
  HandCdr& u32(std::uint32_t v) { return put(v); }
  HandCdr& i32(std::int32_t v) { return put(v); }
  HandCdr& f32(float v) { return put(v); }
  HandCdr& f64(double v) { return put(v); }
  HandCdr& string(std::string_view s) {
    u32(static_cast<std::uint32_t>(s.size() + 1));
    bytes_.insert(bytes_.end(), s.begin(), s.end());
    return u8(0);
  }
  HandCdr& header(std::int32_t sec, std::uint32_t nsec, std::string_view frame) {
    return i32(sec).u32(nsec).string(frame);
  }
  HandCdr& pose(const RosTransform& t) {
    for (const double d : {t.x_m, t.y_m, t.z_m, t.qx, t.qy, t.qz, t.qw}) f64(d);
    return *this;
  }
  [[nodiscard]] const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  template <typename T>
  HandCdr& put(T v) {
    while ((bytes_.size() - 4) % sizeof(T) != 0) bytes_.push_back(0);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + sizeof(T));
    std::memcpy(bytes_.data() + at, &v, sizeof(T));
    return *this;
  }
  std::vector<std::uint8_t> bytes_{0x00, 0x01, 0x00, 0x00};
};

// One visualization_msgs/Marker of type TEXT with every field of Humble's definition; `extras`
// fills the texture, UV coordinates and mesh that tessera's encoder writes empty.
void hand_marker(HandCdr& w, bool extras) {
  w.header(1, 2, "map").string("ns").i32(4).i32(MarkerMessage::kText).i32(MarkerMessage::kAdd);
  w.pose({1, 2, 3, 0, 0, 0, 1});
  w.f64(0.5).f64(0.5).f64(0.5);                   // scale
  w.f32(1).f32(0.5F).f32(0.25F).f32(1);           // color
  w.i32(3).u32(0).u8(0);                          // lifetime, frame_locked
  w.u32(1).f64(7).f64(8).f64(9);                  // points
  w.u32(0);                                       // colors
  w.string(extras ? "package://t/tex.png" : "");  // texture_resource
  // texture: header, format, data
  w.header(extras ? 5 : 0, 0, extras ? "cam" : "").string(extras ? "png" : "");
  w.u32(extras ? 3 : 0);  // texture.data
  if (extras) w.u8(0x89).u8('P').u8('N');
  w.u32(extras ? 2 : 0);  // uv_coordinates
  if (extras) w.f32(0.5F).f32(0.25F).f32(1).f32(0);
  w.string("hello");                               // text
  w.string(extras ? "package://t/mesh.dae" : "");  // mesh_resource
  w.string(extras ? "mesh.dae" : "");              // mesh_file.filename
  w.u32(extras ? 5 : 0);                           // mesh_file.data
  if (extras) w.u8(1).u8(2).u8(3).u8(4).u8(5);
  w.u8(extras ? 1 : 0);  // mesh_use_embedded_materials
}

MarkerMessage hand_marker_fields() {
  MarkerMessage k;
  k.header = {1'000'000'002, "map"};
  k.ns = "ns";
  k.id = 4;
  k.type = MarkerMessage::kText;
  k.pose = {1, 2, 3, 0, 0, 0, 1};
  k.scale = {0.5, 0.5, 0.5};
  k.color = {1, 0.5F, 0.25F, 1};
  k.lifetime_ns = 3'000'000'000;
  k.points = {{7, 8, 9}};
  k.text = "hello";
  return k;
}

TEST(RosMessageEncoders, MarkerLayoutMatchesAnIndependentWriter) {
  HandCdr w;
  w.u32(1);
  hand_marker(w, false);
  EXPECT_EQ(encode_cdr(MarkerArrayMessage{{hand_marker_fields()}}), w.bytes());
}

TEST(RosMessageEncoders, MarkerDecoderStepsOverTextureUvCoordinatesAndMesh) {
  HandCdr w;
  w.u32(2);
  hand_marker(w, true);
  hand_marker(w, false);
  Result<MarkerArrayMessage> back = decode_cdr_marker_array(w.bytes());
  ASSERT_TRUE(back.ok()) << back.error().message;
  ASSERT_EQ(back->markers.size(), 2U);
  expect_same(back->markers[0], hand_marker_fields());
  expect_same(back->markers[1], hand_marker_fields());
}

// Each prefix of a good message (also the empty one and the encapsulation alone) is refused with
// "<type>: byte N:".
template <typename Decode>
void expect_every_truncation_fails(const std::vector<std::uint8_t>& bytes, Decode decode,
                                   std::string_view type) {
  SCOPED_TRACE(std::string(type));
  ASSERT_TRUE(decode(std::span<const std::uint8_t>(bytes)).ok());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const auto r = decode(std::span<const std::uint8_t>(bytes.data(), n));
    ASSERT_FALSE(r.ok()) << n << " of " << bytes.size() << " bytes";
    EXPECT_EQ(r.error().kind, ErrorKind::kInput);
    EXPECT_THAT(r.error().message, HasSubstr(std::string(type) + ": byte "));
  }
}

TEST(RosMessageEncoders, EveryTruncationOfEveryDecodedMessageIsAnError) {
  expect_every_truncation_fails(encode_cdr(sample_transform_stamped()),
                                decode_cdr_transform_stamped, kRos2TransformStamped);
  expect_every_truncation_fails(encode_cdr(sample_grid()), decode_cdr_occupancy_grid,
                                kRos2OccupancyGrid);
  expect_every_truncation_fails(encode_cdr(sample_path()), decode_cdr_path, kRos2Path);
  expect_every_truncation_fails(encode_cdr(sample_path().poses[0]), decode_cdr_pose_stamped,
                                kRos2PoseStamped);
  expect_every_truncation_fails(encode_cdr(sample_markers()), decode_cdr_marker_array,
                                kRos2MarkerArray);
  HandCdr with_extras;
  with_extras.u32(1);
  hand_marker(with_extras, true);
  expect_every_truncation_fails(with_extras.bytes(), decode_cdr_marker_array, kRos2MarkerArray);
  expect_every_truncation_fails(encode_cdr(ClockMessage{5}), decode_cdr_clock, kRos2Clock);
  expect_every_truncation_fails(encode_cdr(sample_twist()), decode_cdr_twist, kRos2Twist);
  expect_every_truncation_fails(encode_cdr(sample_pose_with_covariance()),
                                decode_cdr_pose_with_covariance_stamped,
                                kRos2PoseWithCovarianceStamped);
  expect_every_truncation_fails(encode_cdr(sample_claim()), decode_cdr_frontier_claim,
                                kRos2FrontierClaim);
  expect_every_truncation_fails(encode_cdr(sample_status()), decode_cdr_robot_status,
                                kRos2RobotStatus);
  expect_every_truncation_fails(encode_cdr(sample_command()), decode_cdr_team_command,
                                kRos2TeamCommand);
  OdometryMessage odom;
  odom.twist = sample_twist();
  expect_every_truncation_fails(
      encode_cdr(odom),
      [](std::span<const std::uint8_t> b) { return decode_odometry(b, RosEncoding::kCdr); },
      kOdometryType);
}

// `bytes` with the uint32 at `offset` (counting the encapsulation) replaced by 0xFFFFFFFF.
std::vector<std::uint8_t> with_count_max(std::vector<std::uint8_t> bytes, std::size_t offset) {
  const std::uint32_t max = 0xFFFFFFFFu;
  std::memcpy(bytes.data() + offset, &max, 4);
  return bytes;
}

TEST(RosMessageEncoders, CountsOf0xFFFFFFFFAreRefusedNamingTheField) {
  // OccupancyGrid data: 4 + stamp 8 + "map" 8 + info up to the pose 20 + padding 4 + pose 56.
  OccupancyGridMessage grid = sample_grid();
  grid.header.frame_id = "map";
  Result<OccupancyGridMessage> g =
      decode_cdr_occupancy_grid(with_count_max(encode_cdr(grid), 4 + 8 + 8 + 20 + 4 + 56));
  ASSERT_FALSE(g.ok());
  EXPECT_THAT(g.error().message,
              HasSubstr("nav_msgs/msg/OccupancyGrid: byte 104: data of 4294967295 elements runs "
                        "past the end of the message"));

  // Path poses: after the path's header (stamp 8, "map" 8).
  Result<PathMessage> p = decode_cdr_path(with_count_max(encode_cdr(sample_path()), 4 + 16));
  ASSERT_FALSE(p.ok());
  EXPECT_THAT(p.error().message, HasSubstr("nav_msgs/msg/Path: byte 24: poses of 4294967295"));

  // FrontierClaim robot_id, a string length.
  Result<FrontierClaimMessage> c =
      decode_cdr_frontier_claim(with_count_max(encode_cdr(sample_claim()), 4 + 16));
  ASSERT_FALSE(c.ok());
  EXPECT_THAT(c.error().message, HasSubstr("tessera_msgs/msg/FrontierClaim: byte 24: robot_id"));

  // Every count of a marker, at its offset in hand_marker's layout (after the encapsulation: the
  // markers' count 0, header 4..20, ns 20..27, id 28, pose 40, scale 96, color 120, lifetime 136,
  // frame_locked 144, points 148 and one point 152..176, colors 176, texture_resource 180..185,
  // texture header 188..201, format 204..209, texture.data 212, uv_coordinates 216, text
  // 220..230, mesh_resource 232..237, mesh_file.filename 240..245, mesh_file.data 248).
  HandCdr w;
  w.u32(1);
  hand_marker(w, false);
  ASSERT_EQ(w.bytes().size(), 4U + 253);
  for (const auto& [offset, field] :
       std::vector<std::pair<std::size_t, std::string>>{{0, "markers"},
                                                        {148, "points"},
                                                        {176, "colors"},
                                                        {212, "texture.data"},
                                                        {216, "uv_coordinates"},
                                                        {248, "mesh_file.data"}}) {
    Result<MarkerArrayMessage> m = decode_cdr_marker_array(with_count_max(w.bytes(), 4 + offset));
    ASSERT_FALSE(m.ok()) << field;
    EXPECT_THAT(m.error().message, HasSubstr(field + " of 4294967295 elements runs past")) << field;
  }
}

TEST(RosMessageEncoders, BoolOtherThanZeroOrOneIsRefused) {
  std::vector<std::uint8_t> bytes = encode_cdr(sample_claim());
  bytes.back() = 2;  // active
  Result<FrontierClaimMessage> r = decode_cdr_frontier_claim(bytes);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message,
              HasSubstr("tessera_msgs/msg/FrontierClaim: byte 68: active: bool of value 2"));
}

TEST(RosMessageEncoders, NewDefinitionsListEveryNestedTypeOnce) {
  struct Expected {
    std::string_view type;
    std::string first_line;
    std::vector<std::string> nested;
  };
  const std::vector<std::string> header = {"std_msgs/Header", "builtin_interfaces/Time"};
  const std::vector<std::string> pose = {"geometry_msgs/Pose", "geometry_msgs/Point",
                                         "geometry_msgs/Quaternion"};
  const auto join = [](std::vector<std::string> a, const std::vector<std::string>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const std::vector<Expected> types = {
      {kRos2Clock, "builtin_interfaces/Time clock\n", {"builtin_interfaces/Time"}},
      {kRos2Twist, "geometry_msgs/Vector3 linear\n", {"geometry_msgs/Vector3"}},
      {kRos2PoseWithCovarianceStamped, "std_msgs/Header header\n",
       join(join(header, {"geometry_msgs/PoseWithCovariance"}), pose)},
      {kRos2TransformStamped, "std_msgs/Header header\n",
       join(header,
            {"geometry_msgs/Transform", "geometry_msgs/Vector3", "geometry_msgs/Quaternion"})},
      {kRos2PoseStamped, "std_msgs/Header header\n", join(header, pose)},
      {kRos2Odometry, "std_msgs/Header header\n",
       join(join(header, {"geometry_msgs/PoseWithCovariance", "geometry_msgs/TwistWithCovariance",
                          "geometry_msgs/Twist", "geometry_msgs/Vector3"}),
            pose)},
      {kRos2FrontierClaim, "std_msgs/Header header\n", join(header, {"geometry_msgs/Point"})},
      {kRos2RobotStatus, "std_msgs/Header header\n", join(header, pose)},
      {kRos2TeamCommand, "std_msgs/Header header\n", header},
  };
  for (const Expected& e : types) {
    SCOPED_TRACE(std::string(e.type));
    const std::string definition = ros2msg_definition(e.type);
    EXPECT_EQ(definition.rfind(e.first_line, 0), 0U);
    for (const std::string& nested : e.nested) {
      EXPECT_EQ(occurrences(definition, "\nMSG: " + nested + "\n"), 1) << nested;
    }
    EXPECT_EQ(occurrences(definition, "MSG: "), static_cast<int>(e.nested.size()));
    EXPECT_EQ(occurrences(definition, std::string(80, '=') + "\n"),
              occurrences(definition, "MSG: "));
  }
  // tessera_msgs: the fields as the team's definitions give them.
  EXPECT_EQ(
      ros2msg_definition(kRos2FrontierClaim)
          .rfind(
              "std_msgs/Header header\nstring robot_id\nuint32 claim_id\n"
              "geometry_msgs/Point target\nfloat32 radius_m\nfloat32 path_length_m\nbool active\n"
              "=====",
              0),
      0U);
  EXPECT_EQ(ros2msg_definition(kRos2RobotStatus)
                .rfind("std_msgs/Header header\nstring robot_id\nuint8 state\nstring reason\n"
                       "geometry_msgs/Pose pose\nfloat32 explored_area_m2\nuint64 messages_sent\n"
                       "uint64 bytes_sent\nuint64 messages_dropped\n=====",
                       0),
            0U);
  EXPECT_EQ(ros2msg_definition(kRos2TeamCommand)
                .rfind("std_msgs/Header header\nstring robot_id\nuint8 command\n=====", 0),
            0U);
}

}  // namespace
}  // namespace tessera
