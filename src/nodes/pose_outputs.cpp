// A node's map, pose and map -> odom publications (nodes/pose_outputs.hpp).
#include "tessera/nodes/pose_outputs.hpp"

#include "tessera/io/ros_message_encoders.hpp"
#include "tessera/net/ros_names.hpp"
#include "tessera/record/ros_conversions.hpp"

namespace tessera::nodes {

Result<PoseOutputs> PoseOutputs::advertise(net::Transport& transport, const std::string& ns,
                                           const std::string& map_frame) {
  Result<std::string> map_topic = net::resolve_topic_name("map", ns);
  if (!map_topic.ok()) return map_topic.error();
  const std::string pose_topic = *net::resolve_topic_name("pose", ns);
  PoseOutputs out(transport, map_frame);
  using net::Qos;
  for (Status st :
       {transport.advertise({*map_topic, std::string(kRos2OccupancyGrid), Qos::map()}, out.map_),
        transport.advertise({"/tf", std::string(kRos2TfMessage), Qos::tf()}, out.tf_),
        transport.advertise(
            {pose_topic, std::string(kRos2PoseWithCovarianceStamped), Qos::reliable(10)},
            out.pose_)}) {
    if (!st.ok()) return st.error();
  }
  return out;
}

Status PoseOutputs::publish_map(const OccupancyGrid& map, std::int64_t stamp_ns) const {
  return transport_->publish(map_, encode_cdr(occupancy_grid_message(map, stamp_ns, map_frame_)));
}

Status PoseOutputs::publish_pose(std::int64_t stamp_ns, const Pose2& T_map_base,
                                 const Pose2& T_odom_base, const std::string& odom_frame,
                                 const RosCovariance& covariance) const {
  PoseWithCovarianceStampedMessage pose;
  pose.header = {stamp_ns, map_frame_};
  pose.pose = planar_transform(T_map_base.x, T_map_base.y, T_map_base.theta);
  pose.covariance = covariance;
  if (Status s = transport_->publish(pose_, encode_cdr(pose)); !s.ok()) return s;
  TfMessage map_to_odom;
  map_to_odom.transforms.push_back(planar_transform_stamped(T_map_base * T_odom_base.inverse(),
                                                            stamp_ns, map_frame_, odom_frame));
  return transport_->publish(tf_, encode_cdr(map_to_odom));
}

}  // namespace tessera::nodes
