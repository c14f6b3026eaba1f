#pragma once
// Field groups shared by the message decoders, written once for both readers (Ros1Reader,
// CdrReader have the same calls; only ROS 1's header carries a seq).
#include "tessera/io/ros_messages.hpp"

namespace tessera::io_internal {

/// std_msgs/Header.
template <typename Reader>
RosHeader read_header(Reader& r) {
  RosHeader h;
  if constexpr (Reader::kHasHeaderSeq) r.u32("header.seq");
  h.stamp_ns = r.stamp_ns("header.stamp");
  h.frame_id = r.string("header.frame_id");
  return h;
}

/// geometry_msgs/Vector3 or Point followed by geometry_msgs/Quaternion: Transform and Pose.
template <typename Reader>
RosTransform read_transform(Reader& r) {
  RosTransform t;
  t.x_m = r.f64("translation.x");
  t.y_m = r.f64("translation.y");
  t.z_m = r.f64("translation.z");
  t.qx = r.f64("rotation.x");
  t.qy = r.f64("rotation.y");
  t.qz = r.f64("rotation.z");
  t.qw = r.f64("rotation.w");
  return t;
}

/// geometry_msgs/Twist: Vector3 linear, Vector3 angular.
template <typename Reader>
RosTwist read_twist(Reader& r) {
  RosTwist t;
  t.linear_x_mps = r.f64("twist.linear.x");
  t.linear_y_mps = r.f64("twist.linear.y");
  t.linear_z_mps = r.f64("twist.linear.z");
  t.angular_x_radps = r.f64("twist.angular.x");
  t.angular_y_radps = r.f64("twist.angular.y");
  t.angular_z_radps = r.f64("twist.angular.z");
  return t;
}

/// float64[36]: a fixed-size array, no count.
template <typename Reader>
RosCovariance read_covariance(Reader& r, const char* what) {
  RosCovariance c{};
  for (double& d : c) d = r.f64(what);
  return c;
}

/// geometry_msgs/TransformStamped: Header, string child_frame_id, Transform.
template <typename Reader>
TransformStampedMessage read_transform_stamped(Reader& r) {
  TransformStampedMessage t;
  t.header = read_header(r);
  t.child_frame_id = r.string("child_frame_id");
  t.transform = read_transform(r);
  return t;
}

/// The reader's first failure as "<type>: byte N: ...".
template <typename Reader>
Error decode_error(const Reader& r, std::string_view type) {
  return input_error(std::string(type) + ": " + r.error());
}

}  // namespace tessera::io_internal
