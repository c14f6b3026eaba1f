// Fuzz target: rosbag2 sqlite3 storage files (io/ros_bag.hpp; tables topics and messages, CDR
// messages), opened from memory, then the robot bag made from them (bag_target.hpp). SQLite's own
// page parsing is SQLite's (fuzzed upstream); what this reaches is tessera's use of the tables.
#include "bag_target.hpp"
#include "fuzz_target.hpp"

namespace {

tessera::Status read(std::string_view bytes, const std::filesystem::path& path) {
  return tessera::fuzz::read_bag(&tessera::io_internal::decode_rosbag2_sqlite, bytes, path);
}

TESSERA_FUZZ_TARGET("rosbag2_sqlite", ".db3", &read);

}  // namespace
