#pragma once
// Keeps tests that use DDS apart when ctest runs them in parallel: each test process takes a DDS
// domain and a topic prefix from its process id, and the transport is loopback only (no
// multicast), so two tests meet only if both their domains and their topic names agree.
#include <unistd.h>

#include <cstdint>
#include <string>

namespace tessera::support {

/// A domain in 1..200 (0, ROS 2's default, stays free for anything a developer runs by hand).
[[nodiscard]] inline std::uint32_t test_dds_domain() {
  return 1 + static_cast<std::uint32_t>(::getpid()) % 200;
}

/// "/t<pid>": prefix for the topic names of one test process.
[[nodiscard]] inline std::string test_topic_prefix() { return "/t" + std::to_string(::getpid()); }

}  // namespace tessera::support
