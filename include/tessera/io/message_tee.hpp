#pragma once
// One MessageSink that forwards to several: a run recorded to an MCAP file and served live at
// once. Each channel is opened on every sink; a publish goes to all of them and fails with the
// first sink that fails (the others have still received it).
#include <vector>

#include "tessera/io/message_sink.hpp"

namespace tessera {

class MessageTee final : public MessageSink {
 public:
  /// The sinks must outlive the tee.
  explicit MessageTee(std::vector<MessageSink*> sinks) : sinks_(std::move(sinks)) {}

  ChannelId channel(std::string_view topic, std::string_view type,
                    std::string_view definition) override;
  [[nodiscard]] Status publish(ChannelId channel, std::int64_t time_ns,
                               std::span<const std::uint8_t> cdr) override;

 private:
  struct Channel {
    std::string topic, type;
    std::vector<ChannelId> ids;  // per sink
  };
  std::vector<MessageSink*> sinks_;
  std::vector<Channel> channels_;  // the tee's ChannelId i + 1
};

}  // namespace tessera
