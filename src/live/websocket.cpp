#include "tessera/live/websocket.hpp"

#include <bit>
#include <cstring>

namespace tessera::live {

std::array<std::uint8_t, 20> sha1(std::span<const std::uint8_t> data) {
  // FIPS 180-4 section 6.1: 512-bit blocks, the message padded with 0x80, zeros and its length
  // in bits (big-endian).
  std::uint32_t h[5] = {0x67452301, 0xEFCDAB89, 0x98BADCFE, 0x10325476, 0xC3D2E1F0};
  std::vector<std::uint8_t> m(data.begin(), data.end());
  const std::uint64_t bits = static_cast<std::uint64_t>(data.size()) * 8;
  m.push_back(0x80);
  while (m.size() % 64 != 56) m.push_back(0);
  for (int i = 7; i >= 0; --i) m.push_back(static_cast<std::uint8_t>(bits >> (8 * i)));
  for (std::size_t block = 0; block < m.size(); block += 64) {
    std::uint32_t w[80];
    for (int t = 0; t < 16; ++t) {
      const std::uint8_t* p = &m[block + 4 * static_cast<std::size_t>(t)];
      w[t] = (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) |
             (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
    }
    for (int t = 16; t < 80; ++t) w[t] = std::rotl(w[t - 3] ^ w[t - 8] ^ w[t - 14] ^ w[t - 16], 1);
    std::uint32_t a = h[0], b = h[1], c = h[2], d = h[3], e = h[4];
    for (int t = 0; t < 80; ++t) {
      std::uint32_t f = 0, k = 0;
      if (t < 20) {
        f = (b & c) | (~b & d);
        k = 0x5A827999;
      } else if (t < 40) {
        f = b ^ c ^ d;
        k = 0x6ED9EBA1;
      } else if (t < 60) {
        f = (b & c) | (b & d) | (c & d);
        k = 0x8F1BBCDC;
      } else {
        f = b ^ c ^ d;
        k = 0xCA62C1D6;
      }
      const std::uint32_t temp = std::rotl(a, 5) + f + e + k + w[t];
      e = d;
      d = c;
      c = std::rotl(b, 30);
      b = a;
      a = temp;
    }
    h[0] += a;
    h[1] += b;
    h[2] += c;
    h[3] += d;
    h[4] += e;
  }
  std::array<std::uint8_t, 20> out{};
  for (int i = 0; i < 5; ++i)
    for (int j = 0; j < 4; ++j) out[4 * i + j] = static_cast<std::uint8_t>(h[i] >> (24 - 8 * j));
  return out;
}

std::string base64(std::span<const std::uint8_t> data) {
  static constexpr char kAlphabet[] =
      "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((data.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < data.size(); i += 3) {
    const std::size_t n = std::min<std::size_t>(3, data.size() - i);
    std::uint32_t v = std::uint32_t{data[i]} << 16;
    if (n > 1) v |= std::uint32_t{data[i + 1]} << 8;
    if (n > 2) v |= data[i + 2];
    out += kAlphabet[(v >> 18) & 63];
    out += kAlphabet[(v >> 12) & 63];
    out += n > 1 ? kAlphabet[(v >> 6) & 63] : '=';
    out += n > 2 ? kAlphabet[v & 63] : '=';
  }
  return out;
}

std::string websocket_accept_key(std::string_view client_key) {
  // RFC 6455 section 1.3: base64(SHA-1(key + the protocol's GUID)).
  const std::string joined = std::string(client_key) + "258EAFA5-E914-47DA-95CA-C5AB0DC85B11";
  const auto digest = sha1({reinterpret_cast<const std::uint8_t*>(joined.data()), joined.size()});
  return base64(digest);
}

std::vector<std::uint8_t> encode_frame(Opcode opcode, std::span<const std::uint8_t> payload) {
  std::vector<std::uint8_t> out;
  out.reserve(payload.size() + 10);
  out.push_back(static_cast<std::uint8_t>(0x80 | static_cast<std::uint8_t>(opcode)));
  const std::uint64_t n = payload.size();
  if (n < 126) {
    out.push_back(static_cast<std::uint8_t>(n));
  } else if (n <= 0xFFFF) {
    out.push_back(126);
    out.push_back(static_cast<std::uint8_t>(n >> 8));
    out.push_back(static_cast<std::uint8_t>(n));
  } else {
    out.push_back(127);
    for (int i = 7; i >= 0; --i) out.push_back(static_cast<std::uint8_t>(n >> (8 * i)));
  }
  out.insert(out.end(), payload.begin(), payload.end());
  return out;
}

std::vector<std::uint8_t> encode_frame(Opcode opcode, std::string_view payload) {
  return encode_frame(
      opcode, std::span<const std::uint8_t>(reinterpret_cast<const std::uint8_t*>(payload.data()),
                                            payload.size()));
}

void FrameParser::feed(std::span<const std::uint8_t> bytes) {
  if (!error_.empty()) return;
  buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(consumed_));
  consumed_ = 0;
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
}

