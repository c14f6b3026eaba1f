#pragma once
// The IDL-generated DDS type of each ROS 2 type the DDS transport carries (src/net/idl, compiled
// by idlc into C descriptors: field layout, alignment and the ops Cyclone serializes with).
#include <string_view>
#include <vector>

struct dds_topic_descriptor;

namespace tessera::net::dds_internal {

/// The descriptor of `ros_type` ("nav_msgs/msg/OccupancyGrid"), or nullptr.
[[nodiscard]] const dds_topic_descriptor* find_dds_type(std::string_view ros_type);

/// Every ROS 2 type with a descriptor.
[[nodiscard]] std::vector<std::string_view> dds_type_names();

}  // namespace tessera::net::dds_internal
