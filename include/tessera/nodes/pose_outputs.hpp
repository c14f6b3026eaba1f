#pragma once
// What a node that places a robot in a map publishes (the live SLAM and localization nodes), in
// namespace `ns`: <ns>/map nav_msgs/OccupancyGrid (reliable, transient local: a late viewer or
// planner gets the last one), <ns>/pose geometry_msgs/PoseWithCovarianceStamped (T_map_base;
// reliable, depth 10) and /tf map -> odom (REP-105: the correction that odometry misses).
#include <cstdint>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/ros_messages.hpp"
#include "tessera/net/transport.hpp"

namespace tessera::nodes {

class PoseOutputs {
 public:
  /// Advertises the three topics. kInput error for a namespace that is no ROS 2 name; the
  /// transport's errors otherwise. `transport` must outlive the outputs.
  [[nodiscard]] static Result<PoseOutputs> advertise(net::Transport& transport,
                                                     const std::string& ns,
                                                     const std::string& map_frame);

  [[nodiscard]] Status publish_map(const OccupancyGrid& map, std::int64_t stamp_ns) const;
  /// <ns>/pose with `covariance` (ROS's 6 x 6, row-major) and /tf map -> `odom_frame`
  /// (T_map_base * T_odom_base^-1).
  [[nodiscard]] Status publish_pose(std::int64_t stamp_ns, const Pose2& T_map_base,
                                    const Pose2& T_odom_base, const std::string& odom_frame,
                                    const RosCovariance& covariance = {}) const;

 private:
  PoseOutputs(net::Transport& transport, std::string map_frame)
      : transport_(&transport), map_frame_(std::move(map_frame)) {}
  net::Transport* transport_;
  std::string map_frame_;
  net::Transport::WriterId map_ = 0, tf_ = 0, pose_ = 0;
};

}  // namespace tessera::nodes
