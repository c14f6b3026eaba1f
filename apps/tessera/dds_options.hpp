#pragma once
// The DDS options every node command shares (sim, play, slam --ros): --domain and --network.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>

#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"

namespace tessera::cli {

/// --domain (default $ROS_DOMAIN_ID, else 0) and --network (the machine's network with multicast
/// discovery, as ROS 2 does, instead of 127.0.0.1 only).
void add_dds_options(CLI::App& command, std::uint32_t& domain, bool& network);

/// A DDS participant with those options.
[[nodiscard]] Result<std::unique_ptr<net::Transport>> open_dds(std::uint32_t domain, bool network);

}  // namespace tessera::cli
