#include "tessera/io/message_tee.hpp"

#include "tessera/core/assert.hpp"

namespace tessera {

MessageSink::ChannelId MessageTee::channel(std::string_view topic, std::string_view type,
                                           std::string_view definition) {
  for (std::size_t i = 0; i < channels_.size(); ++i)
    if (channels_[i].topic == topic && channels_[i].type == type)
      return static_cast<ChannelId>(i + 1);
  Channel c{std::string(topic), std::string(type), {}};
  for (MessageSink* sink : sinks_) c.ids.push_back(sink->channel(topic, type, definition));
  channels_.push_back(std::move(c));
  return static_cast<ChannelId>(channels_.size());
}

Status MessageTee::publish(ChannelId channel, std::int64_t time_ns,
                           std::span<const std::uint8_t> cdr) {
  TESSERA_ASSERT(channel >= 1 && channel <= channels_.size());
  const Channel& c = channels_[channel - 1];
  Status first = Ok{};
  for (std::size_t i = 0; i < sinks_.size(); ++i) {
    Status s = sinks_[i]->publish(c.ids[i], time_ns, cdr);
    if (!s && first.ok()) first = std::move(s);
  }
  return first;
}

}  // namespace tessera
