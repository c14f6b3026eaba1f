// Fuzz target: ROS 1 bags, format 2.0 (io/ros_bag.hpp; chunks none, bz2, lz4), then the robot bag
// made from them (bag_target.hpp).
#include "bag_target.hpp"
#include "fuzz_target.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::read_bag(&tessera::io_internal::decode_ros1_bag, bytes, path);
}

TESSERA_FUZZ_TARGET("ros1_bag", ".bag", &read);

}  // namespace
