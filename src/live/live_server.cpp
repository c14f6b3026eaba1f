#include "tessera/live/live_server.hpp"

#include <algorithm>
#include <array>
#include <asio.hpp>
#include <cctype>
#include <deque>
#include <map>
#include <nlohmann/json.hpp>
#include <vector>

#include "tessera/core/assert.hpp"
#include "tessera/live/live_page.hpp"
#include "tessera/live/websocket.hpp"

namespace tessera::live {
namespace {

using asio::ip::tcp;
using Bytes = std::vector<std::uint8_t>;

constexpr std::size_t kMaxRequestBytes = 16 * 1024;
constexpr std::size_t kMaxClientMessageBytes = 1 << 20;
constexpr const char* kFinishedStatusId = "tessera.finished";

std::string lower(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

std::string trim(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
    s.remove_suffix(1);
  return std::string(s);
}

struct HttpRequest {
  std::string method;
  std::string target;
  std::map<std::string, std::string> headers;  // names in lower case
};

// The request line and headers of `text` (up to the blank line); nullopt when malformed.
std::optional<HttpRequest> parse_request(std::string_view text) {
  HttpRequest r;
  std::size_t at = text.find("\r\n");
  if (at == std::string_view::npos) return std::nullopt;
  const std::string_view line = text.substr(0, at);
  const std::size_t s1 = line.find(' ');
  const std::size_t s2 = line.rfind(' ');
  if (s1 == std::string_view::npos || s2 == s1) return std::nullopt;
  r.method = std::string(line.substr(0, s1));
  r.target = std::string(line.substr(s1 + 1, s2 - s1 - 1));
  at += 2;
  while (at < text.size()) {
    const std::size_t end = text.find("\r\n", at);
    if (end == std::string_view::npos || end == at) break;
    const std::string_view h = text.substr(at, end - at);
    const std::size_t colon = h.find(':');
    if (colon == std::string_view::npos) return std::nullopt;
    r.headers[lower(trim(h.substr(0, colon)))] = trim(h.substr(colon + 1));
    at = end + 2;
  }
  return r;
}

Bytes to_bytes(std::string_view s) { return Bytes(s.begin(), s.end()); }

Bytes text_frame(const nlohmann::json& j) { return encode_frame(Opcode::kText, j.dump()); }

Bytes finished_status(const std::string& message) {
  return text_frame(
      {{"op", "status"}, {"level", 0}, {"message", message}, {"id", kFinishedStatusId}});
}

}  // namespace

struct LiveServer::Impl {
  struct Channel {
    std::string topic, type, definition;
    Bytes last;
    std::int64_t last_ns = 0;
    bool has_last = false;
  };
  class Connection;

  Impl(const LiveServerOptions& o) : options(o), acceptor(io) {}
  ~Impl();

  void accept();
  nlohmann::json advertisement(std::size_t first_channel) const;
  void remove(Connection* c);

  LiveServerOptions options;
  asio::io_context io;
  tcp::acceptor acceptor;
  std::vector<Channel> channels;  // ChannelId i + 1 is channels[i]
  std::vector<std::shared_ptr<Connection>> connections;
  std::optional<std::string> finished;
  LiveServerStats stats;
};

class LiveServer::Impl::Connection : public std::enable_shared_from_this<Connection> {
 public:
  Connection(Impl& server, tcp::socket socket) : server_(server), socket_(std::move(socket)) {}

  void start() { read(); }
  [[nodiscard]] bool websocket() const { return websocket_; }
  [[nodiscard]] std::size_t subscriptions() const { return subscriptions_.size(); }

  // Queues a control or JSON frame: never dropped.
  void send(Bytes frame) {
    if (closed_) return;
    queued_bytes_ += frame.size();
    queue_.push_back(std::move(frame));
    write();
  }

  // Queues channel `id`'s message to every subscription of it, unless the queue is full.
  void send_message(MessageSink::ChannelId id, std::int64_t time_ns,
                    std::span<const std::uint8_t> cdr) {
    for (const auto& [subscription, channel] : subscriptions_) {
      if (channel != id) continue;
      if (queued_bytes_ > server_.options.max_queued_bytes_per_client) {
        ++server_.stats.messages_dropped;
        continue;
      }
      Bytes m;
      m.reserve(13 + cdr.size());
      m.push_back(0x01);  // messageData
      for (int i = 0; i < 4; ++i) m.push_back(static_cast<std::uint8_t>(subscription >> (8 * i)));
      const auto t = static_cast<std::uint64_t>(time_ns);
      for (int i = 0; i < 8; ++i) m.push_back(static_cast<std::uint8_t>(t >> (8 * i)));
      m.insert(m.end(), cdr.begin(), cdr.end());
      ++server_.stats.messages_sent;
      send(encode_frame(Opcode::kBinary, m));
    }
  }

