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
    if (Status s = publish(sink, "/scan", kRos2LaserScan, t_ns,
                           laser_scan_message(scan.scan, t_ns, kLaser));
        !s) {
      return s;
    }
    OdometryMessage odom;
    odom.header = {t_ns, "odom"};
    odom.child_frame_id = kBase;
    odom.pose = planar_transform(scan.odometry.x, scan.odometry.y, scan.odometry.theta);
    if (Status s = publish(sink, "/odom", kRos2Odometry, t_ns, odom); !s) return s;
    TfMessage tf;
    tf.transforms.push_back(
        planar_transform_stamped(result.trajectory[i].pose, t_ns, "map", kBase));
    if (Status s = publish(sink, "/tf", kRos2TfMessage, t_ns, tf); !s) return s;
  }
  if (Status s = publish(sink, "/map", kRos2OccupancyGrid, last_ns,
                         occupancy_grid_message(result.map, last_ns, "map"));
      !s) {
    return s;
  }
  std::vector<Pose2> poses;
  std::vector<std::int64_t> stamps;
  for (const StampedPose2& p : result.trajectory) {
    poses.push_back(p.pose);
    stamps.push_back(to_ns(p.t_s));
  }
  return publish(sink, "/path", kRos2Path, last_ns, path_message(poses, stamps, last_ns, "map"));
}

}  // namespace tessera
