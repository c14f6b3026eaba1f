#pragma once
// The ROS 2 messages tessera writes (MCAP recordings, the live view, the team link between
// robots): CDR encoders, CDR decoders of the types ros_messages.hpp does not decode, and their
// ros2msg definitions (MCAP schema encoding "ros2msg": the type's definition, then each type it
// uses after a line of 80 '=' and "MSG: pkg/Type"). Layouts are ROS 2 Humble's: sensor_msgs/
// LaserScan, nav_msgs/Odometry, tf2_msgs/TFMessage (ros_messages.hpp has their structs and
// decoders), geometry_msgs/TransformStamped, nav_msgs/OccupancyGrid, nav_msgs/Path,
// geometry_msgs/PoseStamped, visualization_msgs/MarkerArray, rosgraph_msgs/Clock,
// geometry_msgs/Twist, geometry_msgs/PoseWithCovarianceStamped, and tessera's own team messages
// tessera_msgs/FrontierClaim, RobotStatus and TeamCommand.
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/io/ros_messages.hpp"

namespace tessera {

/// nav_msgs/OccupancyGrid: cells row-major from the cell at `origin` (its lower-left corner),
/// x along a row; -1 unknown, 0..100 the probability of occupancy in percent.
struct OccupancyGridMessage {
  RosHeader header;
  std::int64_t map_load_time_ns = 0;
  float resolution_m = 0.0F;
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  RosTransform origin;  // T_frame_cell00corner (geometry_msgs/Pose)
  std::vector<std::int8_t> data;
};

/// geometry_msgs/PoseStamped.
struct PoseStampedMessage {
  RosHeader header;
  RosTransform pose;
};

/// nav_msgs/Path.
struct PathMessage {
  RosHeader header;
  std::vector<PoseStampedMessage> poses;
};

/// geometry_msgs/Point (and Vector3).
struct RosPoint {
  double x_m = 0.0, y_m = 0.0, z_m = 0.0;
};

/// std_msgs/ColorRGBA, components in [0, 1].
struct RosColor {
  float r = 1.0F, g = 1.0F, b = 1.0F, a = 1.0F;
};

/// visualization_msgs/Marker: the fields tessera fills (texture, UV coordinates and mesh are
/// written empty, and read past by the decoder).
struct MarkerMessage {
  static constexpr std::int32_t kArrow = 0;
  static constexpr std::int32_t kLineStrip = 4;
  static constexpr std::int32_t kLineList = 5;
  static constexpr std::int32_t kCubeList = 6;
  static constexpr std::int32_t kSphereList = 7;
  static constexpr std::int32_t kPoints = 8;
  static constexpr std::int32_t kText = 9;
  static constexpr std::int32_t kAdd = 0;
  static constexpr std::int32_t kDeleteAll = 3;

  RosHeader header;
  std::string ns;
  std::int32_t id = 0;
  std::int32_t type = kPoints;
  std::int32_t action = kAdd;
  RosTransform pose;
  RosPoint scale{1.0, 1.0, 1.0};
  RosColor color;
  std::int64_t lifetime_ns = 0;  // 0: forever
  bool frame_locked = false;
  std::vector<RosPoint> points;
  std::vector<RosColor> colors;  // empty, or one per point
  std::string text;
};

/// visualization_msgs/MarkerArray.
struct MarkerArrayMessage {
  std::vector<MarkerMessage> markers;
};

/// rosgraph_msgs/Clock: the simulated time (/clock), nanoseconds since the epoch.
struct ClockMessage {
  std::int64_t clock_ns = 0;
};

/// geometry_msgs/Twist as a message of its own (a velocity command on cmd_vel, in the robot's
/// base frame): no header.
using TwistMessage = RosTwist;

/// geometry_msgs/PoseWithCovarianceStamped: pose is T_{header.frame_id}_robot (an initial pose,
/// a localisation estimate).
struct PoseWithCovarianceStampedMessage {
  RosHeader header;
  RosTransform pose;
  RosCovariance covariance{};
};

/// tessera_msgs/FrontierClaim: a robot of the team tells the others which frontier it is going
/// to, so that they pick another one.
struct FrontierClaimMessage {
  RosHeader header;            // frame: the team's map frame
  std::string robot_id;        // "r1"
  std::uint32_t claim_id = 0;  // increases per robot
  RosPoint target;             // the frontier goal, metres in header.frame_id
  float radius_m = 0.0F;       // frontier cells within this radius of target are claimed
  float path_length_m = 0.0F;  // the claiming robot's planned path length to target
  bool active = true;          // false: the claim is released
};

/// tessera_msgs/RobotStatus: one robot's state and link counters, sent to the team and the
/// operator. A state outside the constants below is decoded as it is (a newer sender's state);
/// the receiver decides what to do with it.
struct RobotStatusMessage {
  static constexpr std::uint8_t kStarting = 0;
  static constexpr std::uint8_t kExploring = 1;
  static constexpr std::uint8_t kReturningHome = 2;
  static constexpr std::uint8_t kIdle = 3;
  static constexpr std::uint8_t kFinished = 4;
  static constexpr std::uint8_t kStopped = 5;
  static constexpr std::uint8_t kFailed = 6;

