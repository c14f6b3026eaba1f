// tessera explore --ros: one exploring robot of a team (nodes/explorer_node.hpp) in a process of
// its own on Cyclone DDS. It drives the robot rK of a simulator or a real base through
// /rK/cmd_vel until Ctrl-C or SIGTERM (or, with --exit-when-finished, until it has explored all it
// can reach), then writes its own SLAM's outputs, as `tessera slam --ros` does, and report.json
// with its message counts and why it stopped.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "dds_options.hpp"
#include "slam_report.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/nodes/explorer_node.hpp"
#include "tessera/nodes/sim_node.hpp"
#include "tessera/report/core_report.hpp"

namespace tessera::cli {
namespace {

const char* state_name(std::uint8_t s) {
  switch (s) {
    case RobotStatusMessage::kStarting:
      return "starting";
    case RobotStatusMessage::kExploring:
      return "exploring";
    case RobotStatusMessage::kReturningHome:
      return "returning home";
    case RobotStatusMessage::kIdle:
      return "idle";
    case RobotStatusMessage::kFinished:
      return "finished";
    case RobotStatusMessage::kStopped:
      return "stopped";
    default:
      return "failed";
  }
}

// Unknown starts: where the robot placed each teammate, and the match that confirmed it.
nlohmann::json placements_json(const std::vector<nodes::TeammatePlacement>& placements) {
  nlohmann::json out = nlohmann::json::array();
  for (const nodes::TeammatePlacement& p : placements) {
    out.push_back({{"robot", p.robot},
                   {"x_m", p.T_team_map.x},
                   {"y_m", p.T_team_map.y},
                   {"theta_rad", p.T_team_map.theta},
                   {"at_s", p.at_s},
                   {"overlap_m2", p.match.overlap_m2},
                   {"conflict", p.match.conflict},
                   {"wall_agreement", p.match.wall_agreement}});
  }
  return out;
}

nlohmann::json explorer_json(const nodes::ExplorerNode& node) {
  const nodes::ExplorerNodeStats& s = node.stats();
  const nodes::SlamNodeStats& slam = node.slam_stats();
  return {{"state", state_name(node.state())},
          {"reason", node.reason()},
          {"teammate_maps_received", s.teammate_maps_received},
          {"teammate_maps_dropped", s.teammate_maps_dropped},
          {"team_maps_received", s.team_maps_received},
          {"team_maps_published", s.team_maps_published},
          {"claims_received", s.claims_received},
          {"claims_dropped", s.claims_dropped},
          {"commands_received", s.commands_received},
          {"commands_dropped", s.commands_dropped},
          {"routes_planned", s.routes_planned},
          {"targets_given_up", s.targets_given_up},
          {"scans_received", slam.scans_received},
          {"scans_added", slam.scans_added},
          {"scans_dropped_invalid", slam.scans_dropped_invalid},
          {"readings_dropped_invalid", slam.readings_dropped_invalid},
          {"odometry_dropped_invalid", slam.odometry_dropped_invalid},
          {"map_matches_tried", s.map_matches_tried},
          {"map_matches_accepted", s.map_matches_accepted},
          {"placements", placements_json(node.placements())}};
}

// Messages and bytes per topic through this robot's participant.
nlohmann::json traffic_json(const net::Transport& transport) {
  nlohmann::json out = nlohmann::json::object();
  for (const auto& [topic, t] : transport.traffic()) {
    out[topic] = {{"messages_sent", t.messages_sent},
                  {"bytes_sent", t.bytes_sent},
                  {"messages_received", t.messages_received},
                  {"bytes_received", t.bytes_received}};
  }
  return out;
}

// Wall seconds from a scan's receipt to the first map that holds it.
nlohmann::json latency_json(std::vector<double> latencies_s) {
  if (latencies_s.empty()) return nullptr;
  std::sort(latencies_s.begin(), latencies_s.end());
  const auto at = [&](double q) {
    return latencies_s[static_cast<std::size_t>(q * static_cast<double>(latencies_s.size() - 1))];
  };
  return {{"scans", latencies_s.size()},
          {"median_s", at(0.5)},
          {"p99_s", at(0.99)},
          {"max_s", latencies_s.back()}};
}

}  // namespace

void ExploreCommand::add_ros_options() {
  sub_->add_flag("--ros", ros_,
                 "One explorer robot on Cyclone DDS: its own SLAM on <ns>/scan and <ns>/odom, "
                 "frontier routes on the team's merged map, driving by <ns>/cmd_vel; /team/map, "
                 "/team/claims, /team/status out, /team/command in");
  sub_->add_option("--ns", ns_, "--ros: the robot's name and namespace (r1, r2, ...)")
      ->capture_default_str();
  sub_->add_option("--team-start", team_starts_,
                   "--ros: start pose X,Y[,THETA] of every robot of the team in the team frame, "
                   "once per robot, r1 first (default: this robot alone, its start the origin)");
  sub_->add_option("--team", team_size_,
                   "--ros: a team of this many robots r1..rN whose start poses are unknown: "
                   "each finds its teammates by matching their maps against its own (0: the "
                   "starts are given by --team-start, or the robot is alone)")
      ->check(CLI::Range(0, 64))
      ->capture_default_str();
  sub_->add_flag("--exit-when-finished", exit_when_finished_,
                 "--ros: stop once the robot reports it has explored all it can reach");
  add_dds_options(*sub_, domain_, network_);
}

int ExploreCommand::run_ros() const {
  if (world_.file) return report_error(usage_error("--ros explores the topics: give no --world"));
  nodes::ExplorerNodeOptions options;
  options.name = ns_.starts_with('/') ? ns_.substr(1) : ns_;
  if (team_size_ > 0 && !team_starts_.empty()) {
    return report_error(usage_error("--team is a team of unknown starts: give no --team-start"));
  }
  if (team_size_ > 0) {
    for (int i = 0; i < team_size_; ++i) {
      options.team.push_back({nodes::robot_name(i), std::nullopt});
    }
  } else if (team_starts_.empty()) {
    options.team.push_back({options.name, Pose2{}});
  } else {
    for (std::size_t i = 0; i < team_starts_.size(); ++i) {
      Result<Pose2> start = parse_pose(team_starts_[i], "--team-start");
      if (!start.ok()) return report_error(start.error());
      options.team.push_back({nodes::robot_name(static_cast<int>(i)), *start});
    }
  }
  Result<std::unique_ptr<net::Transport>> transport = open_dds(domain_, network_);
  if (!transport.ok()) return report_error(transport.error());
  Result<std::unique_ptr<nodes::ExplorerNode>> node =
      nodes::ExplorerNode::create(options, **transport);
  if (!node.ok()) return report_error(node.error());

  const StopSignals stop;
  ProgressLine progress(!quiet_ && stderr_is_terminal());
  const auto t0 = std::chrono::steady_clock::now();
  while (!StopSignals::requested()) {
    (*transport)->wait(0.01);
    if (Status s = (*node)->spin_once(); !s.ok()) return report_error(s.error());
    progress.show(fmt::format("explore --ros {}: {}, {} scans mapped", options.name,
                              state_name((*node)->state()), (*node)->slam_stats().scans_added));
    if (exit_when_finished_ && (*node)->state() == RobotStatusMessage::kFinished) break;
  }
  progress.finish();
  Result<slam::LaserSlamResult> result = (*node)->finish();
  if (!result.ok()) return report_error(result.error());
  const double wall_s = seconds_since(t0);
  const slam::LaserSlamResult& r = *result;
  nlohmann::json report = {{"options", slam_options_json(options.slam.slam, "ros", ns_)},
                           {"slam", slam_stats_json(r, LaserLog{})},
                           {"explorer", explorer_json(**node)},
                           {"traffic", traffic_json(**transport)},
                           {"map_latency", latency_json((*node)->map_latencies_s())}};
  report["options"]["team_start"] = team_starts_;
  report["options"]["team"] = team_size_;
  const double duration_s =
      r.trajectory.empty() ? 0.0 : r.trajectory.back().t_s - r.trajectory.front().t_s;
  report.update(core_report({"explore", std::nullopt, report["options"], wall_s, duration_s}));
  if (Status s = write_laser_slam_outputs(out_, r, report, nullptr, Pose2{}, nullptr); !s) {
    return report_error(s.error());
  }
  if (!quiet_) {
    fmt::print("explore --ros {}: {}{}{}; {} scans mapped, {} routes, {} targets given up\n",
               options.name, state_name((*node)->state()), (*node)->reason().empty() ? "" : ": ",
               (*node)->reason(), (*node)->slam_stats().scans_added,
               (*node)->stats().routes_planned, (*node)->stats().targets_given_up);
  }
  return kExitOk;
}

}  // namespace tessera::cli
