// Message decoding in both serializations: round trips through the test writer, CDR alignment
// and byte order, and every malformed length refused with the byte it happened at.
#include "tessera/io/ros_messages.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/bag_writer.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

LaserScanMessage sample_scan() {
  LaserScanMessage m;
  m.header = {1'234'000'000'567, "laser"};  // odd-length frame: CDR pads before the floats
  m.angle_min_rad = -1.5F;
  m.angle_max_rad = 1.5F;
  m.angle_increment_rad = 1.0F;
  m.range_min_m = 0.02F;
  m.range_max_m = 5.0F;
  m.ranges_m = {1.0F, std::numeric_limits<float>::infinity(), 2.5F, 0.0F};
  m.intensities = {7.0F};
  return m;
}

class BothEncodings : public ::testing::TestWithParam<RosEncoding> {};

TEST_P(BothEncodings, LaserScanRoundTripsEveryField) {
  const LaserScanMessage m = sample_scan();
  Result<LaserScanMessage> r =
      decode_laser_scan(support::encode_laser_scan(m, GetParam()), GetParam());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->header.stamp_ns, m.header.stamp_ns);
  EXPECT_EQ(r->header.frame_id, "laser");
  EXPECT_EQ(r->angle_min_rad, -1.5F);
  EXPECT_EQ(r->range_max_m, 5.0F);
  EXPECT_EQ(r->ranges_m, m.ranges_m);
  EXPECT_EQ(r->intensities, m.intensities);
}

// A MultiEchoLaserScan reads as the LaserScan of its first echoes (the writer puts a second echo
// 1 m beyond each first); a beam without an echo is no reading.
TEST_P(BothEncodings, MultiEchoLaserScanReadsItsFirstEchoes) {
  LaserScanMessage m = sample_scan();
  m.ranges_m.push_back(std::numeric_limits<float>::quiet_NaN());  // written with no echo
  const std::vector<std::uint8_t> bytes = support::encode_multi_echo_laser_scan(m, GetParam());
  Result<LaserScanMessage> r = decode_multi_echo_laser_scan(bytes, GetParam());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->header.stamp_ns, m.header.stamp_ns);
  EXPECT_EQ(r->header.frame_id, "laser");
  EXPECT_EQ(r->angle_increment_rad, 1.0F);
  EXPECT_EQ(r->range_max_m, 5.0F);
  ASSERT_EQ(r->ranges_m.size(), 5u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(r->ranges_m[i], m.ranges_m[i]) << i;
  EXPECT_TRUE(std::isnan(r->ranges_m[4]));
  EXPECT_EQ(r->intensities, std::vector<float>(5, 100.0F));
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::span<const std::uint8_t> cut(bytes.data(), n);
    Result<LaserScanMessage> bad = decode_multi_echo_laser_scan(cut, GetParam());
    ASSERT_FALSE(bad.ok()) << n << " bytes";
    EXPECT_THAT(bad.error().message, HasSubstr("sensor_msgs/MultiEchoLaserScan"));
  }
  EXPECT_TRUE(is_laser_scan_type("sensor_msgs/msg/MultiEchoLaserScan"));
  EXPECT_TRUE(is_laser_scan_type("sensor_msgs/LaserScan"));
  EXPECT_FALSE(is_laser_scan_type("sensor_msgs/PointCloud2"));
}

TEST_P(BothEncodings, OdometryKeepsFramesAndPose) {
  const OdometryMessage m{{5, "odom"}, "base_footprint", {1.0, 2.0, 0.0, 0.0, 0.0, 0.6, 0.8}};
  Result<OdometryMessage> r = decode_odometry(support::encode_odometry(m, GetParam()), GetParam());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->header.frame_id, "odom");
  EXPECT_EQ(r->child_frame_id, "base_footprint");
  EXPECT_EQ(r->pose.x_m, 1.0);
  EXPECT_EQ(r->pose.qz, 0.6);
  EXPECT_EQ(r->pose.qw, 0.8);
}

