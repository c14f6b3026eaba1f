// tessera localize --ros: the live localization node (nodes/localizer_node.hpp) on Cyclone DDS. It
// localizes what arrives on <ns>/scan and <ns>/odom in a saved session's map until Ctrl-C, SIGTERM
// or --idle-exit-s without a scan, publishing the pose as it goes, then writes what `tessera
// localize --log` writes, with the node's message counts in report.json.
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dds_options.hpp"
#include "session_map.hpp"
#include "tessera/nodes/localizer_node.hpp"

namespace tessera::cli {

void LocalizeCommand::add_ros_options() {
  sub_->add_flag("--ros", ros_,
                 "Live localization node on Cyclone DDS: subscribe <ns>/scan, <ns>/odom, /tf, "
                 "/tf_static; publish <ns>/map (the session's map, once), <ns>/pose with its "
                 "covariance and map -> odom on /tf for every scan that has a pose (with "
                 "--no-odometry: <ns>/scan and the tf alone, the robot followed by its scans, "
                 "and map -> the robot frame)");
  add_live_node_options(*sub_, ns_, domain_, network_, idle_exit_s_);
}

int LocalizeCommand::run_ros() const {
  if (input_.given()) {
    return report_error(usage_error("--ros localizes the topics: give no --log or --bag"));
  }
  if (Status s = input_.check(/*live=*/true); !s) return report_error(s.error());
  Result<Setup> setup = read_setup();
  if (!setup) return report_error(setup.error());
  nodes::LocalizerNodeOptions options;
  options.ns = ns_;
  options.initial_pose = setup->initial_pose;
  options.odometry_from_scans = input_.no_odometry;
  options.base_frame = input_.base_frame;
  Result<slam::ProbabilityGrid> map =
      session_frozen_map(setup->session, options.localizer, session_.string());
  if (!map) return report_error(map.error());

  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::LocalizerNode>> node = nodes::LocalizerNode::create(
      std::move(map).value(), setup->session.map, options, **transport);
  if (!node.ok()) return report_error(node.error());

  const auto t0 = std::chrono::steady_clock::now();
  nodes::LocalizerNode& live = **node;
  const Status ran = run_live_node(
      **transport, idle_exit_s_, !quiet_ && stderr_is_terminal(), [&] { return live.spin_once(); },
      [&] { return live.stats().scans_received; },
      [&] {
        return fmt::format("localize --ros: {} scans received, {} localized",
                           live.stats().scans_received, live.stats().scans_localized);
      });
  if (!ran.ok()) return report_error(ran.error());
  if (Status s = (*node)->finish(); !s) return report_error(s.error());
  const std::vector<slam::LocalizedScan>& scans = (*node)->scans();
  if (scans.empty()) {
    const nodes::LocalizerNodeStats& st = (*node)->stats();
    if (options.odometry_from_scans) {
      return report_error(input_error("localize --ros: no scan arrived"));
    }
    return report_error(input_error(
        st.scans_received > 0 && st.odometry_received == 0
            ? fmt::format("localize --ros: no scan with odometry arrived ({} scans and no "
                          "odometry; --no-odometry follows the robot by its scans)",
                          st.scans_received)
            : std::string("localize --ros: no scan with odometry arrived")));
  }
  const nodes::LocalizerNodeStats& st = (*node)->stats();
  nlohmann::json ros = scan_input_json(st);
  ros["scans_localized"] = st.scans_localized;
  ros["scans_lost"] = st.scans_lost;
  ros["poses_unsure"] = st.poses_unsure;
  return write_outputs(
      scans, (*node)->localizer(), "ros",
      options.odometry_from_scans ? "scan matching (--no-odometry)" : "the odometry topic",
      seconds_since(t0), scans.back().t_s - scans.front().t_s, setup->relations, &ros);
}

}  // namespace tessera::cli
