#include "tessera/live/websocket.hpp"

#include <gtest/gtest.h>

#include <string>

namespace tessera::live {
namespace {

std::span<const std::uint8_t> bytes_of(std::string_view s) {
  return {reinterpret_cast<const std::uint8_t*>(s.data()), s.size()};
}

// A client's frame: masked with `mask`, FIN as given.
std::vector<std::uint8_t> client_frame(Opcode opcode, std::string_view payload, bool fin = true,
                                       std::array<std::uint8_t, 4> mask = {1, 2, 3, 4}) {
  std::vector<std::uint8_t> f = encode_frame(opcode, payload);
  if (!fin) f[0] &= 0x7F;
  const std::size_t header = f.size() - payload.size();
  f[1] |= 0x80;
  std::vector<std::uint8_t> out(f.begin(), f.begin() + static_cast<std::ptrdiff_t>(header));
  out.insert(out.end(), mask.begin(), mask.end());
  for (std::size_t i = 0; i < payload.size(); ++i)
    out.push_back(static_cast<std::uint8_t>(payload[i]) ^ mask[i % 4]);
  return out;
}

TEST(Sha1, MatchesFips180Examples) {
  EXPECT_EQ(base64(sha1(bytes_of("abc"))), "qZk+NkcGgWq6PiVxeFDCbJzQ2J0=");  // a9993e36...
  EXPECT_EQ(base64(sha1(bytes_of(""))), "2jmj7l5rSw0yVb/vlWAYkK/YBwk=");     // da39a3ee...
  // Two blocks: the 56-byte message of FIPS 180-2 appendix A.2.
  EXPECT_EQ(base64(sha1(bytes_of("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"))),
            "hJg+RBw70m66rkqh+VEp5eVGcPE=");  // 84983e44...
}

TEST(Base64, PadsToFourCharacters) {
  EXPECT_EQ(base64(bytes_of("")), "");
  EXPECT_EQ(base64(bytes_of("f")), "Zg==");
  EXPECT_EQ(base64(bytes_of("fo")), "Zm8=");
  EXPECT_EQ(base64(bytes_of("foo")), "Zm9v");
  EXPECT_EQ(base64(bytes_of("foobar")), "Zm9vYmFy");
}

TEST(WebSocket, AcceptKeyIsRfc6455sExample) {
  EXPECT_EQ(websocket_accept_key("dGhlIHNhbXBsZSBub25jZQ=="), "s3pPLMBiTxaQ9kYGzzhZRbK+xOo=");
}

TEST(WebSocket, FramesUseTheShortestLengthField) {
  EXPECT_EQ(encode_frame(Opcode::kText, "hi"), (std::vector<std::uint8_t>{0x81, 2, 'h', 'i'}));
  const std::vector<std::uint8_t> medium = encode_frame(Opcode::kBinary, std::string(300, 'x'));
  ASSERT_EQ(medium.size(), 4u + 300u);
  EXPECT_EQ(medium[1], 126);
  EXPECT_EQ((medium[2] << 8) | medium[3], 300);
  const std::vector<std::uint8_t> large = encode_frame(Opcode::kBinary, std::string(70000, 'x'));
  ASSERT_EQ(large.size(), 10u + 70000u);
  EXPECT_EQ(large[1], 127);
  EXPECT_EQ((large[7] << 16) | (large[8] << 8) | large[9], 70000);
}

TEST(FrameParser, UnmasksMessagesFedAByteAtATime) {
  FrameParser parser(1024);
  const std::vector<std::uint8_t> f = client_frame(Opcode::kText, R"({"op":"subscribe"})");
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_FALSE(parser.next().has_value()) << "at byte " << i;
    parser.feed({&f[i], 1});
  }
  const std::optional<WebSocketMessage> m = parser.next();
  ASSERT_TRUE(m.has_value());
  EXPECT_EQ(m->opcode, Opcode::kText);
  EXPECT_EQ(std::string(m->payload.begin(), m->payload.end()), R"({"op":"subscribe"})");
  EXPECT_TRUE(parser.error().empty());
}

TEST(FrameParser, JoinsFragmentsAndPassesAPingBetweenThem) {
  FrameParser parser(1024);
  std::vector<std::uint8_t> all = client_frame(Opcode::kText, "hel", false);
  const std::vector<std::uint8_t> ping = client_frame(Opcode::kPing, "p");
  const std::vector<std::uint8_t> rest = client_frame(Opcode::kContinuation, "lo");
  all.insert(all.end(), ping.begin(), ping.end());
  all.insert(all.end(), rest.begin(), rest.end());
  parser.feed(all);
  const std::optional<WebSocketMessage> first = parser.next();
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->opcode, Opcode::kPing);
  const std::optional<WebSocketMessage> second = parser.next();
  ASSERT_TRUE(second.has_value());
  EXPECT_EQ(second->opcode, Opcode::kText);
  EXPECT_EQ(std::string(second->payload.begin(), second->payload.end()), "hello");
}

TEST(FrameParser, RefusesUnmaskedOversizedAndOrphanFrames) {
  {
    FrameParser parser(1024);
    parser.feed(encode_frame(Opcode::kText, "x"));  // a server's frame: no mask
    EXPECT_FALSE(parser.next().has_value());
    EXPECT_EQ(parser.close_code(), 1002);
    EXPECT_NE(parser.error().find("mask"), std::string::npos);
  }
  {
    FrameParser parser(10);
    parser.feed(client_frame(Opcode::kBinary, std::string(11, 'x')));
    EXPECT_FALSE(parser.next().has_value());
    EXPECT_EQ(parser.close_code(), 1009);
  }
  {
    FrameParser parser(1024);
    parser.feed(client_frame(Opcode::kContinuation, "x"));
    EXPECT_FALSE(parser.next().has_value());
    EXPECT_EQ(parser.close_code(), 1002);
  }
  {
    FrameParser parser(1024);  // a declared length of 2^63: refused before any allocation
    std::vector<std::uint8_t> f{0x82, 0xFF, 0x80, 0, 0, 0, 0, 0, 0, 0, 1, 2, 3, 4};
    parser.feed(f);
    EXPECT_FALSE(parser.next().has_value());
    EXPECT_EQ(parser.close_code(), 1009);
  }
}

}  // namespace
}  // namespace tessera::live
