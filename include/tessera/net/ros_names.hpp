#pragma once
// ROS 2's names for topics and types, and how ROS 2 (rmw_cyclonedds, rmw_fastrtps) spells them on
// DDS (ROS 2 design article "Topic and Service name mapping to DDS"): topic /r1/scan is DDS topic
// rt/r1/scan; type sensor_msgs/msg/LaserScan is DDS type sensor_msgs::msg::dds_::LaserScan_.
#include <string>
#include <string_view>

#include "tessera/core/result.hpp"

namespace tessera::net {

/// A fully qualified ROS 2 topic name: "/" then tokens of [A-Za-z0-9_] separated by single "/",
/// a token not starting with a digit, no trailing "/". kInput error naming the rule it breaks.
[[nodiscard]] Status check_topic_name(std::string_view name);

/// `name` in namespace `ns` ("/r1"): a relative name ("scan") becomes "/r1/scan", an absolute one
/// ("/tf") stays; then check_topic_name.
[[nodiscard]] Result<std::string> resolve_topic_name(std::string_view name, std::string_view ns);

/// "/r1/scan" -> "rt/r1/scan" (the name must pass check_topic_name).
[[nodiscard]] std::string dds_topic_name(std::string_view ros_topic);

/// "sensor_msgs/msg/LaserScan" -> "sensor_msgs::msg::dds_::LaserScan_"; kInput error when the
/// name is not "<package>/msg/<Type>".
[[nodiscard]] Result<std::string> dds_type_name(std::string_view ros_type);

}  // namespace tessera::net
