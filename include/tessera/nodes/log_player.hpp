#pragma once
// A laser log (a CARMEN log, a bag read as a LaserLog) played as ROS 2 topics, as `ros2 bag play`
// plays a bag, so that the live SLAM node runs on real data (issue 14: `tessera play`). In
// namespace `ns`, per scan in file order, each stamped with the scan's time:
//   <ns>/odom nav_msgs/Odometry (odom -> base_link: the scan's odometry pose),
//   <ns>/scan sensor_msgs/LaserScan (frame laser), and /clock;
// once at the start, /tf_static base_link -> laser (the first scan's laser_in_robot).
// A log of scans alone (LaserLog::has_odometry false) is played without <ns>/odom, as a robot
// without odometry publishes it, and without the static transform when its laser is the robot.
// Frames are prefixed with the namespace's name ("r1/odom") when one is given.
#include <cstdint>
#include <memory>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/net/transport.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera::nodes {

struct LogPlayerOptions {
  std::string ns;  // "" or "/r1"
  /// The writers' QoS depth; the scan and odometry writers offer reliable delivery, which matches
  /// best-effort and reliable readers alike.
  std::uint32_t depth = 100;
};

class LogPlayer {
 public:
  /// kInput error for a log without scans or a namespace that is no ROS 2 name; the transport's
  /// errors otherwise. `log` and `transport` must outlive the player.
  [[nodiscard]] static Result<std::unique_ptr<LogPlayer>> create(const LaserLog& log,
                                                                 const LogPlayerOptions& options,
                                                                 net::Transport& transport);
  ~LogPlayer();
  LogPlayer(const LogPlayer&) = delete;
  LogPlayer& operator=(const LogPlayer&) = delete;

  [[nodiscard]] bool done() const;
  /// The stamp of the next scan (seconds). Precondition: !done().
  [[nodiscard]] double next_stamp_s() const;
  /// Publishes the next scan with its odometry and clock. Precondition: !done().
  [[nodiscard]] Status publish_next();
  [[nodiscard]] std::size_t published() const;
  /// Readers matched with the scan writer now (a player waits for the first).
  [[nodiscard]] std::size_t scan_subscribers() const;

 private:
  struct State;
  explicit LogPlayer(std::unique_ptr<State> state);
  std::unique_ptr<State> state_;
};

}  // namespace tessera::nodes
