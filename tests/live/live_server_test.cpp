#include "tessera/live/live_server.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <asio.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "tessera/live/websocket.hpp"

namespace tessera::live {
namespace {

using asio::ip::tcp;
using ::testing::HasSubstr;

// A plain TCP client in the test's thread: every wait lets the server run (it only makes
// progress inside its own calls), then reads what arrived.
class Client {
 public:
  Client(LiveServer& server, asio::io_context& io) : server_(server), socket_(io) {
    socket_.connect({asio::ip::make_address("127.0.0.1"), server.port()});
  }
  void send(std::string_view bytes) { asio::write(socket_, asio::buffer(bytes)); }
  void send(const std::vector<std::uint8_t>& bytes) { asio::write(socket_, asio::buffer(bytes)); }
  // Serves and reads until `done(received)` or about two seconds.
  template <typename Done>
  bool wait(Done done) {
    for (int i = 0; i < 200; ++i) {
      server_.serve_for(std::chrono::milliseconds(10));
      asio::error_code ec;
      while (socket_.available(ec) > 0 && !ec) {
        std::array<char, 65536> buffer{};
        const std::size_t n = socket_.read_some(asio::buffer(buffer), ec);
        received.append(buffer.data(), n);
      }
      if (done(received)) return true;
    }
    return false;
  }
  std::string received;

