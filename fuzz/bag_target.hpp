#pragma once
// What the three bag harnesses share (ros1_bag, mcap, rosbag2_sqlite): one storage file's bytes
// decoded as read_ros_bag decodes it, keeping the topics a robot bag needs, then converted with
// robot_bag_from as `tessera slam --bag` does, so that the message decoders (LaserScan,
// Odometry, TFMessage in ROS 1 and CDR) and the tf chain see whatever the storage holds.
#include <filesystem>
#include <string>
#include <string_view>
#include <utility>

#include "fuzz_target.hpp"
#include "internal/bag_builder.hpp"
#include "tessera/core/result.hpp"
#include "tessera/io/robot_bag.hpp"

namespace tessera::fuzz {

using BagDecoder = Status (*)(std::string_view bytes, const std::string& file,
                              io_internal::BagBuilder& builder);

inline Status read_bag(BagDecoder decode, std::string_view bytes,
                       const std::filesystem::path& path) {
  BagReadOptions options;
  options.keep = robot_bag_needs;
  io_internal::BagBuilder builder(options);
  if (Status s = decode(bytes, path.string(), builder); !s) return s;
  const RosBag bag = std::move(builder).finish();
  Result<RobotBag> robot = robot_bag_from(bag, path.string());
  // Several scan or odometry topics is the caller's choice to make (kUsage, exit 2), not bad input.
  if (!robot && robot.error().kind == ErrorKind::kUsage) return Ok{};
  return status_of(robot);
}

}  // namespace tessera::fuzz
