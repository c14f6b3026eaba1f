// MCAP writer (mcap.dev/spec): records are an opcode byte, a uint64 length and the content, all
// little endian; strings and byte arrays carry a uint32 length, maps a uint32 byte length.
#include "tessera/io/mcap_writer.hpp"

#include <zstd.h>

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

#include "internal/byte_writer.hpp"
#include "internal/crc32.hpp"

namespace tessera {
namespace {

constexpr std::string_view kMagic("\x89MCAP0\r\n", 8);

enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
  kMessageIndex = 0x07,
  kChunkIndex = 0x08,
  kStatistics = 0x0B,
  kSummaryOffset = 0x0E,
  kDataEnd = 0x0F,
};

using io_internal::crc32_final;
using io_internal::crc32_update;
constexpr std::uint32_t kCrcInit = io_internal::kCrc32Init;

using io_internal::put;
using io_internal::put_string;

std::string record(Opcode op, const std::string& content) {
  std::string out;
  out.reserve(9 + content.size());
  put(out, static_cast<std::uint8_t>(op));
  put(out, static_cast<std::uint64_t>(content.size()));
  return out + content;
}

std::string schema_record(std::uint16_t id, const std::string& name, const std::string& data) {
  std::string c;
  put(c, id);
  put_string(c, name);
  put_string(c, "ros2msg");
  put_string(c, data);
  return record(kSchema, c);
}

std::string channel_record(std::uint16_t id, std::uint16_t schema_id, const std::string& topic) {
  std::string c;
  put(c, id);
  put(c, schema_id);
  put_string(c, topic);
  put_string(c, "cdr");
  put(c, std::uint32_t{0});  // metadata: an empty map
  return record(kChannel, c);
}

Status write_error(const std::filesystem::path& path, const std::string& what) {
  return runtime_error(path.string() + ": cannot write the MCAP file: " + what);
}

}  // namespace

Result<McapWriter> McapWriter::open(const std::filesystem::path& path,
                                    const McapWriterOptions& options) {
  Result<AtomicFileWriter> file = AtomicFileWriter::open(path);
  if (!file) return file.error();
  McapWriter writer(std::move(*file), options);
  std::string header;
  put_string(header, "ros2");
  put_string(header, options.library);
  if (Status s = writer.append(std::string(kMagic) + record(kHeader, header)); !s) return s.error();
  return writer;
}

Status McapWriter::append(const std::string& bytes) {
  data_crc_ = crc32_update(data_crc_, bytes);
  return file_.append(bytes);
}

MessageSink::ChannelId McapWriter::channel(std::string_view topic, std::string_view type,
                                           std::string_view definition) {
  const auto key = std::make_pair(std::string(topic), std::string(type));
  if (const auto it = channel_of_.find(key); it != channel_of_.end()) return it->second;
  const auto schema = std::find_if(schemas_.begin(), schemas_.end(),
                                   [&](const Schema& s) { return s.name == type; });
  std::uint16_t schema_id = 0;
  if (schema == schemas_.end()) {
    schemas_.push_back({std::string(type), std::string(definition)});
    schema_written_.push_back(false);
    schema_id = static_cast<std::uint16_t>(schemas_.size());  // ids start at 1 (0: no schema)
  } else {
    schema_id = static_cast<std::uint16_t>(schema - schemas_.begin() + 1);
  }
  const auto id = static_cast<ChannelId>(channels_.size());
  channels_.push_back({schema_id, std::string(topic), 0, 0});
  channel_written_.push_back(false);
  channel_of_.emplace(key, id);
  return id;
}

Status McapWriter::publish(ChannelId channel, std::int64_t time_ns,
                           std::span<const std::uint8_t> cdr) {
  if (finished_) return write_error(file_.path(), "a message after finish()");
  if (channel >= channels_.size()) return write_error(file_.path(), "a message on no channel");
  Channel& c = channels_[channel];
  // A chunk carries the schema and channel records before the first message that needs them,
  // so that a reader of the data section alone (a cut file, a streaming reader) can decode it.
  if (!schema_written_[c.schema_id - 1]) {
    const Schema& s = schemas_[c.schema_id - 1];
    chunk_ += schema_record(c.schema_id, s.name, s.definition);
    schema_written_[c.schema_id - 1] = true;
  }
  if (!channel_written_[channel]) {
    chunk_ += channel_record(channel, c.schema_id, c.topic);
    channel_written_[channel] = true;
  }
  const auto t = static_cast<std::uint64_t>(std::max<std::int64_t>(time_ns, 0));
  std::string m;
  put(m, channel);
  put(m, c.sequence++);
  put(m, t);  // log time
  put(m, t);  // publish time
  m.append(reinterpret_cast<const char*>(cdr.data()), cdr.size());
  if (chunk_entries_.empty()) {
    chunk_start_ns_ = t;
    chunk_end_ns_ = t;
  }
  chunk_start_ns_ = std::min(chunk_start_ns_, t);
  chunk_end_ns_ = std::max(chunk_end_ns_, t);
  chunk_entries_[channel].emplace_back(t, chunk_.size());
  chunk_ += record(kMessage, m);
  if (message_count_ == 0) start_ns_ = end_ns_ = t;
  start_ns_ = std::min(start_ns_, t);
  end_ns_ = std::max(end_ns_, t);
  ++message_count_;
  ++c.count;
  if (chunk_.size() >= options_.chunk_bytes) return close_chunk();
  return Ok{};
}

