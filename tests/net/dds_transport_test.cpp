#include "tessera/net/dds_transport.hpp"

#include <dds/dds.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <vector>

#include "sensor_msgs.h"  // the IDL-generated type, as a plain Cyclone DDS program uses it
#include "support/dds_isolation.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera::net {
namespace {

using ::testing::HasSubstr;
using Bytes = std::vector<std::uint8_t>;

std::unique_ptr<Transport> participant() {
  Result<std::unique_ptr<Transport>> t =
      make_dds_transport({.domain_id = support::test_dds_domain()});
  EXPECT_TRUE(t.ok()) << (t.ok() ? "" : t.error().message);
  return t.ok() ? std::move(*t) : nullptr;
}

// Cyclone pads a message to a multiple of 4 bytes and says how many bytes it added in the low two
// bits of the encapsulation options (XTypes 1.3, 7.6.3.1.2); otherwise the bytes are the ones sent.
::testing::AssertionResult same_message(const Bytes& received, const Bytes& sent) {
  const std::size_t padding = received.size() >= 4 ? received[3] & 3U : 0;
  if (received.size() != sent.size() + padding || (sent.size() + padding) % 4 != 0) {
    return ::testing::AssertionFailure()
           << received.size() << " bytes received for " << sent.size() << " sent";
  }
  for (std::size_t i = 0; i < received.size(); ++i) {
    const std::uint8_t expected = i == 3            ? static_cast<std::uint8_t>(padding)
                                  : i < sent.size() ? sent[i]
                                                    : 0;
    if (received[i] != expected) return ::testing::AssertionFailure() << "byte " << i << " differs";
  }
  return ::testing::AssertionSuccess();
}

std::string topic(const std::string& name) { return support::test_topic_prefix() + name; }

LaserScanMessage scan_message(float first_range_m) {
  LaserScanMessage m;
  m.header.stamp_ns = 1'700'000'000'123'456'789;
  m.header.frame_id = "r1/laser";
  m.angle_min_rad = -1.5F;
  m.angle_max_rad = 1.5F;
  m.angle_increment_rad = 1.0F;
  m.range_min_m = 0.1F;
  m.range_max_m = 30.0F;
  m.ranges_m = {first_range_m, 2.5F, 3.5F, 4.5F};
  return m;
}

// Polls `t` until `done()` or about ten seconds (discovery on loopback takes a few milliseconds;
// the bound is for a loaded CI machine).
template <typename Done>
bool poll_until(Transport& t, Done done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < end) {
    t.wait(0.05);
    t.poll();
    if (done()) return true;
  }
  return false;
}

// Publishes `message` until the reader's side has one (a writer and reader on DDS match a few
// milliseconds after both exist; best-effort data sent before that is not resent).
template <typename Done>
bool publish_until(Transport& writer, Transport::WriterId w, const Bytes& message,
                   Transport& reader, Done done) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (std::chrono::steady_clock::now() < end) {
    EXPECT_TRUE(writer.publish(w, message).ok());
    reader.wait(0.05);
    reader.poll();
    if (done()) return true;
  }
  return false;
}

TEST(DdsTransport, AScanCrossesBetweenParticipantsByteForByte) {
  auto a = participant();
  auto b = participant();
  ASSERT_TRUE(a && b);
  const TopicSpec spec{topic("/r1/scan"), "sensor_msgs/msg/LaserScan", Qos::sensor_data()};
  std::vector<Bytes> received;
  ASSERT_TRUE(b->subscribe(spec, [&](std::span<const std::uint8_t> cdr) {
                 received.emplace_back(cdr.begin(), cdr.end());
               }).ok());
  const auto w = a->advertise(spec);
  ASSERT_TRUE(w.ok());
  EXPECT_TRUE(poll_until(*a, [&] { return a->matched_readers(*w) == 1; }));
  const Bytes sent = encode_cdr(scan_message(1.25F));
  ASSERT_TRUE(publish_until(*a, *w, sent, *b, [&] { return !received.empty(); }));
  EXPECT_TRUE(same_message(received.front(), sent));
  const auto decoded = decode_laser_scan(received.front(), RosEncoding::kCdr);
  ASSERT_TRUE(decoded.ok());
  EXPECT_EQ(decoded->header.frame_id, "r1/laser");
  EXPECT_EQ(decoded->header.stamp_ns, 1'700'000'000'123'456'789);
  EXPECT_EQ(decoded->ranges_m.size(), 4U);
  EXPECT_GE(b->traffic().at(spec.name).messages_received, 1U);
  EXPECT_EQ(b->traffic().at(spec.name).bytes_received, received.front().size() * received.size());
}

