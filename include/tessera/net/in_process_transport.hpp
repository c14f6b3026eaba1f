#pragma once
// The in-process stand-in for a DDS domain: every transport joined to one bus is a participant
// that sees the others' topics, with DDS's matching rules (same topic name and type, compatible
// QoS: qos.hpp), keep-last queues and transient-local histories that a late reader receives and
// that vanish with their writer, as in DDS. Used by the library's nodes in tests and by runs that
// need no second process. Thread-safe: participants may live on different threads.
#include <memory>

#include "tessera/net/transport.hpp"

namespace tessera::net {

class InProcessBus {
 public:
  InProcessBus();
  ~InProcessBus();
  InProcessBus(const InProcessBus&) = delete;
  InProcessBus& operator=(const InProcessBus&) = delete;

  /// A new participant. It may outlive the bus object (the shared state lives on).
  [[nodiscard]] std::unique_ptr<Transport> join();

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace tessera::net