Status McapWriter::close_chunk() {
  if (chunk_.empty()) return Ok{};
  ChunkIndex index;
  index.start_ns = chunk_start_ns_;
  index.end_ns = chunk_end_ns_;
  index.offset = file_.size();
  index.uncompressed_size = chunk_.size();
  std::string compressed;
  if (options_.zstd_level > 0) {
    compressed.resize(ZSTD_compressBound(chunk_.size()));
    const std::size_t n = ZSTD_compress(compressed.data(), compressed.size(), chunk_.data(),
                                        chunk_.size(), options_.zstd_level);
    if (ZSTD_isError(n) != 0U) return write_error(file_.path(), ZSTD_getErrorName(n));
    compressed.resize(n);
    index.compression = "zstd";
  } else {
    compressed = chunk_;
  }
  index.compressed_size = compressed.size();
  std::string c;
  put(c, index.start_ns);
  put(c, index.end_ns);
  put(c, static_cast<std::uint64_t>(chunk_.size()));
  put(c, crc32_final(crc32_update(kCrcInit, chunk_)));
  put_string(c, index.compression);
  put(c, static_cast<std::uint64_t>(compressed.size()));
  c += compressed;
  std::string bytes = record(kChunk, c);
  index.length = bytes.size();
  // The message indexes, one per channel of the chunk, right after it.
  std::uint64_t at = index.offset + bytes.size();
  for (const auto& [channel, entries] : chunk_entries_) {
    std::string m;
    put(m, channel);
    put(m, static_cast<std::uint32_t>(entries.size() * 16));
    for (const auto& [t, offset] : entries) {
      put(m, t);
      put(m, offset);
    }
    const std::string r = record(kMessageIndex, m);
    index.index_offsets[channel] = at;
    index.index_length += r.size();
    at += r.size();
    bytes += r;
  }
  chunk_.clear();
  chunk_entries_.clear();
  chunk_indexes_.push_back(std::move(index));
  return append(bytes);
}

Status McapWriter::finish() {
  if (finished_) return write_error(file_.path(), "finish() called twice");
  finished_ = true;
  if (Status s = close_chunk(); !s) return s;
  std::string data_end;
  put(data_end, crc32_final(data_crc_));
  if (Status s = file_.append(record(kDataEnd, data_end)); !s) return s;

  // Summary: schemas, channels, statistics, chunk indexes, each group's offset, then the footer.
  const std::uint64_t summary_start = file_.size();
  std::string summary;
  std::string offsets;
  const auto group = [&](Opcode op, const std::string& records) {
    if (records.empty()) return;
    std::string o;
    put(o, static_cast<std::uint8_t>(op));
    put(o, summary_start + summary.size());
    put(o, static_cast<std::uint64_t>(records.size()));
    offsets += record(kSummaryOffset, o);
    summary += records;
  };
  std::string schemas;
  for (std::size_t i = 0; i < schemas_.size(); ++i) {
    schemas +=
        schema_record(static_cast<std::uint16_t>(i + 1), schemas_[i].name, schemas_[i].definition);
  }
  group(kSchema, schemas);
  std::string channels;
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    channels +=
        channel_record(static_cast<std::uint16_t>(i), channels_[i].schema_id, channels_[i].topic);
  }
  group(kChannel, channels);
  std::string stats;
  put(stats, message_count_);
  put(stats, static_cast<std::uint16_t>(schemas_.size()));
  put(stats, static_cast<std::uint32_t>(channels_.size()));
  put(stats, std::uint32_t{0});  // attachments
  put(stats, std::uint32_t{0});  // metadata
  put(stats, static_cast<std::uint32_t>(chunk_indexes_.size()));
  put(stats, start_ns_);
  put(stats, end_ns_);
  put(stats, static_cast<std::uint32_t>(channels_.size() * 10));
  for (std::size_t i = 0; i < channels_.size(); ++i) {
    put(stats, static_cast<std::uint16_t>(i));
    put(stats, channels_[i].count);
  }
  group(kStatistics, record(kStatistics, stats));
  std::string chunks;
  for (const ChunkIndex& k : chunk_indexes_) {
    std::string c;
    put(c, k.start_ns);
    put(c, k.end_ns);
    put(c, k.offset);
    put(c, k.length);
    put(c, static_cast<std::uint32_t>(k.index_offsets.size() * 10));
    for (const auto& [channel, offset] : k.index_offsets) {
      put(c, channel);
      put(c, offset);
    }
    put(c, k.index_length);
    put_string(c, k.compression);
    put(c, k.compressed_size);
    put(c, k.uncompressed_size);
    chunks += record(kChunkIndex, c);
  }
  group(kChunkIndex, chunks);

  const std::uint64_t summary_offset_start = summary_start + summary.size();
  std::string footer_head;
  put(footer_head, static_cast<std::uint8_t>(kFooter));
  put(footer_head, std::uint64_t{8 + 8 + 4});
  put(footer_head, summary.empty() ? std::uint64_t{0} : summary_start);
  put(footer_head, summary_offset_start);
  std::uint32_t summary_crc = crc32_update(kCrcInit, summary);
  summary_crc = crc32_update(summary_crc, offsets);
  summary_crc = crc32_final(crc32_update(summary_crc, footer_head));
  std::string tail = summary + offsets + footer_head;
  put(tail, summary_crc);
  tail += kMagic;
  if (Status s = file_.append(tail); !s) return s;
  return file_.commit();
}

}  // namespace tessera
