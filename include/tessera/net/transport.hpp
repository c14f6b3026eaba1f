#pragma once
// How tessera's nodes talk: ROS 2 topics carrying serialized messages (plain little-endian CDR
// with its encapsulation header, as io/ros_message_encoders.hpp writes and io/ros_messages.hpp
// reads). Two implementations: InProcessBus (in_process_transport.hpp), for the library and most
// tests, and Cyclone DDS (dds_transport.hpp), between processes, with ROS 2's names on the wire.
//
// Delivery is single-threaded and pulled: messages wait in each subscription's keep-last queue
// until the owner calls poll(), which runs the handlers on the caller's thread. A node therefore
// sees its inputs at defined points of its loop, and a run over the in-process bus is
// deterministic.
#include <cstdint>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"
#include "tessera/net/qos.hpp"

namespace tessera::net {

/// A topic as a node declares it: a fully qualified ROS 2 name ("/r1/scan"), the ROS 2 type
/// ("sensor_msgs/msg/LaserScan") and the QoS it offers (writer) or requests (reader).
struct TopicSpec {
  std::string name;
  std::string type;
  Qos qos;
};

/// What went over one topic through one transport, for reports and the throughput benchmark.
struct TopicTraffic {
  std::uint64_t messages_sent = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t messages_received = 0;
  std::uint64_t bytes_received = 0;
};

class Transport {
 public:
  using WriterId = std::uint32_t;
  using ReaderId = std::uint32_t;
  /// Called by poll() with one message's CDR bytes, valid only during the call.
  using Handler = std::function<void(std::span<const std::uint8_t> cdr)>;

  virtual ~Transport() = default;
  Transport(const Transport&) = delete;
  Transport& operator=(const Transport&) = delete;

  /// A writer on `topic`. kInput error for a name that is not a valid ROS 2 topic name or a type
  /// the transport cannot carry.
  [[nodiscard]] Result<WriterId> advertise(const TopicSpec& topic);
  /// The same, storing the writer in `into`: for a node that sets up several in a row.
  [[nodiscard]] Status advertise(const TopicSpec& topic, WriterId& into);
  /// Sends one message. kInput error when `writer` is unknown or (DDS) the bytes do not fit the
  /// type; kRuntime when the middleware fails.
  [[nodiscard]] Status publish(WriterId writer, std::span<const std::uint8_t> cdr);
  /// A reader on `topic`; `handler` runs in poll() for each message received.
  [[nodiscard]] Result<ReaderId> subscribe(const TopicSpec& topic, Handler handler);
  /// The same for a node that never needs the reader's id: it only listens.
  [[nodiscard]] Status listen(const TopicSpec& topic, Handler handler);
  /// Runs the handlers of every message received so far, oldest first per reader, readers in the
  /// order they were created; returns how many messages it delivered.
  std::size_t poll();
  /// Blocks until a message is waiting for poll() or `timeout_s` has passed; true if one waits.
  virtual bool wait(double timeout_s) = 0;
  /// How many readers `writer` is matched with now (same topic and type, compatible QoS), in any
  /// participant: a player waits for its first reader before it sends (0 for an unknown writer).
  [[nodiscard]] virtual std::size_t matched_readers(WriterId writer) const = 0;

  /// Traffic per topic name since the transport was made.
  [[nodiscard]] const std::map<std::string, TopicTraffic, std::less<>>& traffic() const {
    return traffic_;
  }

 protected:
  Transport() = default;
  // The implementation's halves of the public calls, which check names and count traffic.
  [[nodiscard]] virtual Result<WriterId> do_advertise(const TopicSpec& topic) = 0;
  [[nodiscard]] virtual Status do_publish(WriterId writer, std::span<const std::uint8_t> cdr) = 0;
  [[nodiscard]] virtual Result<ReaderId> do_subscribe(const TopicSpec& topic) = 0;
  /// Calls `deliver(reader, cdr)` for each waiting message; returns how many.
  virtual std::size_t do_poll(
      const std::function<void(ReaderId, std::span<const std::uint8_t>)>& deliver) = 0;

 private:
  struct Reader {
    std::string topic;
    Handler handler;
  };
  std::map<WriterId, std::string> writer_topics_;
  std::map<ReaderId, Reader> readers_;
  std::map<std::string, TopicTraffic, std::less<>> traffic_;
};

}  // namespace tessera::net
