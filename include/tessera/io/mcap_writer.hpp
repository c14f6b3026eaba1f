#pragma once
// Writes MCAP files (mcap.dev/spec, version 0) as ROS 2 records them: profile "ros2", schemas in
// "ros2msg", messages in "cdr". Messages go into chunks of about 1 MiB, zstd-compressed, each
// followed by its message indexes; finish() writes the summary section (schemas, channels,
// statistics, chunk indexes) with its summary offsets and the footer, so that readers can seek by
// time without reading the data section. CRC-32 of every chunk's records and of the data section.
// The file appears at its path only when finish() succeeds (AtomicFileWriter): a run that fails
// or is killed leaves no half file.
#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "tessera/io/atomic_file.hpp"
#include "tessera/io/message_sink.hpp"

namespace tessera {

struct McapWriterOptions {
  /// Uncompressed bytes of records after which a chunk is closed.
  std::size_t chunk_bytes = 1 << 20;
  /// zstd level of the chunks; 0 writes them uncompressed.
  int zstd_level = 3;
  std::string library = "tessera";
};

class McapWriter final : public MessageSink {
 public:
  /// Starts the file (magic and header record). kRuntime error naming `path`.
  [[nodiscard]] static Result<McapWriter> open(const std::filesystem::path& path,
                                               const McapWriterOptions& options = {});
  McapWriter(McapWriter&&) noexcept = default;
  McapWriter& operator=(McapWriter&&) noexcept = default;

  ChannelId channel(std::string_view topic, std::string_view type,
                    std::string_view definition) override;
  /// Messages may come in any time order; chunk and statistics times are their min and max.
  [[nodiscard]] Status publish(ChannelId channel, std::int64_t time_ns,
                               std::span<const std::uint8_t> cdr) override;
  /// Closes the last chunk, writes the summary and footer and puts the file in place. Once.
  [[nodiscard]] Status finish();

  [[nodiscard]] std::uint64_t message_count() const { return message_count_; }
  [[nodiscard]] std::size_t chunk_count() const { return chunk_indexes_.size(); }

 private:
  struct Channel {
    std::uint16_t schema_id = 0;
    std::string topic;
    std::uint32_t sequence = 0;
    std::uint64_t count = 0;
  };
  struct Schema {
    std::string name;
    std::string definition;
  };
  struct ChunkIndex {
    std::uint64_t start_ns = 0, end_ns = 0, offset = 0, length = 0, index_length = 0;
    std::uint64_t compressed_size = 0, uncompressed_size = 0;
    std::map<std::uint16_t, std::uint64_t> index_offsets;
    std::string compression;
  };

  McapWriter(AtomicFileWriter file, McapWriterOptions options)
      : file_(std::move(file)), options_(std::move(options)) {}
  Status append(const std::string& bytes);
  Status close_chunk();

  AtomicFileWriter file_;
  McapWriterOptions options_;
  std::vector<Schema> schemas_;    // id = index + 1
  std::vector<Channel> channels_;  // id = index
  std::map<std::pair<std::string, std::string>, ChannelId> channel_of_;
  std::vector<bool> schema_written_;
  std::vector<bool> channel_written_;
  // The open chunk: its records, and per channel (log time, offset in the records) for the index.
  std::string chunk_;
  std::map<std::uint16_t, std::vector<std::pair<std::uint64_t, std::uint64_t>>> chunk_entries_;
  std::uint64_t chunk_start_ns_ = 0, chunk_end_ns_ = 0;
  std::vector<ChunkIndex> chunk_indexes_;
  std::uint64_t message_count_ = 0;
  std::uint64_t start_ns_ = 0, end_ns_ = 0;
  std::uint32_t data_crc_ = 0xFFFFFFFFU;  // running CRC-32 of the data section, pre-inverted
  bool finished_ = false;
};

}  // namespace tessera