  void close() {
    if (closed_) return;
    closed_ = true;
    asio::error_code ignored;
    socket_.shutdown(tcp::socket::shutdown_both, ignored);
    socket_.close(ignored);
    server_.remove(this);
  }

 private:
  void read() {
    socket_.async_read_some(asio::buffer(buffer_),
                            [self = shared_from_this()](asio::error_code ec, std::size_t n) {
                              if (ec) {
                                self->close();
                                return;
                              }
                              self->received({self->buffer_.data(), n});
                              if (!self->closed_) self->read();
                            });
  }

  void write() {
    if (writing_ || queue_.empty() || closed_) return;
    writing_ = true;
    asio::async_write(socket_, asio::buffer(queue_.front()),
                      [self = shared_from_this()](asio::error_code ec, std::size_t) {
                        self->writing_ = false;
                        if (self->closed_) return;
                        self->queued_bytes_ -= self->queue_.front().size();
                        self->queue_.pop_front();
                        if (ec) {
                          self->close();
                        } else if (self->queue_.empty() && self->close_after_write_) {
                          self->close();
                        } else {
                          self->write();
                        }
                      });
  }

  void received(std::span<const std::uint8_t> bytes) {
    if (close_after_write_) return;  // answered or closing: the connection ends once that is out
    if (websocket_) {
      parser_.feed(bytes);
      while (auto m = parser_.next()) on_message(*m);
      if (!parser_.error().empty()) close_with(parser_.close_code(), parser_.error());
      return;
    }
    request_.append(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const std::size_t end = request_.find("\r\n\r\n");
    if (end == std::string::npos) {
      if (request_.size() > kMaxRequestBytes) respond(431, "Request Header Fields Too Large", "");
      return;
    }
    const std::optional<HttpRequest> r =
        parse_request(std::string_view(request_).substr(0, end + 2));
    const std::string rest = request_.substr(end + 4);
    request_.clear();
    if (!r) {
      respond(400, "Bad Request", "");
      return;
    }
    handle(*r);
    if (websocket_ && !rest.empty()) received(to_bytes(rest));
  }

  void handle(const HttpRequest& r) {
    const auto header = [&](const char* name) {
      const auto it = r.headers.find(name);
      return it == r.headers.end() ? std::string() : it->second;
    };
    if (r.method != "GET") {
      respond(405, "Method Not Allowed", "");
      return;
    }
    if (lower(header("upgrade")).find("websocket") != std::string::npos) {
      upgrade(header("sec-websocket-key"), header("sec-websocket-protocol"));
      return;
    }
    const std::string path = r.target.substr(0, r.target.find('?'));
    if (path != "/" && path != "/index.html") {
      respond(404, "Not Found", "");
      return;
    }
    ++server_.stats.pages_served;
    respond(200, "OK", live_page_html(), "text/html; charset=utf-8");
  }

  void respond(int code, const char* reason, std::string_view body,
               const char* type = "text/plain; charset=utf-8") {
    std::string head = "HTTP/1.1 " + std::to_string(code) + " " + reason + "\r\n";
    head += "Content-Type: " + std::string(type) + "\r\n";
    head += "Content-Length: " + std::to_string(body.size()) + "\r\n";
    head += "Cache-Control: no-store\r\nConnection: close\r\n\r\n";
    Bytes out = to_bytes(head);
    out.insert(out.end(), body.begin(), body.end());
    close_after_write_ = true;
    send(std::move(out));
  }

  // RFC 6455 section 4.2.2, with one of the Foxglove subprotocols the client offers.
  void upgrade(const std::string& key, const std::string& offered) {
    std::string protocol;
    std::size_t at = 0;
    while (at <= offered.size() && protocol.empty()) {
      const std::size_t comma = std::min(offered.find(',', at), offered.size());
      const std::string p = trim(std::string_view(offered).substr(at, comma - at));
      if (p == "foxglove.websocket.v1" || p == "foxglove.sdk.v1") protocol = p;
      at = comma + 1;
    }
    if (key.empty() || protocol.empty()) {
      respond(400, "Bad Request",
              "a WebSocket client must offer the subprotocol "
              "foxglove.websocket.v1 or foxglove.sdk.v1\n");
      return;
    }
    send(to_bytes(
        "HTTP/1.1 101 Switching Protocols\r\nUpgrade: websocket\r\n"
        "Connection: Upgrade\r\nSec-WebSocket-Accept: " +
        websocket_accept_key(key) + "\r\nSec-WebSocket-Protocol: " + protocol + "\r\n\r\n"));
    websocket_ = true;
    send(text_frame({{"op", "serverInfo"},
                     {"name", "tessera"},
                     {"capabilities", nlohmann::json::array()},
                     {"supportedEncodings", nlohmann::json::array()},
                     {"metadata", {{"tessera.view", server_.options.view}}},
                     {"sessionId", "tessera"}}));
    if (!server_.channels.empty()) send(text_frame(server_.advertisement(0)));
    if (server_.finished) send(finished_status(*server_.finished));
  }

  void on_message(const WebSocketMessage& m) {
    switch (m.opcode) {
      case Opcode::kPing:
        send(encode_frame(Opcode::kPong, m.payload));
        return;
      case Opcode::kClose:
        send(encode_frame(Opcode::kClose, m.payload));
        close_after_write_ = true;
        return;
      case Opcode::kText:
        on_text(std::string(m.payload.begin(), m.payload.end()));
        return;
      default:
        status(2, "tessera's live view takes no binary messages from clients");
        return;
    }
  }

  void on_text(const std::string& text) {
    const nlohmann::json j = nlohmann::json::parse(text, nullptr, false);
    if (j.is_discarded() || !j.is_object() || !j.contains("op") || !j["op"].is_string()) {
      status(2, "a client message that is not a JSON object with an \"op\"");
      return;
    }
    const std::string op = j["op"].get<std::string>();
    if (op == "subscribe" && j.contains("subscriptions") && j["subscriptions"].is_array()) {
      for (const nlohmann::json& s : j["subscriptions"]) subscribe(s);
    } else if (op == "unsubscribe" && j.contains("subscriptionIds") &&
               j["subscriptionIds"].is_array()) {
      for (const nlohmann::json& id : j["subscriptionIds"])
        if (id.is_number_unsigned()) subscriptions_.erase(id.get<std::uint32_t>());
    } else {
      status(1, "unsupported op \"" + op + "\" (tessera's live view only publishes)");
    }
  }

  void subscribe(const nlohmann::json& s) {
    if (!s.is_object() || !s.contains("id") || !s["id"].is_number_unsigned() ||
        !s.contains("channelId") || !s["channelId"].is_number_unsigned()) {
      status(2, "a subscription without an unsigned id and channelId");
      return;
    }
    const auto id = s["id"].get<std::uint64_t>();
    const auto channel = s["channelId"].get<std::uint64_t>();
    if (id > 0xFFFFFFFFu || channel == 0 || channel > server_.channels.size()) {
      status(2, "no channel " + std::to_string(channel));
      return;
    }
    subscriptions_[static_cast<std::uint32_t>(id)] = static_cast<MessageSink::ChannelId>(channel);
    // The channel's last message, as a transient_local subscriber gets it.
    const Channel& c = server_.channels[channel - 1];
    if (c.has_last) send_message(static_cast<MessageSink::ChannelId>(channel), c.last_ns, c.last);
  }

  void status(int level, const std::string& message) {
    send(text_frame({{"op", "status"}, {"level", level}, {"message", message}}));
  }

  void close_with(std::uint16_t code, const std::string& reason) {
    Bytes payload{static_cast<std::uint8_t>(code >> 8), static_cast<std::uint8_t>(code)};
    payload.insert(payload.end(), reason.begin(),
                   reason.begin() + std::min<std::size_t>(reason.size(), 120));
    send(encode_frame(Opcode::kClose, payload));
    close_after_write_ = true;
  }

  friend struct LiveServer::Impl;

  Impl& server_;
  tcp::socket socket_;
  std::array<std::uint8_t, 8192> buffer_{};
  std::string request_;
  bool websocket_ = false;
  FrameParser parser_{kMaxClientMessageBytes};
  std::map<std::uint32_t, MessageSink::ChannelId> subscriptions_;
  std::deque<Bytes> queue_;
  std::size_t queued_bytes_ = 0;
  bool writing_ = false;
  bool close_after_write_ = false;
  bool closed_ = false;
};

LiveServer::Impl::~Impl() {
  asio::error_code ignored;
  acceptor.close(ignored);
  for (const std::shared_ptr<Connection>& c : std::vector(connections)) c->close();
  io.restart();
  io.poll();
}

void LiveServer::Impl::accept() {
  acceptor.async_accept([this](asio::error_code ec, tcp::socket socket) {
    if (ec) {
      if (ec != asio::error::operation_aborted) accept();
      return;
    }
    asio::error_code ignored;
    socket.set_option(tcp::no_delay(true), ignored);
    connections.push_back(std::make_shared<Connection>(*this, std::move(socket)));
    connections.back()->start();
    accept();
  });
}

nlohmann::json LiveServer::Impl::advertisement(std::size_t first_channel) const {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t i = first_channel; i < channels.size(); ++i) {
    list.push_back({{"id", i + 1},
                    {"topic", channels[i].topic},
                    {"encoding", "cdr"},
                    {"schemaName", channels[i].type},
                    {"schema", channels[i].definition},
                    {"schemaEncoding", "ros2msg"}});
  }
  return {{"op", "advertise"}, {"channels", list}};
}

void LiveServer::Impl::remove(Connection* c) {
  std::erase_if(connections, [c](const std::shared_ptr<Connection>& p) { return p.get() == c; });
}

Result<std::unique_ptr<LiveServer>> LiveServer::start(const LiveServerOptions& options) {
  auto impl = std::make_unique<Impl>(options);
  const std::string where = options.address + ":" + std::to_string(options.port);
  asio::error_code ec;
  const asio::ip::address address = asio::ip::make_address(options.address, ec);
  if (ec) return runtime_error("live view: \"" + options.address + "\" is not an IP address");
  const tcp::endpoint endpoint(address, options.port);
  impl->acceptor.open(endpoint.protocol(), ec);
  if (!ec) impl->acceptor.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) impl->acceptor.bind(endpoint, ec);
  if (!ec) impl->acceptor.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) return runtime_error("live view: cannot listen on " + where + ": " + ec.message());
  impl->accept();
  return std::unique_ptr<LiveServer>(new LiveServer(std::move(impl)));
}

