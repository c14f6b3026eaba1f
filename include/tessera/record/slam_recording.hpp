#pragma once
// Records a finished laser SLAM run (slam/laser_slam.hpp) as ROS 2 messages into a MessageSink:
// per scan, at the scan's stamp, /scan (sensor_msgs/LaserScan in robot0/laser), /odom
// (nav_msgs/Odometry: the log's odometry, odom -> robot0/base_link) and /tf (map ->
// robot0/base_link, the SLAM pose); once, /tf_static (robot0/base_link -> robot0/laser, the first
// scan's mounting); at the last stamp, /map (nav_msgs/OccupancyGrid) and /path (nav_msgs/Path of
// the SLAM trajectory).
#include "tessera/core/result.hpp"
#include "tessera/io/message_sink.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"

namespace tessera {

/// Precondition: result.trajectory has one pose per scan of `log` (as run_laser_slam returns).
[[nodiscard]] Status record_laser_slam(MessageSink& sink, const LaserLog& log,
                                       const slam::LaserSlamResult& result);

}  // namespace tessera
