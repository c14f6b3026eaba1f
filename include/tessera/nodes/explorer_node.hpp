#pragma once
// An exploring robot of a team as a ROS 2 node (issue 14): its own live SLAM (nodes/slam_node.hpp),
// the team's merged map, frontier choice (team/frontier_route.hpp, lecture Algo 9.1 shared by a
// team), and a pure-pursuit path follower (nav/path_follower.hpp) that drives it by cmd_vel. It
// is localised by its SLAM only, never by a simulator's truth. For robot "r1" of a team:
//   SLAM       /r1/scan, /r1/odom, /tf, /tf_static in; /r1/map, /r1/pose, map -> odom out
//   drives     /r1/cmd_vel geometry_msgs/Twist (reliable, depth 10)
//   team       /rK/map of every teammate in (transient local: a late joiner gets them);
//              /team/map out: its own map merged with its teammates' own maps in the team frame
//              (never the cells it filled from theirs: team maps do not feed back), and
//              teammates' /team/map in,
//              which fills the cells no live teammate's map knows (a robot that rejoins gets the
//              map of one that died); /team/claims tessera_msgs/FrontierClaim in and out;
//              /team/status tessera_msgs/RobotStatus out (state, stop reason, pose, counters);
//              /team/command tessera_msgs/TeamCommand in (start, stop, return home)
// The team frame. Known start poses (given to every robot): the frame they are given in, each
// robot's map frame at its start. Unknown start poses: each robot's own map frame; a teammate's
// map, and with it its claims, position and team map, is used once map matching has placed it
// (team/map_match.hpp): an accepted match, confirmed by the next ones on the growing maps.
// Messages that do not decode, a teammate's map of another resolution and claims that are not
// finite are dropped and counted (stats, and RobotStatus::messages_dropped).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/nav/path_follower.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/slam_node.hpp"
#include "tessera/team/frontier_route.hpp"
#include "tessera/team/map_match.hpp"

namespace tessera::nodes {

/// Why an explorer stopped (RobotStatus::reason, ExplorerNode::reason()).
inline constexpr const char* kReasonNoFrontier = "no reachable frontier";
inline constexpr const char* kReasonStoppedByCommand = "stopped by command";
inline constexpr const char* kReasonAtHome = "at home";
inline constexpr const char* kReasonShutDown = "shut down";

/// A robot of the team and where its map frame (its start pose) is in the team frame; nullopt
/// when it is not known (then for every robot of the team: the robots find each other by map
/// matching).
struct TeamMember {
  std::string name;  // "r1": namespace /r1
  std::optional<Pose2> T_team_map;
};

/// Where a robot placed a teammate whose start it did not know.
struct TeammatePlacement {
  std::string robot;
  Pose2 T_team_map;      // the teammate's map frame in this robot's team frame
  double at_s = 0.0;     // robot time
  team::MapMatch match;  // the match that confirmed it
};

struct ExplorerNodeOptions {
  std::string name = "r1";
  /// Every robot of the team, this one included.
  std::vector<TeamMember> team;
  /// SLAM of this robot; its ns is set from `name`. Its map, which the robot plans on, comes at
  /// least every half second of robot time.
  SlamNodeOptions slam{.ns = "",
                       .map_frame = "map",
                       .map_period_wall_s = 1.0,
                       .map_period_stamp_s = 0.5,
                       .queue_depth = 2000,
                       .slam = {}};
  team::FrontierRouteOptions route;
  PathFollowerOptions follower{.max_speed_m_per_s = 0.5,
                               .max_turn_rate_rad_per_s = 1.5,
                               .heading_gain_per_s = 2.0,
                               .turn_in_place_rad = 0.6,
                               .lookahead_m = 0.4,
                               .goal_tolerance_m = 0.15,
                               .slow_down_m = 0.3,
                               .min_speed_fraction = 0.3};
  /// The merged map and the route are checked this often (robot time).
  double plan_period_s = 0.5;
  /// /team/map is published this often (wall clock).
  double team_map_period_wall_s = 2.0;
  /// Robot time (odometry stamps) without 0.1 m of progress along the route before the target
  /// is given up.
  double stuck_s = 8.0;
  /// Robot time with no reachable frontier before the robot reports it has finished.
  double finish_after_s = 4.0;
  /// Robot time between RobotStatus messages.
  double status_period_s = 1.0;
  /// Unknown start poses: each teammate's newest map is matched against the team map at most
  /// this often (robot time) while the teammate is not placed ...
  double match_period_s = 1.0;
  team::MapMatchOptions match;
  /// ... and placed when this many accepted matches in a row agree within
  /// kPlacementAgreement_m and kPlacementAgreement_rad.
  int match_confirmations = 2;
};

/// How far successive matches of one teammate's map may differ and still confirm each other:
/// the maps grow and their SLAM corrects them between matches.
inline constexpr double kPlacementAgreement_m = 0.15;
inline constexpr double kPlacementAgreement_rad = 0.05;

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ExplorerNodeOptions& o);

