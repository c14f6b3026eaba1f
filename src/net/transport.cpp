// The checks and counting every transport shares (transport.hpp), around the implementation's
// do_* calls.
#include "tessera/net/transport.hpp"

#include <utility>

#include "tessera/net/ros_names.hpp"

namespace tessera::net {

namespace {

Status check_topic(const TopicSpec& topic) {
  if (Status name = check_topic_name(topic.name); !name.ok()) return name;
  if (Result<std::string> type = dds_type_name(topic.type); !type.ok()) {
    return input_error("topic " + topic.name + ": " + type.error().message);
  }
  return Ok{};
}

}  // namespace

Result<Transport::WriterId> Transport::advertise(const TopicSpec& topic) {
  if (Status ok = check_topic(topic); !ok.ok()) return ok.error();
  Result<WriterId> id = do_advertise(topic);
  if (id.ok()) writer_topics_[*id] = topic.name;
  return id;
}

Status Transport::advertise(const TopicSpec& topic, WriterId& into) {
  Result<WriterId> id = advertise(topic);
  if (!id.ok()) return id.error();
  into = *id;
  return Ok{};
}

Status Transport::listen(const TopicSpec& topic, Handler handler) {
  Result<ReaderId> id = subscribe(topic, std::move(handler));
  if (!id.ok()) return id.error();
  return Ok{};
}

Status Transport::publish(WriterId writer, std::span<const std::uint8_t> cdr) {
  const auto topic = writer_topics_.find(writer);
  if (topic == writer_topics_.end()) {
    return input_error("publish: no writer " + std::to_string(writer));
  }
  Status sent = do_publish(writer, cdr);
  if (!sent.ok()) return sent;
  // The transparent comparator finds the entry without building a key string per message.
  auto counters = traffic_.find(topic->second);
  if (counters == traffic_.end()) counters = traffic_.emplace(topic->second, TopicTraffic{}).first;
  ++counters->second.messages_sent;
  counters->second.bytes_sent += cdr.size();
  return Ok{};
}

Result<Transport::ReaderId> Transport::subscribe(const TopicSpec& topic, Handler handler) {
  if (Status ok = check_topic(topic); !ok.ok()) return ok.error();
  Result<ReaderId> id = do_subscribe(topic);
  if (id.ok()) readers_[*id] = Reader{topic.name, std::move(handler)};
  return id;
}

std::size_t Transport::poll() {
  return do_poll([this](ReaderId id, std::span<const std::uint8_t> cdr) {
    const auto reader = readers_.find(id);
    if (reader == readers_.end()) return;
    auto counters = traffic_.find(reader->second.topic);
    if (counters == traffic_.end()) {
      counters = traffic_.emplace(reader->second.topic, TopicTraffic{}).first;
    }
    ++counters->second.messages_received;
    counters->second.bytes_received += cdr.size();
    reader->second.handler(cdr);
  });
}

}  // namespace tessera::net
