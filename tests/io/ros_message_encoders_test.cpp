// The CDR encoders read back with tessera's decoders (ros_messages.hpp), which read real ROS 2
// bags; the ros2msg definitions name every nested type once. The third-party decoding of every
// type against these definitions is tests/record/mcap_recording_test.sh.
#include "tessera/io/ros_message_encoders.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

void expect_same(const RosTwist& a, const RosTwist& b) {
  EXPECT_EQ(a.linear_x_mps, b.linear_x_mps);
  EXPECT_EQ(a.linear_y_mps, b.linear_y_mps);
  EXPECT_EQ(a.linear_z_mps, b.linear_z_mps);
  EXPECT_EQ(a.angular_x_radps, b.angular_x_radps);
  EXPECT_EQ(a.angular_y_radps, b.angular_y_radps);
  EXPECT_EQ(a.angular_z_radps, b.angular_z_radps);
}

// Sample messages with a distinct value in every field; frames of odd lengths, so that CDR pads.
RosCovariance sample_covariance(double scale) {
  RosCovariance c{};
  for (std::size_t i = 0; i < c.size(); ++i) c[i] = scale * (static_cast<double>(i) - 17.5);
  return c;
}

RosTwist sample_twist() { return {0.4, -0.1, 0.05, 0.01, -0.02, 0.7}; }

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

}  // namespace
}  // namespace tessera
