#include "tessera/net/in_process_transport.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <thread>
#include <vector>

namespace tessera::net {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using Bytes = std::vector<std::uint8_t>;

const std::string kScanType = "sensor_msgs/msg/LaserScan";
const std::string kMapType = "nav_msgs/msg/OccupancyGrid";

// A subscription that keeps the first byte of each message it is handed.
struct Inbox {
  std::vector<std::uint8_t> firsts;
  Transport::Handler handler() {
    return [this](std::span<const std::uint8_t> cdr) { firsts.push_back(cdr[0]); };
  }
};

Transport::WriterId advertise(Transport& t, const TopicSpec& spec) {
  Result<Transport::WriterId> w = t.advertise(spec);
  EXPECT_TRUE(w.ok());
  return w.ok() ? *w : 0;
}

void subscribe(Transport& t, const TopicSpec& spec, Inbox& inbox) {
  EXPECT_TRUE(t.subscribe(spec, inbox.handler()).ok());
}

void publish(Transport& t, Transport::WriterId w, std::uint8_t first) {
  const Bytes message{first, 1, 2, 3};
  EXPECT_TRUE(t.publish(w, message).ok());
}

TEST(InProcessTransport, AMessageReachesEveryMatchedReaderOnPoll) {
  InProcessBus bus;
  auto a = bus.join();
  auto b = bus.join();
  const TopicSpec scan{"/r1/scan", kScanType, Qos::sensor_data()};
  Inbox at_a, at_b;
  subscribe(*a, scan, at_a);
  subscribe(*b, scan, at_b);
  const auto w = advertise(*a, scan);
  publish(*a, w, 7);
  publish(*a, w, 8);
  EXPECT_TRUE(at_b.firsts.empty());  // nothing runs before poll
  EXPECT_EQ(b->poll(), 2U);
  EXPECT_THAT(at_b.firsts, ElementsAre(7, 8));
  EXPECT_EQ(a->poll(), 2U);  // the writer's own participant reads it too, as in ROS 2
  EXPECT_EQ(b->poll(), 0U);
}

TEST(InProcessTransport, KeepLastDropsTheOldestUnreadMessages) {
  InProcessBus bus;
  auto a = bus.join();
  const TopicSpec scan{"/scan", kScanType, Qos::sensor_data()};  // depth 5
  Inbox inbox;
  subscribe(*a, scan, inbox);
  const auto w = advertise(*a, scan);
  for (std::uint8_t i = 0; i < 8; ++i) publish(*a, w, i);
  a->poll();
  EXPECT_THAT(inbox.firsts, ElementsAre(3, 4, 5, 6, 7));
}

TEST(InProcessTransport, ATransientLocalReaderGetsTheLastMapOnJoiningAndAVolatileOneDoesNot) {
  InProcessBus bus;
  auto mapper = bus.join();
  const TopicSpec map{"/map", kMapType, Qos::map()};
  const auto w = advertise(*mapper, map);
  publish(*mapper, w, 1);
  publish(*mapper, w, 2);
  auto late = bus.join();
  Inbox latched, fresh_only;
  subscribe(*late, map, latched);
  subscribe(*late, {"/map", kMapType, Qos::reliable(10)}, fresh_only);
  late->poll();
  EXPECT_THAT(latched.firsts, ElementsAre(2));
  EXPECT_TRUE(fresh_only.firsts.empty());
  // The history goes with its writer's participant.
  mapper.reset();
  Inbox after;
  subscribe(*late, map, after);
  late->poll();
  EXPECT_TRUE(after.firsts.empty());
}

TEST(InProcessTransport, AWriterCountsItsMatchedReaders) {
  InProcessBus bus;
  auto a = bus.join();
  const auto w = advertise(*a, {"/scan", kScanType, Qos::reliable(5)});
  EXPECT_EQ(a->matched_readers(w), 0U);
  auto b = bus.join();
  Inbox inbox;
  subscribe(*b, {"/scan", kScanType, Qos::sensor_data()}, inbox);
  subscribe(*b, {"/scan", kMapType, Qos::sensor_data()}, inbox);  // another type: no match
  EXPECT_EQ(a->matched_readers(w), 1U);
  b.reset();
  EXPECT_EQ(a->matched_readers(w), 0U);
  EXPECT_EQ(a->matched_readers(999), 0U);
}

TEST(InProcessTransport, IncompatibleQosOrTypeMeansNoMatch) {
  InProcessBus bus;
  auto a = bus.join();
  Inbox reliable_reader, other_type, latched_reader;
  subscribe(*a, {"/scan", kScanType, Qos::reliable(5)}, reliable_reader);
  subscribe(*a, {"/scan", kMapType, Qos::sensor_data()}, other_type);
  subscribe(*a, {"/scan", kScanType, Qos::map()}, latched_reader);
  const auto w = advertise(*a, {"/scan", kScanType, Qos::sensor_data()});  // best effort
  publish(*a, w, 1);
  EXPECT_EQ(a->poll(), 0U);
}

TEST(InProcessTransport, BadNamesAndTypesAreInputErrors) {
  InProcessBus bus;
  auto a = bus.join();
  const auto bad_name = a->advertise({"scan", kScanType, Qos::sensor_data()});
  ASSERT_FALSE(bad_name.ok());
  EXPECT_EQ(bad_name.error().kind, ErrorKind::kInput);
  EXPECT_THAT(bad_name.error().message, HasSubstr("must start with '/'"));
  const auto bad_type = a->subscribe({"/scan", "LaserScan", Qos::sensor_data()}, {});
  ASSERT_FALSE(bad_type.ok());
  EXPECT_THAT(bad_type.error().message, HasSubstr("topic /scan"));
  const Bytes m{0, 1, 0, 0};
  EXPECT_FALSE(a->publish(99, m).ok());
}

TEST(InProcessTransport, AHandlerMayPublish) {
  InProcessBus bus;
  auto a = bus.join();
  const TopicSpec ping{"/ping", kScanType, Qos::reliable(10)};
  const TopicSpec pong{"/pong", kScanType, Qos::reliable(10)};
  const auto w_pong = advertise(*a, pong);
  Inbox pongs;
  subscribe(*a, pong, pongs);
  ASSERT_TRUE(a->subscribe(ping, [&](std::span<const std::uint8_t> cdr) {
                 publish(*a, w_pong, static_cast<std::uint8_t>(cdr[0] + 1));
               }).ok());
  const auto w_ping = advertise(*a, ping);
  publish(*a, w_ping, 4);
  a->poll();  // runs the ping handler, which publishes a pong
  a->poll();
  EXPECT_THAT(pongs.firsts, ElementsAre(5));
}

TEST(InProcessTransport, WaitWakesOnAMessageFromAnotherThreadAndTimesOutWithout) {
  InProcessBus bus;
  auto reader = bus.join();
  auto writer = bus.join();
  const TopicSpec scan{"/scan", kScanType, Qos::sensor_data()};
  Inbox inbox;
  subscribe(*reader, scan, inbox);
  EXPECT_FALSE(reader->wait(0.01));
  const auto w = advertise(*writer, scan);
  std::thread sender([&] { publish(*writer, w, 9); });
  EXPECT_TRUE(reader->wait(10.0));
  sender.join();
  reader->poll();
  EXPECT_THAT(inbox.firsts, ElementsAre(9));
}

TEST(InProcessTransport, TrafficIsCountedPerTopic) {
  InProcessBus bus;
  auto a = bus.join();
  auto b = bus.join();
  const TopicSpec scan{"/scan", kScanType, Qos::sensor_data()};
  Inbox inbox;
  subscribe(*b, scan, inbox);
  const auto w = advertise(*a, scan);
  publish(*a, w, 1);
  publish(*a, w, 2);
  b->poll();
  EXPECT_EQ(a->traffic().at("/scan").messages_sent, 2U);
  EXPECT_EQ(a->traffic().at("/scan").bytes_sent, 8U);
  EXPECT_EQ(b->traffic().at("/scan").messages_received, 2U);
  EXPECT_EQ(b->traffic().at("/scan").bytes_received, 8U);
  EXPECT_EQ(b->traffic().at("/scan").messages_sent, 0U);
}

}  // namespace
}  // namespace tessera::net
