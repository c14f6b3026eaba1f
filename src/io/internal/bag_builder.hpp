#pragma once
// What every bag format reader fills: topics merged by name and type, counts and times per topic,
// and the kept messages' bytes in one buffer. The format readers (ros1_bag.cpp,
// rosbag2_sqlite.cpp, mcap_reader.cpp) only parse; this collects.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "internal/byte_cursor.hpp"
#include "internal/decompress.hpp"
#include "tessera/io/ros_bag.hpp"

namespace tessera::io_internal {

class BagBuilder {
 public:
  explicit BagBuilder(const BagReadOptions& options) : options_(options) {}

  /// The index of the topic with this name and type, made on first sight.
  std::size_t topic(const std::string& name, const std::string& type,
                    const std::string& serialization) {
    const auto key = std::make_pair(name, type);
    if (auto it = index_.find(key); it != index_.end()) return it->second;
    const std::size_t i = bag_.topics.size();
    BagTopic t;
    t.name = name;
    t.type = type;
    t.serialization = serialization;
    bag_.topics.push_back(std::move(t));
    keep_.push_back(options_.keep && options_.keep(bag_.topics.back()));
    index_.emplace(key, i);
    return i;
  }

  /// Counts a message on topic `t` and keeps its bytes when the caller asked for them (with
  /// zstd_messages(), decompressed; a message that does not decompress is not kept, and
  /// message_error() says why).
  void message(std::size_t t, std::int64_t log_time_ns, Bytes data) {
    BagTopic& topic = bag_.topics[t];
    if (topic.message_count == 0 || log_time_ns < topic.first_ns) topic.first_ns = log_time_ns;
    if (topic.message_count == 0 || log_time_ns > topic.last_ns) topic.last_ns = log_time_ns;
    ++topic.message_count;
    if (!keep_[t]) return;
    if (zstd_messages_) {
      if (std::string e = decompress_zstd(data, kMaxChunkBytes, scratch_); !e.empty()) {
        if (message_error_.empty()) {
          message_error_ =
              "message " + std::to_string(topic.message_count) + " of " + topic.name + ": " + e;
        }
        return;
      }
      data = Bytes(scratch_);
    }
    if (bag_.data.empty()) bag_.data.reserve(size_hint_);
    bag_.messages.push_back({t, log_time_ns, bag_.data.size(), data.size()});
    bag_.data.insert(bag_.data.end(), data.begin(), data.end());
  }

  /// Every message's bytes are Zstandard data (rosbag2's compression_mode MESSAGE).
  void zstd_messages() { zstd_messages_ = true; }
  /// The first message that did not decompress; empty when none.
  [[nodiscard]] const std::string& message_error() const { return message_error_; }

  void add_file(const std::filesystem::path& file) { bag_.files.push_back(file); }
  /// Bytes the kept messages may take (the storage file's size): reserved on the first kept
  /// message, so that keeping a whole bag does not copy it again while growing.
  void set_size_hint(std::size_t bytes) { size_hint_ = bytes; }
  void set_format(std::string format) { bag_.format = std::move(format); }
  [[nodiscard]] RosBag finish() && { return std::move(bag_); }

 private:
  const BagReadOptions& options_;
  RosBag bag_;
  std::vector<bool> keep_;
  std::size_t size_hint_ = 0;
  bool zstd_messages_ = false;
  std::vector<std::uint8_t> scratch_;  // a decompressed message
  std::string message_error_;
  std::map<std::pair<std::string, std::string>, std::size_t> index_;
};

/// The format readers; each reads one storage file into `builder`. kInput errors name `path`.
[[nodiscard]] Status read_ros1_bag_file(const std::filesystem::path& path, BagBuilder& builder);
[[nodiscard]] Status read_rosbag2_sqlite_file(const std::filesystem::path& path,
                                              BagBuilder& builder);
[[nodiscard]] Status read_mcap_file(const std::filesystem::path& path, BagBuilder& builder);

/// The same on a storage file's bytes already in memory (the fuzz harnesses; the sqlite one opens
/// a copy as an in-memory database). kInput errors name `file`.
[[nodiscard]] Status decode_ros1_bag(std::string_view bytes, const std::string& file,
                                     BagBuilder& builder);
[[nodiscard]] Status decode_rosbag2_sqlite(std::string_view bytes, const std::string& file,
                                           BagBuilder& builder);
[[nodiscard]] Status decode_mcap(std::string_view bytes, const std::string& file,
                                 BagBuilder& builder);

}  // namespace tessera::io_internal
