#pragma once
// Live localization in a saved map as a ROS 2 node (issue 16: `tessera localize --ros`), the
// localizer of slam/localizer.hpp fed from topics instead of a file, as AMCL or Cartographer's
// pure localization run beside a robot's driver. In namespace `ns` ("/r1", or "" for none):
//   subscribes <ns>/scan, <ns>/odom, /tf_static and /tf, paired as nodes/scan_input.hpp says
//   publishes  <ns>/map nav_msgs/OccupancyGrid once, the frozen map (reliable, transient local: a
//              late planner or viewer gets it);
//              <ns>/pose geometry_msgs/PoseWithCovarianceStamped (T_map_base and its covariance)
//              and /tf map -> odom (REP-105) for every scan that has a pose. A pose that is not
//              confident (its scans have just stopped fitting the map, or it is tracked on little
//              of the map, beyond where the session went) carries unsure_variance on top of the
//              refinement's covariance, so that a consumer weighing by covariance (a planner, an
//              EKF) trusts it little. A robot not found yet, or lost, publishes nothing: a planner
//              is never handed a guess.
// A robot without odometry (odometry_from_scans): <ns>/odom is not read, the robot is followed
// between scans by odometry made from the scans (slam::ScanMatchedOdometry, decision 0034), and
// /tf carries map -> the robot frame.
// The node keeps every scan's result for the run's outputs (about 150 bytes a scan).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/scan_input.hpp"
#include "tessera/slam/localizer.hpp"

namespace tessera::nodes {

struct LocalizerNodeOptions {
  std::string ns{};  // "" or "/r1"
  std::string map_frame = "map";
  /// Scans waiting for odometry or for the localizer: beyond this, the oldest is dropped.
  std::uint32_t queue_depth = 2000;
  slam::LocalizerOptions localizer{};
  /// Added to the covariance of a pose that is not confident: (0.5 m)^2 on x and y, (0.2 rad)^2
  /// on the heading.
  double unsure_variance_m2 = 0.25;
  double unsure_variance_rad2 = 0.04;
  /// T_map_robot of the first scan; nullopt: found by global relocalization.
  std::optional<Pose2> initial_pose{};
  /// Scans alone: the odometry is made from the scans (local SLAM alone, restarted every few
  /// thousand scans so that memory stays bounded).
  bool odometry_from_scans = false;
  /// With odometry_from_scans: the robot frame, where the tf places the laser; empty: the
  /// laser's own frame (ScanInputOptions::base_frame).
  std::string base_frame{};
};

/// What came in (ScanInputStats) and what became of it.
struct LocalizerNodeStats : ScanInputStats {
  std::uint64_t scans_localized = 0;  // scans that got a pose
  std::uint64_t scans_lost = 0;       // scans taken with no pose
  std::uint64_t poses_unsure = 0;     // published with the added variance (not confident)
};

class LocalizerNode {
 public:
  /// `map` is the frozen map to localize in and `picture` what is published on <ns>/map (the
  /// session's map). kUsage error for invalid localizer options; kInput for a namespace that is
  /// no ROS 2 name; the transport's errors otherwise. `transport` must outlive the node.
  [[nodiscard]] static Result<std::unique_ptr<LocalizerNode>> create(
      slam::ProbabilityGrid map, const OccupancyGrid& picture, const LocalizerNodeOptions& options,
      net::Transport& transport);
  ~LocalizerNode();
  LocalizerNode(const LocalizerNode&) = delete;
  LocalizerNode& operator=(const LocalizerNode&) = delete;

  /// Delivers what has arrived and localizes every scan whose odometry is known, publishing its
  /// pose and map -> odom. Returns how many scans it took; kRuntime error when a
  /// publication fails.
  [[nodiscard]] Result<int> spin_once();
  /// Takes the scans still waiting (odometry clamped to the last message). Call once, at the end.
  [[nodiscard]] Status finish();

  /// Every scan taken, in order, with its state, pose, confidence and covariance.
  [[nodiscard]] const std::vector<slam::LocalizedScan>& scans() const;
  [[nodiscard]] const LocalizerNodeStats& stats() const;
  [[nodiscard]] const slam::Localizer& localizer() const;

 private:
  struct State;
  explicit LocalizerNode(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