void FrameParser::fail(std::string message, std::uint16_t code) {
  error_ = std::move(message);
  close_code_ = code;
  buffer_.clear();
  consumed_ = 0;
}

std::optional<WebSocketMessage> FrameParser::next() {
  while (error_.empty()) {
    const std::size_t available = buffer_.size() - consumed_;
    if (available < 2) return std::nullopt;
    const std::uint8_t* p = buffer_.data() + consumed_;
    const bool fin = (p[0] & 0x80) != 0;
    if ((p[0] & 0x70) != 0) {
      fail("reserved bits set in a frame", 1002);
      break;
    }
    const auto opcode = static_cast<Opcode>(p[0] & 0x0F);
    const bool masked = (p[1] & 0x80) != 0;
    std::uint64_t length = p[1] & 0x7F;
    std::size_t header = 2;
    if (length == 126) {
      if (available < 4) return std::nullopt;
      length = (std::uint64_t{p[2]} << 8) | p[3];
      header = 4;
    } else if (length == 127) {
      if (available < 10) return std::nullopt;
      length = 0;
      for (int i = 0; i < 8; ++i) length = (length << 8) | p[2 + i];
      header = 10;
    }
    if (!masked) {
      fail("a client frame without a mask", 1002);
      break;
    }
    const bool control = (static_cast<std::uint8_t>(opcode) & 0x08) != 0;
    if (control && (!fin || length > 125)) {
      fail("a fragmented or oversized control frame", 1002);
      break;
    }
    if (length > max_message_bytes_ || fragments_.size() + length > max_message_bytes_) {
      fail("a message over " + std::to_string(max_message_bytes_) + " bytes", 1009);
      break;
    }
    if (available < header + 4 + length) return std::nullopt;
    const std::uint8_t* mask = p + header;
    const std::uint8_t* data = mask + 4;
    std::vector<std::uint8_t> payload(static_cast<std::size_t>(length));
    for (std::size_t i = 0; i < payload.size(); ++i) payload[i] = data[i] ^ mask[i % 4];
    consumed_ += header + 4 + static_cast<std::size_t>(length);
    switch (opcode) {
      case Opcode::kClose:
      case Opcode::kPing:
      case Opcode::kPong:
        return WebSocketMessage{opcode, std::move(payload)};
      case Opcode::kText:
      case Opcode::kBinary:
        if (fragmented_) {
          fail("a new message before the last one's fragments ended", 1002);
          return std::nullopt;
        }
        if (fin) return WebSocketMessage{opcode, std::move(payload)};
        fragmented_ = opcode;
        fragments_ = std::move(payload);
        continue;
      case Opcode::kContinuation:
        if (!fragmented_) {
          fail("a continuation frame without a message to continue", 1002);
          return std::nullopt;
        }
        fragments_.insert(fragments_.end(), payload.begin(), payload.end());
        if (!fin) continue;
        {
          WebSocketMessage m{*fragmented_, std::move(fragments_)};
          fragmented_.reset();
          fragments_.clear();
          return m;
        }
      default:
        fail("a reserved opcode", 1002);
        return std::nullopt;
    }
  }
  return std::nullopt;
}

}  // namespace tessera::live
