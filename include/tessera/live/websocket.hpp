#pragma once
// The WebSocket protocol's pieces (RFC 6455) the live view's server needs, without sockets: the
// handshake's accept key, frames out (unmasked, as a server sends them) and a parser of frames in
// (masked, as clients must send them). Pure functions and a byte-fed parser, so they are tested
// without a network.
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace tessera::live {

/// SHA-1 (FIPS 180-4) of `data`: the handshake's only use of it.
[[nodiscard]] std::array<std::uint8_t, 20> sha1(std::span<const std::uint8_t> data);
/// Base64 (RFC 4648, with padding).
[[nodiscard]] std::string base64(std::span<const std::uint8_t> data);
/// Sec-WebSocket-Accept for a client's Sec-WebSocket-Key (RFC 6455 section 4.2.2).
[[nodiscard]] std::string websocket_accept_key(std::string_view client_key);

enum class Opcode : std::uint8_t {
  kContinuation = 0x0,
  kText = 0x1,
  kBinary = 0x2,
  kClose = 0x8,
  kPing = 0x9,
  kPong = 0xA,
};

/// One unfragmented, unmasked frame (FIN set) carrying `payload`.
[[nodiscard]] std::vector<std::uint8_t> encode_frame(Opcode opcode,
                                                     std::span<const std::uint8_t> payload);
[[nodiscard]] std::vector<std::uint8_t> encode_frame(Opcode opcode, std::string_view payload);

/// A whole message from a client: fragments joined, mask removed.
struct WebSocketMessage {
  Opcode opcode = Opcode::kText;
  std::vector<std::uint8_t> payload;
};

/// Parses the frames a client sends, fed bytes as they arrive. Protocol errors (an unmasked
/// frame, a message over the size limit, a fragmented control frame, a continuation without a
/// start, reserved bits or opcodes) end the parser: error() names the problem and the connection
/// is to be closed (close code 1002, or 1009 for the size).
class FrameParser {
 public:
  explicit FrameParser(std::size_t max_message_bytes) : max_message_bytes_(max_message_bytes) {}

  /// Appends `bytes`; the complete messages are then taken with next().
  void feed(std::span<const std::uint8_t> bytes);
  /// The next complete message, if any (control frames come out as they arrive, between the
  /// fragments of a data message, as RFC 6455 section 5.4 allows).
  [[nodiscard]] std::optional<WebSocketMessage> next();
  [[nodiscard]] const std::string& error() const { return error_; }
  /// 1002 (protocol error) or 1009 (message too big) once error() is set.
  [[nodiscard]] std::uint16_t close_code() const { return close_code_; }

 private:
  void fail(std::string message, std::uint16_t code);

  std::size_t max_message_bytes_;
  std::vector<std::uint8_t> buffer_;
  std::size_t consumed_ = 0;
  std::optional<Opcode> fragmented_;  // the opcode of a data message whose fragments are arriving
  std::vector<std::uint8_t> fragments_;
  std::string error_;
  std::uint16_t close_code_ = 0;
};

}  // namespace tessera::live
