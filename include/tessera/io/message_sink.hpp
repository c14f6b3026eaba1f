#pragma once
// Where a run's ROS 2 messages go: an MCAP recording (mcap_writer.hpp) or, later, the live view.
// A sink knows channels (a topic with its message type and ros2msg schema) and takes serialized
// CDR messages on them, stamped in nanoseconds.
#include <cstdint>
#include <span>
#include <string_view>

#include "tessera/core/result.hpp"

namespace tessera {

class MessageSink {
 public:
  using ChannelId = std::uint16_t;

  virtual ~MessageSink() = default;
  /// The channel of `topic` carrying `type` ("nav_msgs/msg/OccupancyGrid") whose ros2msg
  /// definition is `definition`; the same topic and type give the same channel.
  virtual ChannelId channel(std::string_view topic, std::string_view type,
                            std::string_view definition) = 0;
  /// One message on `channel` at `time_ns` (log and publish time). kRuntime errors (disk full).
  [[nodiscard]] virtual Status publish(ChannelId channel, std::int64_t time_ns,
                                       std::span<const std::uint8_t> cdr) = 0;
};

}  // namespace tessera
