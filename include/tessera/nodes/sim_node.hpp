#pragma once
// The simulator as a node (issue 14): differential-drive robots with a lidar and drifting wheel
// odometry in a world, speaking ROS 2 topics over a net::Transport as a Gazebo or Stage robot
// does. Per robot rN (r1, r2, ...), with REP-105 frames prefixed by the robot's name:
//   publishes /rN/scan  sensor_msgs/LaserScan  (frame rN/laser, sensor-data QoS)
//             /rN/odom  nav_msgs/Odometry      (rN/odom -> rN/base_link, sensor-data QoS)
//             /tf       rN/odom -> rN/base_link;  /tf_static rN/base_link -> rN/laser
//             /sim/rN/ground_truth nav_msgs/Odometry (world -> rN/base_link; evaluation only)
//   obeys     /rN/cmd_vel geometry_msgs/Twist (linear.x, angular.z; zero after cmd_timeout_s)
// and /clock (rosgraph_msgs/Clock) for the whole simulation, which starts at time 0 and advances
// one physics step per step() call: as fast as the caller calls it (the caller paces it against
// the wall clock for --rate, as ROS's use_sim_time nodes expect).
#include <cstdint>
#include <memory>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sensors/odometry_model.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::nodes {

struct SimNodeOptions {
  /// T_world_robot of each robot at time 0; the number of robots.
  std::vector<Pose2> starts;
  double physics_step_s = 0.01;
  double scan_rate_hz = 10.0;
  double odom_rate_hz = 50.0;
  double clock_rate_hz = 100.0;
  /// A robot stops when its last cmd_vel is older than this (a lost teleop or planner).
  double cmd_timeout_s = 0.5;
  /// Commands are clamped to these (a small indoor robot, TurtleBot 2 class).
  double max_speed_m_per_s = 0.7;
  double max_turn_rate_rad_per_s = 2.0;
  /// The robot is a disc of this radius: a step that would overlap a solid cell is not taken
  /// (the robot stalls against the wall, and its odometry reports no motion).
  double robot_radius_m = 0.15;
  /// A 360-degree lidar, one beam per degree, 12 m range, 1 cm noise (RPLIDAR-A2 class).
  LidarOptions lidar{.beams = 360,
                     .fov_rad = 2.0 * std::numbers::pi,
                     .min_range_m = 0.05,
                     .max_range_m = 12.0,
                     .range_noise_stddev_m = 0.01};
  OdometryErrorOptions odometry;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const SimNodeOptions& o);

/// "r1" for robot 0: robots' names, namespaces (/r1) and frame prefixes (r1/base_link).
[[nodiscard]] std::string robot_name(int robot);

class SimNode {
 public:
  /// Advertises and subscribes every topic. kInput error for invalid options ("sim node: <what>")
  /// or a start pose whose disc overlaps a solid cell ("sim node: start of r2 at (x, y) m is in
  /// a wall"); the transport's errors otherwise. `world` and `transport` must outlive the node.
  /// Deterministic for a seed: robot i's odometry and lidar noise draw from Rng(seed).fork(2i)
  /// and fork(2i + 1).
  [[nodiscard]] static Result<std::unique_ptr<SimNode>> create(const World& world,
                                                               const SimNodeOptions& options,
                                                               std::uint64_t seed,
                                                               net::Transport& transport);
  ~SimNode();
  SimNode(const SimNode&) = delete;
  SimNode& operator=(const SimNode&) = delete;

  /// One physics step: reads the commands that arrived (transport.poll()), moves each robot along
  /// its commanded arc, then publishes what is due at the new time. kRuntime error when a publish
  /// fails.
  [[nodiscard]] Status step();

  [[nodiscard]] double time_s() const;
  [[nodiscard]] int robot_count() const;
  [[nodiscard]] Pose2 true_pose(int robot) const;      // T_world_robot
  [[nodiscard]] Pose2 odometry_pose(int robot) const;  // T_odom_robot as /rN/odom reports it
  /// Steps refused because the robot would have hit a wall.
  [[nodiscard]] std::uint64_t stalls(int robot) const;
  /// cmd_vel messages that did not decode or carried a non-finite velocity: dropped.
  [[nodiscard]] std::uint64_t dropped_commands() const;

 private:
  struct State;
  explicit SimNode(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
