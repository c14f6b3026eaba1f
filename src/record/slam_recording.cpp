#include "tessera/record/slam_recording.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "tessera/core/assert.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera {
namespace {

const std::string kBase = "robot0/base_link";
const std::string kLaser = "robot0/laser";

template <typename Message>
Status publish(MessageSink& sink, std::string_view topic, std::string_view type, std::int64_t t_ns,
               const Message& m) {
  const MessageSink::ChannelId channel = sink.channel(topic, type, ros2msg_definition(type));
  return sink.publish(channel, t_ns, encode_cdr(m));
}

// /scan, /odom (the log's odometry) and /tf (map -> base_link at T_map_robot) of one scan.
Status publish_scan(MessageSink& sink, const StampedScan& scan, std::int64_t t_ns,
                    const Pose2& T_map_robot) {
  if (Status s =
          publish(sink, "/scan", kRos2LaserScan, t_ns, laser_scan_message(scan.scan, t_ns, kLaser));
      !s) {
    return s;
  }
  OdometryMessage odom;
  odom.header = {t_ns, "odom"};
  odom.child_frame_id = kBase;
  odom.pose = planar_transform(scan.odometry.x, scan.odometry.y, scan.odometry.theta);
  if (Status s = publish(sink, "/odom", kRos2Odometry, t_ns, odom); !s) return s;
  TfMessage tf;
  tf.transforms.push_back(planar_transform_stamped(T_map_robot, t_ns, "map", kBase));
  return publish(sink, "/tf", kRos2TfMessage, t_ns, tf);
}

Status publish_map_and_path(MessageSink& sink, const slam::LaserSlamResult& result,
                            std::int64_t t_ns) {
  if (Status s = publish(sink, "/map", kRos2OccupancyGrid, t_ns,
                         occupancy_grid_message(result.map, t_ns, "map"));
      !s) {
    return s;
  }
  return publish(sink, "/path", kRos2Path, t_ns, path_message(result.trajectory, t_ns, "map"));
}

}  // namespace

Status record_laser_slam(MessageSink& sink, const LaserLog& log,
                         const slam::LaserSlamResult& result) {
  TESSERA_ASSERT(result.trajectory.size() == log.scans.size());
  if (log.scans.empty()) return Ok{};
  std::int64_t last_ns = to_ns(log.scans.front().t_s);
  {
    TfMessage statics;
    statics.transforms.push_back(
        planar_transform_stamped(log.scans.front().laser_in_robot, last_ns, kBase, kLaser));
    if (Status s = publish(sink, "/tf_static", kRos2TfMessage, last_ns, statics); !s) return s;
  }
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const StampedScan& scan = log.scans[i];
    const std::int64_t t_ns = to_ns(scan.t_s);
    last_ns = std::max(last_ns, t_ns);
    if (Status s = publish_scan(sink, scan, t_ns, result.trajectory[i].pose); !s) return s;
  }
  return publish_map_and_path(sink, result, last_ns);
}

Status record_laser_slam_result(MessageSink& sink, const slam::LaserSlamResult& result) {
  if (result.trajectory.empty()) return Ok{};
  std::int64_t last_ns = 0;
  for (const StampedPose2& p : result.trajectory) last_ns = std::max(last_ns, to_ns(p.t_s));
  TfMessage tf;
  tf.transforms.push_back(
      planar_transform_stamped(result.trajectory.back().pose, last_ns, "map", kBase));
  if (Status s = publish(sink, "/tf", kRos2TfMessage, last_ns, tf); !s) return s;
  return publish_map_and_path(sink, result, last_ns);
}

Status SlamLiveRecorder::scan(const slam::LaserSlam& slam, const StampedScan& scan, bool with_map) {
  const std::int64_t t_ns = to_ns(scan.t_s);
  if (!static_sent_) {
    TfMessage statics;
    statics.transforms.push_back(
        planar_transform_stamped(scan.laser_in_robot, t_ns, kBase, kLaser));
    if (Status s = publish(sink_, "/tf_static", kRos2TfMessage, t_ns, statics); !s) return s;
    static_sent_ = true;
  }
  if (Status s = publish_scan(sink_, scan, t_ns, slam.latest_pose()); !s) return s;
  if (!with_map) return Ok{};
  return publish(sink_, "/map", kRos2OccupancyGrid, t_ns,
                 occupancy_grid_message(slam.current_map(), t_ns, "map"));
}

}  // namespace tessera
