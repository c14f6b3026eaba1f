// The in-process bus (in_process_transport.hpp): one shared state, locked by one mutex, holding
// every participant's writers and readers; a publish copies the message into each matched
// reader's keep-last queue and, for a transient-local writer, into the writer's history.
#include "tessera/net/in_process_transport.hpp"

#include <chrono>
#include <condition_variable>
#include <deque>
#include <mutex>
#include <vector>

namespace tessera::net {

using Bytes = std::vector<std::uint8_t>;

struct InProcessBus::State {
  struct Writer {
    std::uint32_t participant = 0;
    TopicSpec topic;
    std::deque<Bytes> history;  // transient local only: the last qos.depth messages
  };
  struct Reader {
    std::uint32_t participant = 0;
    TopicSpec topic;
    std::deque<Bytes> queue;
  };

  std::mutex mutex;
  std::condition_variable arrived;
  std::uint32_t next_participant = 1;
  std::uint32_t next_id = 1;
  std::map<std::uint32_t, Writer> writers;
  std::map<std::uint32_t, Reader> readers;

  static bool matches(const TopicSpec& w, const TopicSpec& r) {
    return w.name == r.name && w.type == r.type && qos_compatible(w.qos, r.qos);
  }
  static void keep_last(std::deque<Bytes>& q, std::uint32_t depth) {
    while (q.size() > std::max<std::uint32_t>(depth, 1)) q.pop_front();
  }
};

namespace {

class InProcessTransport final : public Transport {
 public:
  explicit InProcessTransport(std::shared_ptr<InProcessBus::State> state)
      : state_(std::move(state)) {
    const std::lock_guard lock(state_->mutex);
    participant_ = state_->next_participant++;
  }

  ~InProcessTransport() override {
    // The participant's writers go with it, and with them their transient-local histories.
    const std::lock_guard lock(state_->mutex);
    std::erase_if(state_->writers,
                  [&](const auto& w) { return w.second.participant == participant_; });
    std::erase_if(state_->readers,
                  [&](const auto& r) { return r.second.participant == participant_; });
  }

  std::size_t matched_readers(WriterId writer) const override {
    const std::lock_guard lock(state_->mutex);
    const auto w = state_->writers.find(writer);
    if (w == state_->writers.end()) return 0;
    std::size_t n = 0;
    for (const auto& [id, r] : state_->readers)
      n += State::matches(w->second.topic, r.topic) ? 1 : 0;
    return n;
  }

  bool wait(double timeout_s) override {
    std::unique_lock lock(state_->mutex);
    return state_->arrived.wait_for(lock, std::chrono::duration<double>(timeout_s),
                                    [&] { return has_waiting_locked(); });
  }

 private:
  Result<WriterId> do_advertise(const TopicSpec& topic) override {
    const std::lock_guard lock(state_->mutex);
    const std::uint32_t id = state_->next_id++;
    state_->writers[id] = {participant_, topic, {}};
    return id;
  }

  Status do_publish(WriterId writer, std::span<const std::uint8_t> cdr) override {
    {
      const std::lock_guard lock(state_->mutex);
      auto w = state_->writers.find(writer);
      if (w == state_->writers.end())
        return input_error("publish: no writer " + std::to_string(writer));
      const Bytes bytes(cdr.begin(), cdr.end());
      for (auto& [id, r] : state_->readers) {
        if (!State::matches(w->second.topic, r.topic)) continue;
        r.queue.push_back(bytes);
        State::keep_last(r.queue, r.topic.qos.depth);
      }
      if (w->second.topic.qos.durability == Qos::Durability::kTransientLocal) {
        w->second.history.push_back(bytes);
        State::keep_last(w->second.history, w->second.topic.qos.depth);
      }
    }
    state_->arrived.notify_all();
    return Ok{};
  }

  Result<ReaderId> do_subscribe(const TopicSpec& topic) override {
    const std::lock_guard lock(state_->mutex);
    const std::uint32_t id = state_->next_id++;
    State::Reader reader{participant_, topic, {}};
    // A transient-local reader gets each matched writer's history, as DDS delivers it on match.
    if (topic.qos.durability == Qos::Durability::kTransientLocal) {
      for (const auto& [wid, w] : state_->writers) {
        if (!State::matches(w.topic, topic)) continue;
        for (const Bytes& m : w.history) reader.queue.push_back(m);
      }
      State::keep_last(reader.queue, topic.qos.depth);
    }
    state_->readers[id] = std::move(reader);
    return id;
  }

  std::size_t do_poll(
      const std::function<void(ReaderId, std::span<const std::uint8_t>)>& deliver) override {
    // Take each reader's queue under the lock, deliver outside it: a handler may publish.
    std::vector<std::pair<ReaderId, std::deque<Bytes>>> taken;
    {
      const std::lock_guard lock(state_->mutex);
      for (auto& [id, r] : state_->readers) {
        if (r.participant != participant_ || r.queue.empty()) continue;
        taken.emplace_back(id, std::move(r.queue));
        r.queue.clear();
      }
    }
    std::size_t n = 0;
    for (const auto& [id, queue] : taken) {
      for (const Bytes& m : queue) {
        deliver(id, m);
        ++n;
      }
    }
    return n;
  }

  bool has_waiting_locked() const {
    for (const auto& [id, r] : state_->readers) {
      if (r.participant == participant_ && !r.queue.empty()) return true;
    }
    return false;
  }

  using State = InProcessBus::State;
  std::shared_ptr<State> state_;
  std::uint32_t participant_ = 0;
};

}  // namespace

InProcessBus::InProcessBus() : state_(std::make_shared<State>()) {}
InProcessBus::~InProcessBus() = default;

std::unique_ptr<Transport> InProcessBus::join() {
  return std::make_unique<InProcessTransport>(state_);
}

}  // namespace tessera::net
