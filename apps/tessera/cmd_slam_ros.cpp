// tessera slam --ros: the live SLAM node (nodes/slam_node.hpp) on Cyclone DDS. It maps what
// arrives on <ns>/scan and <ns>/odom until Ctrl-C, SIGTERM or --idle-exit-s without a scan, then
// writes what `tessera slam --log` writes, with the node's message counts in report.json. With
// --no-odometry it maps <ns>/scan alone (a robot without odometry, decision 0034).
#include <fmt/format.h>

#include <chrono>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dds_options.hpp"
#include "slam_report.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/nodes/slam_node.hpp"
#include "tessera/report/core_report.hpp"
#include "tessera/report/eval_report.hpp"

namespace tessera::cli {
namespace {

nlohmann::json node_stats_json(const nodes::SlamNodeStats& s) {
  nlohmann::json out = scan_input_json(s);
  out["scans_added"] = s.scans_added;
  out["maps_published"] = s.maps_published;
  return out;
}

}  // namespace

void SlamCommand::add_ros_options() {
  sub_->add_flag("--ros", ros_,
                 "Live SLAM node on Cyclone DDS: subscribe <ns>/scan, <ns>/odom, /tf, /tf_static; "
                 "publish <ns>/map, <ns>/pose and map -> odom on /tf (with --no-odometry: "
                 "<ns>/scan and the tf alone, and map -> the robot frame, --base-frame or the "
                 "laser's)");
  add_live_node_options(*sub_, ns_, domain_, network_, idle_exit_s_);
}

// Shared with run(): a live node maps as the same flags map a log.
slam::LaserSlamOptions SlamCommand::method_options() const {
  slam::LaserSlamOptions options;
  options.loop_closure = !no_loop_closure_;
  options.manhattan = manhattan_;
  if (no_whole_map_) options.final_map_passes = 0;
  options.odometry_calibration.enabled = !no_odometry_calibration_;
  return options;
}

int SlamCommand::run_ros() const {
  if (input_.given() || world_.file) {
    return report_error(usage_error("--ros maps the topics: give no --log, --bag or --world"));
  }
  if (save_) return report_error(usage_error("--save saves a --log, --bag or --world run"));
  if (Status s = input_.check(/*live=*/true); !s) return report_error(s.error());
  nodes::SlamNodeOptions options;
  options.ns = ns_;
  options.slam = method_options();
  options.slam.use_odometry = !input_.no_odometry;
  options.base_frame = input_.base_frame;
  options.slam.map_resolution_m = cell_m_.value_or(0.05);
  std::optional<std::vector<Relation>> relations;
  if (relations_) {
    Result<std::vector<Relation>> read = read_relations(*relations_);
    if (!read) return report_error(read.error());
    relations = std::move(read).value();
  }
  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::SlamNode>> node = nodes::SlamNode::create(options, **transport);
  if (!node.ok()) return report_error(node.error());

  const auto t0 = std::chrono::steady_clock::now();
  nodes::SlamNode& live = **node;
  const Status ran = run_live_node(
      **transport, idle_exit_s_, !quiet_ && stderr_is_terminal(), [&] { return live.spin_once(); },
      [&] { return live.stats().scans_received; },
      [&] {
        return fmt::format("slam --ros: {} scans received, {} mapped", live.stats().scans_received,
                           live.stats().scans_added);
      });
  if (!ran.ok()) return report_error(ran.error());
  Result<slam::LaserSlamResult> result = (*node)->finish();
  if (!result.ok()) {
    Error error = result.error();
    const nodes::SlamNodeStats& st = live.stats();
    if (options.slam.use_odometry && st.scans_received > 0 && st.odometry_received == 0) {
      error.message += "; --no-odometry maps them";
    }
    return report_error(error);
  }
  const double wall_s = seconds_since(t0);
  const slam::LaserSlamResult& r = *result;

  nlohmann::json report = {{"options", slam_options_json(options.slam, "ros", ns_)},
                           {"slam", slam_stats_json(r, LaserLog{})},
                           {"ros", node_stats_json((*node)->stats())}};
  if (!options.slam.use_odometry) report["options"]["base_frame"] = (*node)->odom_frame();
  const double duration_s =
      r.trajectory.empty() ? 0.0 : r.trajectory.back().t_s - r.trajectory.front().t_s;
  report.update(core_report({"slam", std::nullopt, report["options"], wall_s, duration_s}));
  std::optional<RelationMetric> metric;
  if (relations) {
    Result<RelationMetric> scored = relation_metric(r.trajectory, *relations, time_offset_s_);
    if (!scored) return report_error(scored.error());
    metric = *scored;
    report["options"]["relations"] = relations_->string();
    report["options"]["time_offset_s"] = time_offset_s_;
    report["relations"] = relations_report(*metric, {})["relations"];
  }
  if (Status s = write_laser_slam_outputs(out_, r, report, nullptr, Pose2{}, nullptr); !s) {
    return report_error(s.error());
  }
  if (!quiet_) {
    const nodes::SlamNodeStats& st = (*node)->stats();
    fmt::print(
        "slam --ros: {} scans received, {} mapped, {} dropped; {} submaps, {} loop "
        "closures\n",
        st.scans_received, st.scans_added,
        st.scans_dropped_invalid + st.scans_dropped_no_pose + st.scans_dropped_overflow,
        r.stats.submaps, r.stats.loop_closures);
    if (metric) print_relations_summary(*metric);
    fmt::print("outputs: {}/map.yaml map.pgm map.png trajectory.txt graph.g2o report.json\n",
               out_.string());
  }
  return kExitOk;
}

}  // namespace tessera::cli