TEST_P(BothEncodings, OdometryKeepsTwistAndCovariances) {
  // Written field by field here (support::encode_odometry writes them as zeros); ROS 1 and ROS 2
  // Odometry have the same field order.
  support::MessageWriter w(GetParam());
  w.header({5, "odom"});
  w.string("base_footprint");
  w.transform({1.0, 2.0, 0.0, 0.0, 0.0, 0.6, 0.8});
  for (int i = 0; i < 36; ++i) w.f64(i);  // pose covariance
  for (const double d : {0.5, -0.1, 0.0, 0.0, 0.0, 0.25}) w.f64(d);
  for (int i = 0; i < 36; ++i) w.f64(-i);  // twist covariance
  Result<OdometryMessage> r = decode_odometry(std::move(w).take(), GetParam());
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->pose.qw, 0.8);
  EXPECT_EQ(r->pose_covariance[0], 0.0);
  EXPECT_EQ(r->pose_covariance[35], 35.0);
  EXPECT_EQ(r->twist.linear_x_mps, 0.5);
  EXPECT_EQ(r->twist.linear_y_mps, -0.1);
  EXPECT_EQ(r->twist.angular_z_radps, 0.25);
  EXPECT_EQ(r->twist_covariance[1], -1.0);
  EXPECT_EQ(r->twist_covariance[35], -35.0);
}

TEST_P(BothEncodings, TfMessageKeepsEveryTransform) {
  TfMessage m;
  m.transforms.push_back({{1, "a"}, "bb", {1, 0, 0, 0, 0, 0, 1}});
  m.transforms.push_back({{2, "ccc"}, "d", {0, 2, 0, 0, 0, 1, 0}});
  Result<TfMessage> r = decode_tf_message(support::encode_tf_message(m, GetParam()), GetParam());
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->transforms.size(), 2u);
  EXPECT_EQ(r->transforms[1].header.frame_id, "ccc");
  EXPECT_EQ(r->transforms[1].child_frame_id, "d");
  EXPECT_EQ(r->transforms[1].transform.y_m, 2.0);
}

TEST_P(BothEncodings, EveryTruncationIsAnErrorNamingAByte) {
  const std::vector<std::uint8_t> bytes = support::encode_laser_scan(sample_scan(), GetParam());
  for (std::size_t n = 0; n < bytes.size(); ++n) {
    const std::span<const std::uint8_t> cut(bytes.data(), n);
    Result<LaserScanMessage> r = decode_laser_scan(cut, GetParam());
    ASSERT_FALSE(r.ok()) << n << " bytes";
    EXPECT_THAT(r.error().message, HasSubstr("sensor_msgs/LaserScan"));
  }
}

INSTANTIATE_TEST_SUITE_P(RosMessages, BothEncodings,
                         ::testing::Values(RosEncoding::kRos1, RosEncoding::kCdr));

TEST(RosMessages, CdrAlignsEightByteFieldsFromTheEndOfTheEncapsulationHeader) {
  // Odometry: stamp (8) + "odom\0" (4 + 5 = 17 -> 17) + child "b\0" (pad to 20, 4 + 2 -> 26),
  // then the first float64 starts at the next multiple of 8 after the header: 32 (+4 header).
  const OdometryMessage m{{0, "odom"}, "b", {3.5, 0, 0, 0, 0, 0, 1}};
  const std::vector<std::uint8_t> bytes = support::encode_odometry(m, RosEncoding::kCdr);
  double x = 0.0;
  std::memcpy(&x, bytes.data() + 4 + 32, 8);
  EXPECT_EQ(x, 3.5);
  EXPECT_EQ(decode_odometry(bytes, RosEncoding::kCdr)->pose.x_m, 3.5);
}

TEST(RosMessages, BigEndianCdrIsRead) {
  // TFMessage with no transforms, then one transform written big endian by hand.
  std::vector<std::uint8_t> bytes = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x01,  // 1
                                     0x00, 0x00, 0x00, 0x07, 0x00, 0x00, 0x00, 0x09,  // stamp
                                     0x00, 0x00, 0x00, 0x02, 'a',  0x00, 0x00, 0x00,  // "a"
                                     0x00, 0x00, 0x00, 0x02, 'b',  0x00};             // "b"
  while ((bytes.size() - 4) % 8 != 0) bytes.push_back(0);
  for (double d : {1.25, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0}) {
    std::uint8_t le[8];
    std::memcpy(le, &d, 8);
    for (int i = 7; i >= 0; --i) bytes.push_back(le[i]);
  }
  Result<TfMessage> r = decode_tf_message(bytes, RosEncoding::kCdr);
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->transforms.size(), 1u);
  EXPECT_EQ(r->transforms[0].header.stamp_ns, 7'000'000'009);
  EXPECT_EQ(r->transforms[0].child_frame_id, "b");
  EXPECT_EQ(r->transforms[0].transform.x_m, 1.25);
  EXPECT_EQ(r->transforms[0].transform.qw, 1.0);
}

