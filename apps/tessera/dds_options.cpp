#include "dds_options.hpp"

#include <chrono>
#include <cstdlib>
#include <string>

#include "cli_support.hpp"
#include "tessera/net/dds_transport.hpp"

namespace tessera::cli {

void add_dds_options(CLI::App& command, std::uint32_t& domain, bool& network) {
  if (const char* ros_domain = std::getenv("ROS_DOMAIN_ID"); ros_domain != nullptr) {
    domain = static_cast<std::uint32_t>(std::strtoul(ros_domain, nullptr, 10));
  }
  command.add_option("--domain", domain, "DDS domain (default: $ROS_DOMAIN_ID, else 0)")
      ->check(CLI::Range(0, 232))
      ->capture_default_str();
  command.add_flag("--network", network,
                   "Use the machine's network with multicast discovery, as ROS 2 does (default: "
                   "127.0.0.1 only)");
}

void add_live_node_options(CLI::App& command, std::string& ns, std::uint32_t& domain, bool& network,
                           double& idle_exit_s) {
  command.add_option("--ns", ns, "--ros: namespace of the topics, e.g. /r1 (default: none)");
  add_dds_options(command, domain, network);
  command
      .add_option("--idle-exit-s", idle_exit_s,
                  "--ros: finish when no scan has arrived for this long (0: run until stopped)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
}

Result<std::unique_ptr<net::Transport>> open_dds(std::uint32_t domain, bool network) {
  return net::make_dds_transport({.domain_id = domain, .loopback_only = !network});
}

Status run_live_node(net::Transport& transport, double idle_exit_s, bool show_progress,
                     const std::function<Result<int>()>& spin,
                     const std::function<std::uint64_t()>& scans_received,
                     const std::function<std::string()>& progress_text) {
  const StopSignals stop;
  ProgressLine progress(show_progress);
  auto last_scan = std::chrono::steady_clock::now();
  std::uint64_t received = 0;
  while (!StopSignals::requested()) {
    transport.wait(0.05);
    if (Result<int> spun = spin(); !spun.ok()) return spun.error();
    if (scans_received() != received) {
      received = scans_received();
      last_scan = std::chrono::steady_clock::now();
      progress.show(progress_text());
    }
    if (idle_exit_s > 0.0 && received > 0 && seconds_since(last_scan) > idle_exit_s) break;
  }
  progress.finish();
  return Ok{};
}

nlohmann::json scan_input_json(const nodes::ScanInputStats& s) {
  return {{"scans_received", s.scans_received},
          {"scans_dropped_invalid", s.scans_dropped_invalid},
          {"readings_dropped_invalid", s.readings_dropped_invalid},
          {"scans_dropped_no_pose", s.scans_dropped_no_pose},
          {"scans_dropped_overflow", s.scans_dropped_overflow},
          {"odometry_received", s.odometry_received},
          {"odometry_dropped_invalid", s.odometry_dropped_invalid}};
}

}  // namespace tessera::cli
