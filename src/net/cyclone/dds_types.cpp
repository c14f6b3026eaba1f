// The table of IDL-generated descriptors (dds_types.hpp). A type added to src/net/idl is added
// here once; the test checks that each descriptor's DDS name is ROS 2's mapping of the key.
#include "cyclone/dds_types.hpp"

#include <array>
#include <utility>

#include "geometry_msgs.h"
#include "nav_msgs.h"
#include "rosgraph_msgs.h"
#include "sensor_msgs.h"
#include "tessera_msgs.h"
#include "tf2_msgs.h"
#include "visualization_msgs.h"

namespace tessera::net::dds_internal {
namespace {

constexpr std::array<std::pair<std::string_view, const dds_topic_descriptor_t*>, 18> kTypes{{
    {"builtin_interfaces/msg/Time", &builtin_interfaces_msg_dds__Time__desc},
    {"geometry_msgs/msg/PoseStamped", &geometry_msgs_msg_dds__PoseStamped__desc},
    {"geometry_msgs/msg/PoseWithCovarianceStamped",
     &geometry_msgs_msg_dds__PoseWithCovarianceStamped__desc},
    {"geometry_msgs/msg/TransformStamped", &geometry_msgs_msg_dds__TransformStamped__desc},
    {"geometry_msgs/msg/Twist", &geometry_msgs_msg_dds__Twist__desc},
    {"nav_msgs/msg/OccupancyGrid", &nav_msgs_msg_dds__OccupancyGrid__desc},
    {"nav_msgs/msg/Odometry", &nav_msgs_msg_dds__Odometry__desc},
    {"nav_msgs/msg/Path", &nav_msgs_msg_dds__Path__desc},
    {"rosgraph_msgs/msg/Clock", &rosgraph_msgs_msg_dds__Clock__desc},
    {"sensor_msgs/msg/LaserScan", &sensor_msgs_msg_dds__LaserScan__desc},
    {"std_msgs/msg/Header", &std_msgs_msg_dds__Header__desc},
    {"tessera_msgs/msg/FrontierClaim", &tessera_msgs_msg_dds__FrontierClaim__desc},
    {"tessera_msgs/msg/RobotStatus", &tessera_msgs_msg_dds__RobotStatus__desc},
    {"tessera_msgs/msg/TeamCommand", &tessera_msgs_msg_dds__TeamCommand__desc},
    {"tf2_msgs/msg/TFMessage", &tf2_msgs_msg_dds__TFMessage__desc},
    {"visualization_msgs/msg/Marker", &visualization_msgs_msg_dds__Marker__desc},
    {"visualization_msgs/msg/MarkerArray", &visualization_msgs_msg_dds__MarkerArray__desc},
    {"sensor_msgs/msg/CompressedImage", &sensor_msgs_msg_dds__CompressedImage__desc},
}};

}  // namespace

const dds_topic_descriptor* find_dds_type(std::string_view ros_type) {
  for (const auto& [name, descriptor] : kTypes) {
    if (name == ros_type) return descriptor;
  }
  return nullptr;
}

std::vector<std::string_view> dds_type_names() {
  std::vector<std::string_view> out;
  for (const auto& entry : kTypes) out.push_back(entry.first);
  return out;
}

}  // namespace tessera::net::dds_internal
