#pragma once
// What every node command shares (sim, play, slam --ros, localize --ros): the DDS options
// --domain and --network, the loop of a live node fed by scans, and the report of its scan input.
#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/scan_input.hpp"

namespace tessera::cli {

/// --domain (default $ROS_DOMAIN_ID, else 0) and --network (the machine's network with multicast
/// discovery, as ROS 2 does, instead of 127.0.0.1 only).
void add_dds_options(CLI::App& command, std::uint32_t& domain, bool& network);

/// A live node's options (slam --ros, localize --ros): --ns, the DDS options and --idle-exit-s.
void add_live_node_options(CLI::App& command, std::string& ns, std::uint32_t& domain, bool& network,
                           double& idle_exit_s);

/// A DDS participant with those options.
[[nodiscard]] Result<std::unique_ptr<net::Transport>> open_dds(std::uint32_t domain, bool network);

/// Drives a live node until Ctrl-C, SIGTERM or, with idle_exit_s > 0, that long without a new
/// scan after the first: waits on the transport, calls `spin` (a node's spin_once; its error ends
/// the loop), and shows
/// `progress_text()` on the terminal (when `show_progress`) whenever `scans_received()` changes.
[[nodiscard]] Status run_live_node(net::Transport& transport, double idle_exit_s,
                                   bool show_progress, const std::function<Result<int>()>& spin,
                                   const std::function<std::uint64_t()>& scans_received,
                                   const std::function<std::string()>& progress_text);

/// report.json's counts of the scans and odometry a node received and dropped.
[[nodiscard]] nlohmann::json scan_input_json(const nodes::ScanInputStats& s);

}  // namespace tessera::cli
