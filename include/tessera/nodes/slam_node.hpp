#pragma once
// Live laser SLAM as a ROS 2 node (issue 14), the pipeline of slam/laser_slam.hpp fed from topics
// instead of a file. In namespace `ns` ("/r1", or "" for none):
//   subscribes <ns>/scan, <ns>/odom, /tf_static and /tf, paired as nodes/scan_input.hpp says
//              (a scan is added once its odometry is known); with slam.use_odometry off, <ns>/scan
//              and the tf alone (scans alone, decision 0034)
//   publishes  <ns>/map nav_msgs/OccupancyGrid (reliable, transient local: a late viewer gets it)
//              at least once per map_period_wall_s while scans arrive, /tf map -> odom (REP-105;
//              without odometry map -> the robot frame), and <ns>/pose
//              geometry_msgs/PoseWithCovarianceStamped (T_map_base per scan).
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose_interpolation.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/nodes/scan_input.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera::nodes {

struct SlamNodeOptions {
  std::string ns;  // "" or "/r1"
  std::string map_frame = "map";
  double map_period_wall_s = 1.0;
  /// Also publish the map whenever the scans' stamps have advanced this much since the last one
  /// (0: off): a robot that plans on its map in simulated time faster than real time.
  double map_period_stamp_s = 0.0;
  /// Scans waiting for odometry or for SLAM: beyond this, the oldest is dropped and counted.
  std::uint32_t queue_depth = 2000;
  slam::LaserSlamOptions slam{};
  /// With slam.use_odometry off: the robot frame, where the tf places the laser; empty: the
  /// laser's own frame (ScanInputOptions::base_frame).
  std::string base_frame{};
};

/// What came in (ScanInputStats) and what became of it.
struct SlamNodeStats : ScanInputStats {
  std::uint64_t scans_added = 0;
  std::uint64_t maps_published = 0;
};

class SlamNode {
 public:
  /// kUsage error for invalid SLAM options; kInput for a namespace that is no ROS 2 name; the
  /// transport's errors otherwise. `transport` must outlive the node.
  [[nodiscard]] static Result<std::unique_ptr<SlamNode>> create(const SlamNodeOptions& options,
                                                                net::Transport& transport);
  ~SlamNode();
  SlamNode(const SlamNode&) = delete;
  SlamNode& operator=(const SlamNode&) = delete;

  /// Delivers what has arrived and adds every scan whose odometry is known, publishing the pose
  /// and map -> odom for each and the map when due. Returns how many scans it added; kRuntime
  /// error when SLAM's optimisation or a publication fails.
  [[nodiscard]] Result<int> spin_once();
  /// Adds the scans still waiting (odometry clamped to the last message), optimises once more and
  /// publishes the final map. Call once, at the end.
  [[nodiscard]] Result<slam::LaserSlamResult> finish();

  [[nodiscard]] const SlamNodeStats& stats() const;
  /// True once a scan has been added (the pose and map exist).
  [[nodiscard]] bool started() const;
  /// The map last published (nullptr before the first): what a planner on the robot uses.
  [[nodiscard]] const OccupancyGrid* map() const;
  /// How many maps have been published: a planner's "is there a newer map".
  [[nodiscard]] std::uint64_t map_revision() const { return stats().maps_published; }
  /// Per scan mapped, in order: wall seconds from its receipt to the publication of the first map
  /// that holds it (the latency a teammate or viewer sees, less the transport's).
  [[nodiscard]] const std::vector<double>& map_latencies_s() const;
  /// T_map_odom after the last scan added (REP-105's map -> odom); identity before the first.
  [[nodiscard]] Pose2 T_map_odom() const;
  /// The child frame of the map -> odom transform: the odometry's frame, or without odometry the
  /// robot frame (ScanInput::odom_frame); empty before the first scan.
  [[nodiscard]] const std::string& odom_frame() const;
  /// The newest odometry message's T_odom_base and stamp; nullopt before the first. With
  /// T_map_odom() it gives the robot's pose between scans, at the odometry's rate.
  [[nodiscard]] std::optional<PoseAtNs> latest_odometry() const;

 private:
  struct State;
  explicit SlamNode(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