LiveServer::LiveServer(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
LiveServer::~LiveServer() = default;

std::uint16_t LiveServer::port() const { return impl_->acceptor.local_endpoint().port(); }

MessageSink::ChannelId LiveServer::channel(std::string_view topic, std::string_view type,
                                           std::string_view definition) {
  for (std::size_t i = 0; i < impl_->channels.size(); ++i) {
    const Impl::Channel& c = impl_->channels[i];
    if (c.topic == topic && c.type == type) return static_cast<ChannelId>(i + 1);
  }
  impl_->channels.push_back(
      {std::string(topic), std::string(type), std::string(definition), {}, 0, false});
  const nlohmann::json advertise = impl_->advertisement(impl_->channels.size() - 1);
  for (const auto& c : std::vector(impl_->connections))
    if (c->websocket()) c->send(text_frame(advertise));
  return static_cast<ChannelId>(impl_->channels.size());
}

Status LiveServer::publish(ChannelId channel, std::int64_t time_ns,
                           std::span<const std::uint8_t> cdr) {
  TESSERA_ASSERT(channel >= 1 && channel <= impl_->channels.size());
  Impl::Channel& c = impl_->channels[channel - 1];
  c.last.assign(cdr.begin(), cdr.end());
  c.last_ns = time_ns;
  c.has_last = true;
  for (const auto& connection : std::vector(impl_->connections))
    if (connection->websocket()) connection->send_message(channel, time_ns, cdr);
  poll();
  return Ok{};
}

void LiveServer::poll() {
  impl_->io.restart();
  impl_->io.poll();
}

void LiveServer::serve_for(std::chrono::milliseconds duration) {
  impl_->io.restart();
  impl_->io.run_for(duration);
}

void LiveServer::finish(const std::string& message) {
  impl_->finished = message;
  for (const auto& c : std::vector(impl_->connections))
    if (c->websocket()) c->send(finished_status(message));
  poll();
}

LiveServerStats LiveServer::stats() const {
  LiveServerStats s = impl_->stats;
  s.clients = 0;
  s.subscriptions = 0;
  for (const auto& c : impl_->connections) {
    if (!c->websocket()) continue;
    ++s.clients;
    s.subscriptions += c->subscriptions();
  }
  return s;
}

}  // namespace tessera::live
