#pragma once
// The evaluator's view of a team over ROS 2 topics (issue 14): what `tessera team` and the team
// tests read to score a run. It listens only; the robots never see it. It reads
//   /rK/map       every robot's own SLAM map (transient local), merged with the known starts: a
//                 robot that dies keeps its last map here, as the team's does
//   /rK/pose      every robot's SLAM pose (its estimate, in its map frame)
//   /sim/rK/ground_truth  the simulator's truth, which only evaluation reads
//   /team/status  each robot's state, stop reason and counters
//   /clock        simulated time
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/explorer_node.hpp"

namespace tessera::nodes {

struct TeamObserverRobot {
  std::vector<StampedPose2> truth;  // T_world_robot from the simulator
  std::vector<StampedPose2> slam;   // T_team_robot: the robot's pose estimate in the team frame
  std::optional<RobotStatusMessage> status;
  std::uint64_t maps_received = 0;
  std::uint64_t map_bytes_received = 0;
};

class TeamObserver {
 public:
  /// `team`: each robot and its map frame in the team (= world) frame, which the evaluator knows
  /// even when the robots do not (kUsage error for a robot without it). `transport` must outlive
  /// the observer.
  [[nodiscard]] static Result<std::unique_ptr<TeamObserver>> create(
      const std::vector<TeamMember>& team, double resolution_m, net::Transport& transport);
  ~TeamObserver();
  TeamObserver(const TeamObserver&) = delete;
  TeamObserver& operator=(const TeamObserver&) = delete;

  /// Delivers what arrived; returns how many messages.
  std::size_t spin_once();
  /// The robots' maps merged onto `into` (team frame), e.g. the truth's grid.
  [[nodiscard]] OccupancyGrid merged(const GridGeometry& into) const;
  /// True when a map arrived since the last call.
  [[nodiscard]] bool take_map_update();
  [[nodiscard]] double sim_time_s() const;
  [[nodiscard]] const std::map<std::string, TeamObserverRobot>& robots() const;
  /// Maps that did not decode or that the merger refused (another resolution, bad size).
  [[nodiscard]] std::uint64_t maps_dropped() const;

 private:
  struct State;
  explicit TeamObserver(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