struct ExplorerNodeStats {
  std::uint64_t teammate_maps_received = 0;
  std::uint64_t teammate_maps_dropped = 0;  // did not decode, another resolution, bad size
  std::uint64_t team_maps_received = 0;     // teammates' /team/map
  std::uint64_t claims_received = 0;
  std::uint64_t claims_dropped = 0;  // did not decode or not finite
  std::uint64_t commands_received = 0;
  std::uint64_t commands_dropped = 0;  // did not decode or an unknown command
  std::uint64_t routes_planned = 0;
  std::uint64_t targets_given_up = 0;  // stuck, or still a frontier once reached
  std::uint64_t team_maps_published = 0;
  std::uint64_t map_matches_tried = 0;  // unknown starts: matches of teammates' maps
  std::uint64_t map_matches_accepted = 0;
};

class ExplorerNode {
 public:
  /// kUsage error for invalid options or a name missing from the team; the SLAM node's and the
  /// transport's errors otherwise. `transport` must outlive the node.
  [[nodiscard]] static Result<std::unique_ptr<ExplorerNode>> create(
      const ExplorerNodeOptions& options, net::Transport& transport);
  ~ExplorerNode();
  ExplorerNode(const ExplorerNode&) = delete;
  ExplorerNode& operator=(const ExplorerNode&) = delete;

  /// Delivers what arrived, runs SLAM on it, re-plans when due and sends the velocity command
  /// for the newest odometry. kRuntime error when SLAM or a publication fails.
  [[nodiscard]] Status spin_once();
  /// Stops the robot, releases its claim and says why in a last status (kReasonShutDown unless
  /// it had finished), then finishes the SLAM (SlamNode::finish).
  [[nodiscard]] Result<slam::LaserSlamResult> finish();

  /// A RobotStatusMessage state constant.
  [[nodiscard]] std::uint8_t state() const;
  /// Why the robot stopped exploring (kReasonNoFrontier, kReasonStoppedByCommand, kReasonAtHome,
  /// kReasonShutDown); empty while it explores.
  [[nodiscard]] const std::string& reason() const;
  /// The team map the robot plans on (team frame); empty before its first map.
  [[nodiscard]] const OccupancyGrid& team_map() const;
  /// T_team_robot from SLAM and odometry; nullopt before the first scan is mapped.
  [[nodiscard]] std::optional<Pose2> pose() const;
  [[nodiscard]] const ExplorerNodeStats& stats() const;
  /// Unknown start poses: the teammates placed so far, in the order they were placed.
  [[nodiscard]] const std::vector<TeammatePlacement>& placements() const;
  [[nodiscard]] const SlamNodeStats& slam_stats() const;
  /// SlamNode::map_latencies_s of the robot's SLAM.
  [[nodiscard]] const std::vector<double>& map_latencies_s() const;

 private:
  struct State;
  explicit ExplorerNode(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