  RosHeader header;
  std::string robot_id;
  std::uint8_t state = kStarting;
  std::string reason;  // why it stopped or failed, empty otherwise
  RosTransform pose;   // the robot's pose estimate, T_{header.frame_id}_robot
  float explored_area_m2 = 0.0F;
  std::uint64_t messages_sent = 0;
  std::uint64_t bytes_sent = 0;
  std::uint64_t messages_dropped = 0;  // received messages rejected as invalid
};

/// tessera_msgs/TeamCommand: the operator's command to one robot or to all. A command outside the
/// constants below is decoded as it is; the receiver decides what to do with it.
struct TeamCommandMessage {
  static constexpr std::uint8_t kStart = 0;
  static constexpr std::uint8_t kStop = 1;
  static constexpr std::uint8_t kReturnHome = 2;

  RosHeader header;
  std::string robot_id;  // empty: every robot
  std::uint8_t command = kStart;
};

/// The type names as MCAP schemas and ROS 2 name them.
inline constexpr std::string_view kRos2LaserScan = "sensor_msgs/msg/LaserScan";
inline constexpr std::string_view kRos2Odometry = "nav_msgs/msg/Odometry";
inline constexpr std::string_view kRos2TfMessage = "tf2_msgs/msg/TFMessage";
inline constexpr std::string_view kRos2TransformStamped = "geometry_msgs/msg/TransformStamped";
inline constexpr std::string_view kRos2OccupancyGrid = "nav_msgs/msg/OccupancyGrid";
inline constexpr std::string_view kRos2Path = "nav_msgs/msg/Path";
inline constexpr std::string_view kRos2PoseStamped = "geometry_msgs/msg/PoseStamped";
inline constexpr std::string_view kRos2MarkerArray = "visualization_msgs/msg/MarkerArray";
inline constexpr std::string_view kRos2Clock = "rosgraph_msgs/msg/Clock";
inline constexpr std::string_view kRos2Twist = "geometry_msgs/msg/Twist";
inline constexpr std::string_view kRos2PoseWithCovarianceStamped =
    "geometry_msgs/msg/PoseWithCovarianceStamped";
inline constexpr std::string_view kRos2FrontierClaim = "tessera_msgs/msg/FrontierClaim";
inline constexpr std::string_view kRos2RobotStatus = "tessera_msgs/msg/RobotStatus";
inline constexpr std::string_view kRos2TeamCommand = "tessera_msgs/msg/TeamCommand";

/// CDR (little endian, with the encapsulation header) of each message.
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const LaserScanMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const OdometryMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const TfMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const TransformStampedMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const OccupancyGridMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const PathMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const PoseStampedMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const MarkerArrayMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const ClockMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const TwistMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const PoseWithCovarianceStampedMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const FrontierClaimMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const RobotStatusMessage& m);
[[nodiscard]] std::vector<std::uint8_t> encode_cdr(const TeamCommandMessage& m);

/// CDR decoders (either byte order, plain CDR encapsulation only) of the messages above that
/// ros_messages.hpp does not decode. kInput error "<kRos2* type>: byte N: <what>" when a length
/// or count runs past the message, a string lacks its NUL, a bool is neither 0 nor 1, or the
/// encapsulation is not plain CDR; the caller adds where the bytes came from. Bytes after the
/// last field (a writer's padding) are ignored, as decode_laser_scan ignores them.
[[nodiscard]] Result<TransformStampedMessage> decode_cdr_transform_stamped(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<OccupancyGridMessage> decode_cdr_occupancy_grid(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<PathMessage> decode_cdr_path(std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<PoseStampedMessage> decode_cdr_pose_stamped(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<MarkerArrayMessage> decode_cdr_marker_array(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<ClockMessage> decode_cdr_clock(std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<TwistMessage> decode_cdr_twist(std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<PoseWithCovarianceStampedMessage> decode_cdr_pose_with_covariance_stamped(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<FrontierClaimMessage> decode_cdr_frontier_claim(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<RobotStatusMessage> decode_cdr_robot_status(
    std::span<const std::uint8_t> bytes);
[[nodiscard]] Result<TeamCommandMessage> decode_cdr_team_command(
    std::span<const std::uint8_t> bytes);

/// The ros2msg definition of one of the kRos2* types, with every type it uses; empty for a type
/// tessera does not write.
[[nodiscard]] std::string ros2msg_definition(std::string_view type);

/// RosTransform of a planar pose: translation (x, y, 0), rotation yaw about z.
[[nodiscard]] RosTransform planar_transform(double x_m, double y_m, double yaw_rad);

}  // namespace tessera
