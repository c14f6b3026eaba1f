#pragma once
// What every node command shares (sim, play, slam --ros, localize --ros): the DDS options
// --domain and --network, and the report of a node's scan input.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <memory>
#include <nlohmann/json.hpp>

#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/scan_input.hpp"

namespace tessera::cli {

/// --domain (default $ROS_DOMAIN_ID, else 0) and --network (the machine's network with multicast
/// discovery, as ROS 2 does, instead of 127.0.0.1 only).
void add_dds_options(CLI::App& command, std::uint32_t& domain, bool& network);

/// A DDS participant with those options.
[[nodiscard]] Result<std::unique_ptr<net::Transport>> open_dds(std::uint32_t domain, bool network);

/// report.json's counts of the scans and odometry a node received and dropped.
[[nodiscard]] nlohmann::json scan_input_json(const nodes::ScanInputStats& s);

}  // namespace tessera::cli
