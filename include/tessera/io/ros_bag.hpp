#pragma once
// Reading ROS bags: every topic with its type and message count, and the bytes of the messages of
// the topics the caller keeps. Formats (chosen by what the path is, not by options):
//   - a ROS 1 bag, format 2.0 (wiki.ros.org/Bags/Format/2.0): a file starting "#ROSBAG V2.0";
//     chunks uncompressed, bz2 or lz4 (LZ4 frame format, as roslz4 writes it). The legacy format
//     1.2 ("#ROSRECORD V1.2") is refused with an error that says so.
//   - a rosbag2 folder (metadata.yaml, then its relative_file_paths in order) with sqlite3 (.db3)
//     or mcap storage, or one .db3 or .mcap file on its own.
//   - an MCAP file (mcap.dev/spec): records read in file order, chunks uncompressed, zstd or lz4;
//     the summary section is not needed.
// The bytes of each message are kept as the bag stores them (ROS 1 serialization or CDR);
// ros_messages.hpp decodes them.
#include <cstdint>
#include <filesystem>
#include <functional>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/result.hpp"

namespace tessera {

/// One topic: connections (ROS 1) or channels (MCAP) with the same name and type are one topic.
struct BagTopic {
  std::string name;
  std::string type;           // as the bag spells it: "sensor_msgs/LaserScan" or ".../msg/..."
  std::string serialization;  // "ros1" or "cdr" (anything else is kept and named in errors)
  std::uint64_t message_count = 0;
  std::int64_t first_ns = 0;  // receive (log) time of the first and last message
  std::int64_t last_ns = 0;

  /// Messages per second over the topic's span: (count - 1) / (last - first); 0 when fewer than
  /// two messages or no span.
  [[nodiscard]] double rate_hz() const;
};

/// One kept message: its topic (index into RosBag::topics), its receive (log) time and where its
/// bytes are in RosBag::data.
struct BagMessage {
  std::size_t topic = 0;
  std::int64_t log_time_ns = 0;
  std::size_t offset = 0;
  std::size_t size = 0;
};

/// What read_ros_bag found.
struct RosBag {
  std::string format;  // "ROS 1 bag 2.0", "rosbag2 (sqlite3)", "rosbag2 (mcap)", "MCAP"
  std::vector<std::filesystem::path> files;  // the storage files read, in order
  std::vector<BagTopic> topics;              // in the order the bag first names them
  std::vector<BagMessage> messages;          // the kept topics' messages, in storage order
  std::vector<std::uint8_t> data;            // their bytes, back to back

  [[nodiscard]] std::span<const std::uint8_t> bytes(const BagMessage& m) const {
    return std::span<const std::uint8_t>(data).subspan(m.offset, m.size);
  }
  [[nodiscard]] std::uint64_t message_count() const;
  /// Earliest and latest log time over all topics, nanoseconds; 0 when the bag is empty.
  [[nodiscard]] std::int64_t start_ns() const;
  [[nodiscard]] std::int64_t end_ns() const;
  [[nodiscard]] double duration_s() const;
};

struct BagReadOptions {
  /// Which topics' message bytes to keep (every message is counted either way); empty keeps none.
  std::function<bool(const BagTopic& topic)> keep;
};

/// Reads the bag at `path` (a ROS 1 .bag, a rosbag2 folder, a .db3 or a .mcap file).
/// Errors, kInput, one line naming the file: not a bag, a legacy 1.2 bag, a record or length that
/// runs past its file or chunk, an unknown or unavailable compression, a chunk that does not
/// decompress to its stated size, a message on a connection or channel never defined, a missing
/// or malformed metadata.yaml or storage file, a sqlite file without rosbag2's tables.
/// Cost: one pass over the file; chunks are decompressed one at a time.
[[nodiscard]] Result<RosBag> read_ros_bag(const std::filesystem::path& path,
                                          const BagReadOptions& options = {});

/// True when `path` looks like something read_ros_bag reads (a .bag, .db3 or .mcap file, or a
/// folder holding metadata.yaml); it does not open the file.
[[nodiscard]] bool is_ros_bag_path(const std::filesystem::path& path);

}  // namespace tessera
