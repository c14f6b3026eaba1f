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

/// The end of a run for a live view that saw it scan by scan (SlamLiveRecorder): /map and /path
/// of the final optimisation, and /tf at the last scan's final pose, stamped at the last scan.
[[nodiscard]] Status record_laser_slam_result(MessageSink& sink,
                                              const slam::LaserSlamResult& result);

/// A laser SLAM run while it runs, for the live view: after each LaserSlam::add_scan, the same
/// /scan, /odom and /tf (the current estimate) as record_laser_slam, and /map from
/// LaserSlam::current_map() when the caller asks for it (it costs a map build).
class SlamLiveRecorder {
 public:
  explicit SlamLiveRecorder(MessageSink& sink) : sink_(sink) {}
  [[nodiscard]] Status scan(const slam::LaserSlam& slam, const StampedScan& scan, bool with_map);

 private:
  MessageSink& sink_;
  bool static_sent_ = false;
};

}  // namespace tessera
