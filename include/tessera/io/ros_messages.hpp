#pragma once
// The ROS messages tessera reads from bags, decoded from either serialization: ROS 1 (bag format
// 2.0, MCAP "ros1") or ROS 2 CDR (rosbag2 sqlite3 and MCAP "cdr"). Field layouts are those of the
// message definitions: sensor_msgs/LaserScan, nav_msgs/Odometry (with its twist and covariances),
// tf2_msgs/TFMessage with geometry_msgs/TransformStamped. Every field is checked for length.
#include <array>
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

/// geometry_msgs/Twist: linear velocity in metres per second and angular velocity in radians per
/// second, along and about the x, y, z axes of the frame it is expressed in.
struct RosTwist {
  double linear_x_mps = 0.0, linear_y_mps = 0.0, linear_z_mps = 0.0;
  double angular_x_radps = 0.0, angular_y_radps = 0.0, angular_z_radps = 0.0;
};

/// A geometry_msgs float64[36] covariance: 6x6, row-major, over (x, y, z, rotation about x, y, z)
/// in the units of the pose or twist it belongs to.
using RosCovariance = std::array<double, 36>;

/// nav_msgs/Odometry: pose is T_{header.frame_id}_{child_frame_id}; twist is the velocity of
/// child_frame_id expressed in child_frame_id. Covariances all zero when the source leaves them
/// unset.
struct OdometryMessage {
  RosHeader header;
  std::string child_frame_id;
  RosTransform pose;
  RosCovariance pose_covariance{};
  RosTwist twist{};
  RosCovariance twist_covariance{};
};

/// Decoders. kInput error "<Type>: byte N: <what>" when a length runs past the message, a CDR
/// string lacks its NUL, or the encapsulation is not plain CDR; the caller adds file and topic.
[[nodiscard]] Result<LaserScanMessage> decode_laser_scan(std::span<const std::uint8_t> bytes,
                                                         RosEncoding encoding);
/// sensor_msgs/MultiEchoLaserScan (the LaserScan fields with a LaserEcho, a float32[] of echoes,
/// per beam; Cartographer's own bags record their lasers so) read as a LaserScan of each beam's
/// first echo, as Cartographer reads it; a beam without an echo is NaN (no reading).
[[nodiscard]] Result<LaserScanMessage> decode_multi_echo_laser_scan(
    std::span<const std::uint8_t> bytes, RosEncoding encoding);
[[nodiscard]] Result<OdometryMessage> decode_odometry(std::span<const std::uint8_t> bytes,
                                                      RosEncoding encoding);
[[nodiscard]] Result<TfMessage> decode_tf_message(std::span<const std::uint8_t> bytes,
                                                  RosEncoding encoding);

/// The type names in ROS 1 form ("sensor_msgs/LaserScan"); ros_type_is accepts ROS 2's
/// "sensor_msgs/msg/LaserScan" for the same type.
inline constexpr std::string_view kLaserScanType = "sensor_msgs/LaserScan";
inline constexpr std::string_view kMultiEchoLaserScanType = "sensor_msgs/MultiEchoLaserScan";
inline constexpr std::string_view kOdometryType = "nav_msgs/Odometry";
inline constexpr std::string_view kTfMessageType = "tf2_msgs/TFMessage";
[[nodiscard]] bool ros_type_is(std::string_view type, std::string_view ros1_name);
/// A LaserScan or a MultiEchoLaserScan: a planar laser's scan.
[[nodiscard]] bool is_laser_scan_type(std::string_view type);

}  // namespace tessera
