#pragma once
// The ROS messages tessera reads from bags, decoded from either serialization: ROS 1 (bag format
// 2.0, MCAP "ros1") or ROS 2 CDR (rosbag2 sqlite3 and MCAP "cdr"). Field layouts are those of the
// message definitions: sensor_msgs/LaserScan, nav_msgs/Odometry, tf2_msgs/TFMessage with
// geometry_msgs/TransformStamped. Fields tessera does not use (covariances, twist, intensities'
// meaning) are read past but still checked for length.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/core/result.hpp"

namespace tessera {

/// How a message's bytes are laid out.
enum class RosEncoding {
  kRos1,  // ROS 1 serialization: little endian, packed
  kCdr,   // ROS 2: CDR with a 4-byte encapsulation header, aligned fields
};

/// std_msgs/Header without ROS 1's seq; stamp in nanoseconds since the epoch.
struct RosHeader {
  std::int64_t stamp_ns = 0;
  std::string frame_id;
};

/// sensor_msgs/LaserScan: beam i at angle_min_rad + i * angle_increment_rad in header.frame_id;
/// a valid range lies in [range_min_m, range_max_m], anything else (inf, NaN, 0) is no reading.
struct LaserScanMessage {
  RosHeader header;
  float angle_min_rad = 0.0F;
  float angle_max_rad = 0.0F;
  float angle_increment_rad = 0.0F;
  float time_increment_s = 0.0F;
  float scan_time_s = 0.0F;
  float range_min_m = 0.0F;
  float range_max_m = 0.0F;
  std::vector<float> ranges_m;
  std::vector<float> intensities;
};

/// A rigid transform in 3D: translation in metres and a unit quaternion (geometry_msgs/Transform,
/// and geometry_msgs/Pose read the same way). T_parent_child.
struct RosTransform {
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;
  double qx = 0.0, qy = 0.0, qz = 0.0, qw = 1.0;
};

/// geometry_msgs/TransformStamped: T_{header.frame_id}_{child_frame_id}.
struct TransformStampedMessage {
  RosHeader header;
  std::string child_frame_id;
  RosTransform transform;
};

/// tf2_msgs/TFMessage.
struct TfMessage {
  std::vector<TransformStampedMessage> transforms;
};

/// nav_msgs/Odometry: pose.pose is T_{header.frame_id}_{child_frame_id}; covariances and twist are
/// skipped.
struct OdometryMessage {
  RosHeader header;
  std::string child_frame_id;
  RosTransform pose;
};

/// Decoders. kInput error "<Type>: byte N: <what>" when a length runs past the message, a CDR
/// string lacks its NUL, or the encapsulation is not plain CDR; the caller adds file and topic.
[[nodiscard]] Result<LaserScanMessage> decode_laser_scan(std::span<const std::uint8_t> bytes,
                                                         RosEncoding encoding);
[[nodiscard]] Result<OdometryMessage> decode_odometry(std::span<const std::uint8_t> bytes,
                                                      RosEncoding encoding);
[[nodiscard]] Result<TfMessage> decode_tf_message(std::span<const std::uint8_t> bytes,
                                                  RosEncoding encoding);

/// The type names in ROS 1 form ("sensor_msgs/LaserScan"); ros_type_is accepts ROS 2's
/// "sensor_msgs/msg/LaserScan" for the same type.
inline constexpr std::string_view kLaserScanType = "sensor_msgs/LaserScan";
inline constexpr std::string_view kOdometryType = "nav_msgs/Odometry";
inline constexpr std::string_view kTfMessageType = "tf2_msgs/TFMessage";
[[nodiscard]] bool ros_type_is(std::string_view type, std::string_view ros1_name);

}  // namespace tessera