 private:
  LiveServer& server_;
  tcp::socket socket_;
};

// A client frame: masked, as RFC 6455 requires of clients.
std::vector<std::uint8_t> masked(Opcode opcode, std::string_view payload) {
  std::vector<std::uint8_t> f = encode_frame(opcode, payload);
  const std::size_t header = f.size() - payload.size();
  std::vector<std::uint8_t> out(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(header));
  out[1] |= 0x80;
  const std::array<std::uint8_t, 4> mask{0x12, 0x34, 0x56, 0x78};
  out.insert(out.end(), mask.begin(), mask.end());
  for (std::size_t i = 0; i < payload.size(); ++i)
    out.push_back(static_cast<std::uint8_t>(payload[i]) ^ mask[i % 4]);
  return out;
}

// The server's frames in `bytes` after the HTTP response head.
std::vector<WebSocketMessage> frames_after_head(const std::string& bytes) {
  std::vector<WebSocketMessage> out;
  std::size_t at = bytes.find("\r\n\r\n");
  if (at == std::string::npos) return out;
  at += 4;
  while (at + 2 <= bytes.size()) {
    const auto* p = reinterpret_cast<const std::uint8_t*>(bytes.data()) + at;
    std::uint64_t n = p[1] & 0x7F;
    std::size_t header = 2;
    if (n == 126) {
      n = (std::uint64_t{p[2]} << 8) | p[3];
      header = 4;
    } else if (n == 127) {
      n = 0;
      for (int i = 0; i < 8; ++i) n = (n << 8) | p[2 + i];
      header = 10;
    }
    if (at + header + n > bytes.size()) break;
    out.push_back(
        {static_cast<Opcode>(p[0] & 0x0F), std::vector<std::uint8_t>(p + header, p + header + n)});
    at += header + static_cast<std::size_t>(n);
  }
  return out;
}

std::vector<nlohmann::json> json_ops(const std::vector<WebSocketMessage>& frames) {
  std::vector<nlohmann::json> out;
  for (const WebSocketMessage& f : frames)
    if (f.opcode == Opcode::kText)
      out.push_back(nlohmann::json::parse(std::string(f.payload.begin(), f.payload.end())));
  return out;
}

std::vector<WebSocketMessage> binaries(const std::vector<WebSocketMessage>& frames) {
  std::vector<WebSocketMessage> out;
  for (const WebSocketMessage& f : frames)
    if (f.opcode == Opcode::kBinary) out.push_back(f);
  return out;
}

constexpr const char* kUpgrade =
    "GET / HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
    "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n"
    "Sec-WebSocket-Protocol: foxglove.websocket.v1\r\n\r\n";

std::unique_ptr<LiveServer> started(LiveServerOptions o = {}) {
  Result<std::unique_ptr<LiveServer>> s = LiveServer::start(o);
  EXPECT_TRUE(static_cast<bool>(s)) << (s ? "" : s.error().message);
  return std::move(s).value();
}

TEST(LiveServer, ServesThePageOverHttp) {
  auto server = started();
  asio::io_context io;
  Client client(*server, io);
  client.send("GET / HTTP/1.1\r\nHost: 127.0.0.1\r\n\r\n");
  ASSERT_TRUE(
      client.wait([](const std::string& r) { return r.find("</html>") != std::string::npos; }));
  EXPECT_THAT(client.received, HasSubstr("HTTP/1.1 200 OK"));
  EXPECT_THAT(client.received, HasSubstr("text/html"));
  EXPECT_THAT(client.received, HasSubstr("foxglove.websocket.v1"));  // the page connects back
  EXPECT_EQ(server->stats().pages_served, 1u);

  Client other(*server, io);
  other.send("GET /nothing HTTP/1.1\r\n\r\n");
  ASSERT_TRUE(
      other.wait([](const std::string& r) { return r.find("\r\n\r\n") != std::string::npos; }));
  EXPECT_THAT(other.received, HasSubstr("404"));
}

TEST(LiveServer, SpeaksTheFoxgloveProtocol) {
  LiveServerOptions o;
  o.view = "explore";
  auto server = started(o);
  const MessageSink::ChannelId map =
      server->channel("/map", "nav_msgs/msg/OccupancyGrid", "int8[] data");
  ASSERT_TRUE(server->publish(map, 5, std::vector<std::uint8_t>{0, 1, 0, 0, 7}));

  asio::io_context io;
  Client client(*server, io);
  client.send(kUpgrade);
  ASSERT_TRUE(
      client.wait([](const std::string& r) { return json_ops(frames_after_head(r)).size() >= 2; }));
  EXPECT_THAT(client.received, HasSubstr("HTTP/1.1 101"));
  EXPECT_THAT(client.received, HasSubstr("Sec-WebSocket-Accept: s3pPLMBiTxaQ9kYGzzhZRbK+xOo="));
  EXPECT_THAT(client.received, HasSubstr("Sec-WebSocket-Protocol: foxglove.websocket.v1"));
  std::vector<nlohmann::json> ops = json_ops(frames_after_head(client.received));
  EXPECT_EQ(ops[0]["op"], "serverInfo");
  EXPECT_EQ(ops[0]["metadata"]["tessera.view"], "explore");
  ASSERT_EQ(ops[1]["op"], "advertise");
  ASSERT_EQ(ops[1]["channels"].size(), 1u);
  EXPECT_EQ(ops[1]["channels"][0]["topic"], "/map");
  EXPECT_EQ(ops[1]["channels"][0]["encoding"], "cdr");
  EXPECT_EQ(ops[1]["channels"][0]["schemaEncoding"], "ros2msg");
  EXPECT_EQ(ops[1]["channels"][0]["schemaName"], "nav_msgs/msg/OccupancyGrid");
  const int channel_id = ops[1]["channels"][0]["id"];

  // Subscribing delivers the channel's last message at once (a late viewer still sees the map).
  client.send(masked(Opcode::kText, R"({"op":"subscribe","subscriptions":[{"id":7,"channelId":)" +
                                        std::to_string(channel_id) + "}]}"));
  ASSERT_TRUE(
      client.wait([](const std::string& r) { return !binaries(frames_after_head(r)).empty(); }));
  std::vector<WebSocketMessage> data = binaries(frames_after_head(client.received));
  ASSERT_EQ(data[0].payload.size(), 1u + 4u + 8u + 5u);
  EXPECT_EQ(data[0].payload[0], 0x01);  // messageData
  EXPECT_EQ(data[0].payload[1], 7);     // subscription id, little-endian
  EXPECT_EQ(data[0].payload[5], 5);     // timestamp (ns), little-endian
  EXPECT_EQ(data[0].payload[17], 7);
  EXPECT_EQ(server->stats().subscriptions, 1u);

  // A new message and a new channel reach the subscribed client as they are published.
  ASSERT_TRUE(server->publish(map, 9, std::vector<std::uint8_t>{0, 1, 0, 0, 8}));
  server->channel("/tf", "tf2_msgs/msg/TFMessage", "");
  server->finish("run finished");
  ASSERT_TRUE(client.wait(
      [](const std::string& r) { return r.find("tessera.finished") != std::string::npos; }));
  const std::vector<WebSocketMessage> frames = frames_after_head(client.received);
  data = binaries(frames);
  ASSERT_EQ(data.size(), 2u);
  EXPECT_EQ(data[1].payload[5], 9);
  ops = json_ops(frames);
  EXPECT_EQ(ops[2]["op"], "advertise");
  EXPECT_EQ(ops[2]["channels"][0]["topic"], "/tf");
  EXPECT_EQ(ops[3]["op"], "status");
  EXPECT_EQ(ops[3]["id"], "tessera.finished");

  // Unsubscribed: no more data; a ping is answered.
  client.send(masked(Opcode::kText, R"({"op":"unsubscribe","subscriptionIds":[7]})"));
  client.send(masked(Opcode::kPing, "hi"));
  ASSERT_TRUE(client.wait([](const std::string& r) {
    for (const WebSocketMessage& f : frames_after_head(r))
      if (f.opcode == Opcode::kPong) return true;
    return false;
  }));
  ASSERT_TRUE(server->publish(map, 11, std::vector<std::uint8_t>{0, 1, 0, 0, 9}));
  client.wait([](const std::string&) { return false; });
  EXPECT_EQ(binaries(frames_after_head(client.received)).size(), 2u);
}

TEST(LiveServer, RefusesAWebSocketWithoutAFoxgloveSubprotocol) {
  auto server = started();
  asio::io_context io;
  Client client(*server, io);
  client.send(
      "GET / HTTP/1.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
      "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n");
  ASSERT_TRUE(
      client.wait([](const std::string& r) { return r.find("subprotocol") != std::string::npos; }));
  EXPECT_THAT(client.received, HasSubstr("HTTP/1.1 400"));
}

TEST(LiveServer, BadClientMessagesGetAStatusNotACrash) {
  auto server = started();
  server->channel("/map", "nav_msgs/msg/OccupancyGrid", "");
  asio::io_context io;
  Client client(*server, io);
  client.send(kUpgrade);
  client.send(masked(Opcode::kText, "{not json"));
  client.send(
      masked(Opcode::kText, R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":99}]})"));
  client.send(masked(Opcode::kText, R"({"op":"subscribe","subscriptions":[{"id":-1}]})"));
  ASSERT_TRUE(client.wait([](const std::string& r) {
    int statuses = 0;
    for (const nlohmann::json& j : json_ops(frames_after_head(r))) statuses += j["op"] == "status";
    return statuses == 3;
  }));
  EXPECT_EQ(server->stats().subscriptions, 0u);
  // A frame without a mask ends the connection with close code 1002.
  client.send(encode_frame(Opcode::kText, "{}"));
  ASSERT_TRUE(client.wait([](const std::string& r) {
    for (const WebSocketMessage& f : frames_after_head(r))
      if (f.opcode == Opcode::kClose) return f.payload.size() >= 2 && f.payload[1] == 0xEA;  // 1002
    return false;
  }));
}

TEST(LiveServer, AClientThatDoesNotReadLosesMessagesNotTheRunsTime) {
  LiveServerOptions o;
  o.max_queued_bytes_per_client = 1 << 20;
  auto server = started(o);
  const MessageSink::ChannelId big = server->channel("/big", "nav_msgs/msg/OccupancyGrid", "");
  asio::io_context io;
  tcp::socket silent(io);
  silent.connect({asio::ip::make_address("127.0.0.1"), server->port()});
  asio::write(silent, asio::buffer(std::string_view(kUpgrade)));
  server->serve_for(std::chrono::milliseconds(50));
  const std::string subscribe =
      R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":)" + std::to_string(big) + "}]}";
  asio::write(silent, asio::buffer(masked(Opcode::kText, subscribe)));
  server->serve_for(std::chrono::milliseconds(50));
  ASSERT_EQ(server->stats().subscriptions, 1u);
  const std::vector<std::uint8_t> payload(1 << 20, 0x55);
  for (int i = 0; i < 200; ++i) ASSERT_TRUE(server->publish(big, i, payload));  // 200 MB
  const LiveServerStats s = server->stats();
  EXPECT_GT(s.messages_dropped, 0u);
  EXPECT_LT(s.messages_sent, 200u);
}

TEST(LiveServer, APortInUseIsARuntimeError) {
  auto first = started();
  LiveServerOptions o;
  o.port = first->port();
  // reuse_address lets a port in TIME_WAIT be bound again, not one another socket listens on.
  Result<std::unique_ptr<LiveServer>> second = LiveServer::start(o);
  ASSERT_FALSE(second);
  EXPECT_EQ(second.error().kind, ErrorKind::kRuntime);
  EXPECT_THAT(second.error().message, HasSubstr(std::to_string(o.port)));
  o.address = "not-an-address";
  o.port = 0;
  EXPECT_FALSE(LiveServer::start(o));
}

}  // namespace
}  // namespace tessera::live