TEST(RosMessages, BigEndianCdrSequencesAreSwapped) {
  // LaserScan: stamp, frame "" (length 1, the NUL), padding, seven float32, ranges [1.5, -2],
  // intensities [], all big endian.
  std::vector<std::uint8_t> bytes = {0x00, 0x00, 0x00, 0x00,  // encapsulation: CDR_BE
                                     0x00, 0x00, 0x00, 0x03, 0x00, 0x00, 0x00, 0x04,  // stamp
                                     0x00, 0x00, 0x00, 0x01,   // frame_id length
                                     0x00, 0x00, 0x00, 0x00};  // NUL, pad
  const auto be32 = [&bytes](std::uint32_t u) {
    for (int shift = 24; shift >= 0; shift -= 8) {
      bytes.push_back(static_cast<std::uint8_t>(u >> shift));
    }
  };
  const auto be_float = [&be32](float f) {
    std::uint32_t u = 0;
    std::memcpy(&u, &f, 4);
    be32(u);
  };
  for (int i = 0; i < 7; ++i) be_float(static_cast<float>(i));
  be32(2);
  be_float(1.5F);
  be_float(-2.0F);
  be32(0);
  Result<LaserScanMessage> r = decode_laser_scan(bytes, RosEncoding::kCdr);
  ASSERT_TRUE(r.ok()) << r.error().message;
  EXPECT_EQ(r->header.stamp_ns, 3'000'000'004);
  EXPECT_EQ(r->header.frame_id, "");
  EXPECT_EQ(r->range_max_m, 6.0F);
  EXPECT_EQ(r->ranges_m, (std::vector<float>{1.5F, -2.0F}));
  EXPECT_TRUE(r->intensities.empty());
}

TEST(RosMessages, CdrStringWithoutTerminatorIsRefused) {
  std::vector<std::uint8_t> bytes = support::encode_laser_scan(sample_scan(), RosEncoding::kCdr);
  // frame_id "laser\0" starts at 4 + 8 + 4; overwrite its NUL.
  ASSERT_EQ(bytes[4 + 8 + 4 + 5], 0);
  bytes[4 + 8 + 4 + 5] = 'X';
  Result<LaserScanMessage> r = decode_laser_scan(bytes, RosEncoding::kCdr);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("no terminating NUL"));
}

TEST(RosMessages, ArrayCountBeyondTheMessageIsRefusedBeforeAllocating) {
  std::vector<std::uint8_t> bytes = support::encode_laser_scan(sample_scan(), RosEncoding::kRos1);
  // ROS 1: seq 4, stamp 8, "laser" 4 + 5, seven floats 28: the ranges count is at 49.
  const std::uint32_t huge = 0xFFFFFFF0u;
  std::memcpy(bytes.data() + 49, &huge, 4);
  Result<LaserScanMessage> r = decode_laser_scan(bytes, RosEncoding::kRos1);
  ASSERT_FALSE(r.ok());
  EXPECT_THAT(r.error().message, HasSubstr("byte 53: ranges of 4294967280 elements runs past"));
}

TEST(RosMessages, XcdrTwoEncapsulationIsRefused) {
  std::vector<std::uint8_t> bytes = support::encode_tf_message({}, RosEncoding::kCdr);
  bytes[1] = 0x07;  // PLAIN_CDR2 little endian
  EXPECT_FALSE(decode_tf_message(bytes, RosEncoding::kCdr).ok());
}

TEST(RosMessages, Ros2TypeNamesMatchTheirRos1Names) {
  EXPECT_TRUE(ros_type_is("sensor_msgs/msg/LaserScan", kLaserScanType));
  EXPECT_TRUE(ros_type_is("sensor_msgs/LaserScan", kLaserScanType));
  EXPECT_FALSE(ros_type_is("sensor_msgs/msg/LaserScanX", kLaserScanType));
  EXPECT_FALSE(ros_type_is("other_msgs/msg/LaserScan", kLaserScanType));
}

}  // namespace
}  // namespace tessera