TEST(DdsTransport, PlainCycloneReadsTesserasScanWithTheIdlType) {
  auto a = participant();
  ASSERT_TRUE(a);
  const TopicSpec spec{topic("/scan"), "sensor_msgs/msg/LaserScan", Qos::reliable(10)};
  const auto w = a->advertise(spec);
  ASSERT_TRUE(w.ok());
  // A second participant in the plain C API, on the same domain, with the generated type.
  const dds_entity_t pp = dds_create_participant(support::test_dds_domain(), nullptr, nullptr);
  ASSERT_GT(pp, 0);
  const std::string dds_name = "rt" + spec.name;
  const dds_entity_t tp = dds_create_topic(pp, &sensor_msgs_msg_dds__LaserScan__desc,
                                           dds_name.c_str(), nullptr, nullptr);
  dds_qos_t* qos = dds_create_qos();
  dds_qset_reliability(qos, DDS_RELIABILITY_RELIABLE, DDS_MSECS(100));
  const dds_entity_t rd = dds_create_reader(pp, tp, qos, nullptr);
  dds_delete_qos(qos);
  ASSERT_GT(rd, 0);
  const Bytes sent = encode_cdr(scan_message(0.75F));
  bool got = false;
  sensor_msgs_msg_dds__LaserScan_ m{};
  for (int i = 0; i < 200 && !got; ++i) {
    ASSERT_TRUE(a->publish(*w, sent).ok());
    dds_sleepfor(DDS_MSECS(20));
    void* samples[1] = {&m};
    dds_sample_info_t info;
    got = dds_take(rd, samples, &info, 1, 1) == 1 && info.valid_data;
  }
  ASSERT_TRUE(got);
  EXPECT_STREQ(m.header.frame_id, "r1/laser");
  EXPECT_EQ(m.header.stamp.sec, 1'700'000'000);
  EXPECT_EQ(m.header.stamp.nanosec, 123'456'789U);
  ASSERT_EQ(m.ranges._length, 4U);
  EXPECT_FLOAT_EQ(m.ranges._buffer[0], 0.75F);
  EXPECT_FLOAT_EQ(m.range_max, 30.0F);
  dds_sample_free(&m, &sensor_msgs_msg_dds__LaserScan__desc, DDS_FREE_CONTENTS);
  dds_delete(pp);
}

TEST(DdsTransport, ALateReaderGetsTheLastMapFromATransientLocalWriter) {
  auto mapper = participant();
  ASSERT_TRUE(mapper);
  const TopicSpec spec{topic("/map"), "nav_msgs/msg/OccupancyGrid", Qos::map()};
  const auto w = mapper->advertise(spec);
  ASSERT_TRUE(w.ok());
  OccupancyGridMessage map;
  map.header.frame_id = "map";
  map.resolution_m = 0.05F;
  map.width = 2;
  map.height = 1;
  map.data = {0, 100};
  ASSERT_TRUE(mapper->publish(*w, encode_cdr(map)).ok());
  map.data = {100, -1};
  const Bytes last = encode_cdr(map);
  ASSERT_TRUE(mapper->publish(*w, last).ok());
  auto late = participant();
  ASSERT_TRUE(late);
  std::vector<Bytes> received;
  ASSERT_TRUE(late->subscribe(spec,
                              [&](std::span<const std::uint8_t> cdr) {
                                received.emplace_back(cdr.begin(), cdr.end());
                              })
                  .ok());
  ASSERT_TRUE(poll_until(*late, [&] { return !received.empty(); }));
  EXPECT_EQ(received.size(), 1U);  // depth 1: only the last map
  EXPECT_TRUE(same_message(received.back(), last));
}

TEST(DdsTransport, BytesThatDoNotFitTheTypeAreRefusedBeforeTheyReachTheWire) {
  auto a = participant();
  ASSERT_TRUE(a);
  const auto w = a->advertise({topic("/scan"), "sensor_msgs/msg/LaserScan", Qos::sensor_data()});
  ASSERT_TRUE(w.ok());
  Bytes message = encode_cdr(scan_message(1.0F));
  const Bytes truncated(message.begin(), message.end() - 6);
  const Status short_one = a->publish(*w, truncated);
  ASSERT_FALSE(short_one.ok());
  EXPECT_EQ(short_one.error().kind, ErrorKind::kInput);
  EXPECT_THAT(short_one.error().message, HasSubstr("does not fit the type"));
  message[message.size() - 4] = 0xff;  // intensities' count far past the end
  EXPECT_FALSE(a->publish(*w, message).ok());
  const Bytes no_header{1, 2};
  EXPECT_THAT(a->publish(*w, no_header).error().message, HasSubstr("encapsulation"));
  const Bytes header_only{0, 1, 0, 0};
  EXPECT_THAT(a->publish(*w, header_only).error().message, HasSubstr("no fields"));
  EXPECT_EQ(a->traffic().count(topic("/scan")), 0U);  // nothing counted as sent
}

TEST(DdsTransport, EveryCarriedTypeHasItsRos2NameOnTheWire) {
  auto a = participant();
  ASSERT_TRUE(a);
  const std::vector<std::string> types = dds_transport_types();
  EXPECT_GE(types.size(), 15U);
  int i = 0;
  for (const std::string& type : types) {
    // advertise fails when the IDL's DDS type name is not ROS 2's mapping of `type`.
    const auto w = a->advertise({topic("/t" + std::to_string(i++)), type, Qos::reliable(1)});
    EXPECT_TRUE(w.ok()) << type << ": " << (w.ok() ? "" : w.error().message);
  }
  const auto unknown = a->advertise({topic("/x"), "std_msgs/msg/String", Qos::reliable(1)});
  ASSERT_FALSE(unknown.ok());
  EXPECT_THAT(unknown.error().message, HasSubstr("is not one the DDS transport carries"));
}

TEST(DdsTransport, DomainIdsOutOfRangeAreInputErrors) {
  const auto t = make_dds_transport({.domain_id = 233});
  ASSERT_FALSE(t.ok());
  EXPECT_EQ(t.error().kind, ErrorKind::kInput);
  EXPECT_THAT(t.error().message, HasSubstr("out of range"));
}

}  // namespace
}  // namespace tessera::net
