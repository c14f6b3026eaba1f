#pragma once
// The live view: a MessageSink that serves a run's ROS 2 messages as they are published, over
// the Foxglove WebSocket protocol (subprotocols foxglove.websocket.v1 and foxglove.sdk.v1:
// serverInfo, advertise, subscribe/unsubscribe, binary message data), so Foxglove and Lichtblick
// show the run as it happens, and the live page (live_page.hpp) on plain HTTP at the same port.
//
// One thread: the server makes progress only inside its calls (publish(), poll(), serve_for()),
// so the run that drives it stays deterministic and nothing needs a lock. A client that reads
// slower than the run publishes loses message data (counted), never the run's time: each client
// has a bounded send queue. The last message of every channel is kept and sent to a client when
// it subscribes (as ROS 2's transient_local maps are), so a page opened late still shows the map.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/io/message_sink.hpp"

namespace tessera::live {

struct LiveServerOptions {
  /// Where to listen; 127.0.0.1 keeps the view on this machine.
  std::string address = "127.0.0.1";
  /// 0: a free port the system picks (port() tells which).
  std::uint16_t port = 0;
  /// What the run is ("explore", "slam", "bob", "fusion"): serverInfo's metadata "tessera.view",
  /// which the page uses to pick its colours (BOB: the paper's Figure 5a).
  std::string view;
  /// Message data queued for one client beyond this is dropped for that client.
  std::size_t max_queued_bytes_per_client = 64u << 20;
};

/// Counts for a report or a test.
struct LiveServerStats {
  std::size_t clients = 0;          // WebSocket clients connected now
  std::size_t subscriptions = 0;    // their subscriptions now
  std::uint64_t pages_served = 0;   // HTTP responses with the page
  std::uint64_t messages_sent = 0;  // message data frames queued to clients
  std::uint64_t messages_dropped = 0;
};

class LiveServer final : public MessageSink {
 public:
  /// Listens on options.address:options.port. kRuntime error when it cannot (port in use).
  [[nodiscard]] static Result<std::unique_ptr<LiveServer>> start(const LiveServerOptions& options);
  ~LiveServer() override;
  LiveServer(const LiveServer&) = delete;
  LiveServer& operator=(const LiveServer&) = delete;

  [[nodiscard]] std::uint16_t port() const;

  ChannelId channel(std::string_view topic, std::string_view type,
                    std::string_view definition) override;
  /// Keeps the message as its channel's last, queues it to the channel's subscribers and lets
  /// the server do what is ready (poll()). Never fails: a network problem is a client's, not
  /// the run's.
  [[nodiscard]] Status publish(ChannelId channel, std::int64_t time_ns,
                               std::span<const std::uint8_t> cdr) override;

  /// Does what is ready (accepts, reads, writes) without waiting.
  void poll();
  /// Serves for `duration` (waits for the network in between).
  void serve_for(std::chrono::milliseconds duration);
  /// Tells every client, now and later, that the run ended: a status message (level info,
  /// id "tessera.finished", text `message`).
  void finish(const std::string& message);
  [[nodiscard]] LiveServerStats stats() const;

 private:
  struct Impl;
  explicit LiveServer(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace tessera::live
