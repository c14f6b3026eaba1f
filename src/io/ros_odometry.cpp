// nav_msgs/Odometry in ROS 1 serialization and CDR: Header, string child_frame_id,
// PoseWithCovariance (Pose, float64[36]), TwistWithCovariance (Twist, float64[36]).
#include "internal/cdr_reader.hpp"
#include "internal/ros1_reader.hpp"
#include "internal/ros_message_fields.hpp"
#include "tessera/io/ros_messages.hpp"

namespace tessera {
namespace {

template <typename Reader>
Result<OdometryMessage> decode(Reader r) {
  OdometryMessage m;
  m.header = io_internal::read_header(r);
  m.child_frame_id = r.string("child_frame_id");
  m.pose = io_internal::read_transform(r);
  m.pose_covariance = io_internal::read_covariance(r, "pose.covariance");
  m.twist = io_internal::read_twist(r);
  m.twist_covariance = io_internal::read_covariance(r, "twist.covariance");
  if (!r.ok()) return io_internal::decode_error(r, kOdometryType);
  return m;
}

}  // namespace

Result<OdometryMessage> decode_odometry(std::span<const std::uint8_t> bytes, RosEncoding encoding) {
  if (encoding == RosEncoding::kRos1) return decode(io_internal::Ros1Reader(bytes));
  return decode(io_internal::CdrReader(bytes));
}

}  // namespace tessera
