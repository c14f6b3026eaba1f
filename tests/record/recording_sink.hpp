#pragma once
// A MessageSink that keeps what it is given, for the recorder tests.
#include <map>
#include <string>
#include <vector>

#include "tessera/io/message_sink.hpp"

namespace tessera::test {

class RecordingSink final : public MessageSink {
 public:
  struct Message {
    std::string topic;
    std::string type;
    std::int64_t t_ns = 0;
    std::vector<std::uint8_t> cdr;
  };

  ChannelId channel(std::string_view topic, std::string_view type,
                    std::string_view definition) override {
    definitions[std::string(type)] = std::string(definition);
    for (std::size_t i = 0; i < channels.size(); ++i) {
      if (channels[i].first == topic && channels[i].second == type) {
        return static_cast<ChannelId>(i);
      }
    }
    channels.emplace_back(std::string(topic), std::string(type));
    return static_cast<ChannelId>(channels.size() - 1);
  }

  Status publish(ChannelId channel, std::int64_t time_ns,
                 std::span<const std::uint8_t> cdr) override {
    messages.push_back({channels.at(channel).first, channels.at(channel).second, time_ns,
                        std::vector<std::uint8_t>(cdr.begin(), cdr.end())});
    return Ok{};
  }

  [[nodiscard]] std::vector<const Message*> on(const std::string& topic) const {
    std::vector<const Message*> out;
    for (const Message& m : messages) {
      if (m.topic == topic) out.push_back(&m);
    }
    return out;
  }

  std::vector<std::pair<std::string, std::string>> channels;
  std::map<std::string, std::string> definitions;
  std::vector<Message> messages;
};

}  // namespace tessera::test
