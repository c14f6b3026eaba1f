// ROS bag format 2.0 (wiki.ros.org/Bags/Format/2.0): "#ROSBAG V2.0\n", then records
// <header_len u32><header><data_len u32><data>, a header being fields <field_len
// u32><name>=<value>. Records: bag header (op 0x03: index_pos u64, conn_count, chunk_count), chunk
// (0x05: compression "none" | "bz2" | "lz4", size = uncompressed bytes) whose data holds connection
// (0x07) and message data (0x02: conn u32, time = secs u32 + nsecs u32) records, index data (0x04)
// after each chunk, and at index_pos the connection and chunk info (0x06: chunk_pos u64, ...)
// records. Reading follows the index as rosbag's own reader does (bag header -> index_pos -> chunk
// infos
// -> each chunk at its chunk_pos), so the index data records between chunks are never walked:
// rosbag writers of 2012 wrote their data_len wrong (laser_scan_matcher's demo.bag: 5560 for 278
// 12-byte entries). A bag whose recording was cut off (index_pos 0) is read front to back.
#include <map>
#include <optional>
#include <string>

#include "internal/bag_builder.hpp"
#include "internal/decompress.hpp"
#include "internal/file_util.hpp"

namespace tessera::io_internal {
namespace {

constexpr std::string_view kMagic = "#ROSBAG V2.0\n";
enum Op : std::uint8_t {
  kMessageData = 0x02,
  kBagHeader = 0x03,
  kIndexData = 0x04,
  kChunk = 0x05,
  kChunkInfo = 0x06,
  kConnection = 0x07,
};

/// The fields of one record header (name -> value bytes).
using HeaderFields = std::map<std::string, Bytes, std::less<>>;

/// Splits a header into its fields; an empty string on success, otherwise what is wrong.
std::string parse_fields(Bytes header, HeaderFields& out) {
  ByteCursor c(header);
  while (!c.at_end()) {
    std::uint32_t len = 0;
    Bytes field;
    if (!c.u32(len)) return "header field length cut off";
    if (!c.take(len, field)) {
      return "header field of " + std::to_string(len) + " bytes runs past its header (" +
             std::to_string(c.remaining()) + " bytes left)";
    }
    const std::string_view text = as_text(field);
    const std::size_t eq = text.find('=');
    if (eq == std::string_view::npos) return "header field without '='";
    out[std::string(text.substr(0, eq))] = field.subspan(eq + 1);
  }
  return {};
}

/// One record and where it starts (for messages).
struct Record {
  std::size_t offset = 0;
  HeaderFields fields;
  Bytes data;
};

/// Reads records from one buffer (the file after the magic, or one uncompressed chunk).
class RecordReader {
 public:
  /// `where` names the buffer in errors: "<file>: byte N" or "<file>: chunk at byte N, byte M".
  RecordReader(Bytes bytes, std::size_t base_offset, std::string where)
      : cursor_(bytes), base_(base_offset), where_(std::move(where)) {}

  [[nodiscard]] bool at_end() const { return cursor_.at_end(); }
  /// Bytes read so far from this reader's buffer.
  [[nodiscard]] std::size_t position() const { return cursor_.position(); }

  /// The next record, or an error naming its offset.
  Result<Record> next() {
    Record r;
    r.offset = base_ + cursor_.position();
    std::uint32_t header_len = 0, data_len = 0;
    Bytes header;
    if (!cursor_.u32(header_len)) return error(r.offset, "record header length cut off");
    if (!cursor_.take(header_len, header)) {
      return error(r.offset, "record header of " + std::to_string(header_len) +
                                 " bytes runs past the end (" +
                                 std::to_string(cursor_.remaining()) + " bytes left)");
    }
    if (!cursor_.u32(data_len)) return error(r.offset, "record data length cut off");
    if (!cursor_.take(data_len, r.data)) {
      return error(r.offset, "record data of " + std::to_string(data_len) +
                                 " bytes runs past the end (" +
                                 std::to_string(cursor_.remaining()) + " bytes left)");
    }
    if (std::string what = parse_fields(header, r.fields); !what.empty()) {
      return error(r.offset, what);
    }
    return r;
  }

  [[nodiscard]] Error error(std::size_t offset, const std::string& what) const {
    return input_error(where_ + "byte " + std::to_string(offset) + ": " + what);
  }

 private:
  ByteCursor cursor_;
  std::size_t base_;
  std::string where_;
};

/// A fixed-size little-endian field of a record header.
template <typename T>
std::optional<T> field_uint(const HeaderFields& f, std::string_view name) {
  const auto it = f.find(name);
  if (it == f.end() || it->second.size() != sizeof(T)) return std::nullopt;
  ByteCursor c(it->second);
  T v{};
  if constexpr (sizeof(T) == 1) (void)c.u8(v);
  if constexpr (sizeof(T) == 4) (void)c.u32(v);
  if constexpr (sizeof(T) == 8) (void)c.u64(v);
  return v;
}

std::optional<std::string_view> field_text(const HeaderFields& f, std::string_view name) {
  const auto it = f.find(name);
  if (it == f.end()) return std::nullopt;
  return as_text(it->second);
}

class Ros1BagReader {
 public:
  Ros1BagReader(std::string file, BagBuilder& builder)
      : file_(std::move(file)), builder_(builder) {}

  /// The index section at index_pos (connection and chunk info records), then each chunk at the
  /// chunk_pos its chunk info gives, in that order.
  Status read_indexed(Bytes all, std::size_t index_pos) {
    RecordReader index(all.subspan(index_pos), index_pos, file_ + ": ");
    std::vector<std::pair<std::size_t, std::uint64_t>> chunk_positions;  // record, chunk_pos
    while (!index.at_end()) {
      Result<Record> r = index.next();
      if (!r) return r.error();
      const auto op = field_uint<std::uint8_t>(r->fields, "op");
      if (op == kConnection) {
        if (Status s = connection(index, *r); !s) return s;
      } else if (op == kChunkInfo) {
        const auto chunk_pos = field_uint<std::uint64_t>(r->fields, "chunk_pos");
        if (!chunk_pos) return index.error(r->offset, "chunk info record without chunk_pos");
        chunk_positions.emplace_back(r->offset, *chunk_pos);
      } else {
        return index.error(r->offset,
                           "expected connection or chunk info records after "
                           "index_pos, found op " +
                               std::to_string(op.value_or(0)));
      }
    }
    for (const auto& [info_at, chunk_pos] : chunk_positions) {
      if (chunk_pos < kMagic.size() || chunk_pos >= all.size()) {
        return index.error(info_at, "chunk_pos " + std::to_string(chunk_pos) +
                                        " lies outside the file (" + std::to_string(all.size()) +
                                        " bytes)");
      }
      const auto at = static_cast<std::size_t>(chunk_pos);
      RecordReader records(all.subspan(at), at, file_ + ": ");
      Result<Record> r = records.next();
      if (!r) return r.error();
      if (field_uint<std::uint8_t>(r->fields, "op") != kChunk) {
        return records.error(at, "the chunk info at byte " + std::to_string(info_at) +
                                     " points at a record that is not a chunk");
      }
      if (Status s = chunk(records, *r); !s) return s;
    }
    return Ok{};
  }

  /// The records of one buffer; `in_chunk` when it is an uncompressed chunk.
  Status read_records(RecordReader& records, bool in_chunk) {
    while (!records.at_end()) {
      Result<Record> r = records.next();
      if (!r) return r.error();
      const std::optional<std::uint8_t> op = field_uint<std::uint8_t>(r->fields, "op");
      if (!op) return records.error(r->offset, "record without a one-byte op field");
      Status s = Ok{};
      switch (*op) {
        case kMessageData:
          s = message(records, *r);
          break;
        case kConnection:
          s = connection(records, *r);
          break;
        case kChunk:
          if (in_chunk) return records.error(r->offset, "chunk inside a chunk");
          s = chunk(records, *r);
          break;
        case kBagHeader:
        case kIndexData:
        case kChunkInfo:
          break;
        default:
          return records.error(r->offset, "unknown record op " + std::to_string(*op));
      }
      if (!s) return s;
    }
    return Ok{};
  }

 private:
  /// Connection record: header conn, topic; data is a header with type (and md5sum,
  /// message_definition, callerid, latching, which tessera does not need).
  Status connection(const RecordReader& records, const Record& r) {
    const auto conn = field_uint<std::uint32_t>(r.fields, "conn");
    const auto topic = field_text(r.fields, "topic");
    if (!conn || !topic) return records.error(r.offset, "connection record without conn or topic");
    HeaderFields data;
    if (std::string what = parse_fields(r.data, data); !what.empty()) {
      return records.error(r.offset, "connection " + std::to_string(*conn) + ": " + what);
    }
    const auto type = field_text(data, "type");
    if (!type)
      return records.error(r.offset, "connection " + std::to_string(*conn) + " has no type");
    if (connections_.find(*conn) == connections_.end()) {
      connections_[*conn] = builder_.topic(std::string(*topic), std::string(*type), "ros1");
    }
    return Ok{};
  }

  Status message(const RecordReader& records, const Record& r) {
    const auto conn = field_uint<std::uint32_t>(r.fields, "conn");
    const auto time = field_uint<std::uint64_t>(r.fields, "time");
    if (!conn || !time) return records.error(r.offset, "message record without conn or time");
    const auto it = connections_.find(*conn);
    if (it == connections_.end()) {
      return records.error(r.offset, "message on connection " + std::to_string(*conn) +
                                         ", which no connection record before it defines");
    }
    // time: secs (low 4 bytes) then nsecs (high 4 bytes), both little endian.
    const auto secs = static_cast<std::int64_t>(*time & 0xFFFFFFFFu);
    const auto nsecs = static_cast<std::int64_t>(*time >> 32);
    builder_.message(it->second, secs * 1'000'000'000 + nsecs, r.data);
    return Ok{};
  }

  Status chunk(const RecordReader& records, const Record& r) {
    const auto compression = field_text(r.fields, "compression");
    const auto size = field_uint<std::uint32_t>(r.fields, "size");
    if (!compression || !size) {
      return records.error(r.offset, "chunk record without compression or size");
    }
    const std::string where = file_ + ": chunk at byte " + std::to_string(r.offset) + ", ";
    if (*compression == "none") {
      if (*size != r.data.size()) {
        return records.error(r.offset, "uncompressed chunk of " + std::to_string(r.data.size()) +
                                           " bytes says its size is " + std::to_string(*size));
      }
      RecordReader inner(r.data, 0, where);
      return read_records(inner, true);
    }
    if (*compression != "bz2" && *compression != "lz4") {
      return records.error(r.offset, "chunk compression '" + std::string(*compression) +
                                         "' is unknown (expected none, bz2 or lz4)");
    }
    if (std::string what = decompress(*compression, r.data, *size, buffer_); !what.empty()) {
      return records.error(r.offset, "chunk: " + what);
    }
    std::vector<std::uint8_t> uncompressed = std::move(buffer_);
    RecordReader inner(uncompressed, 0, where);
    Status s = read_records(inner, true);
    buffer_ = std::move(uncompressed);  // reuse the allocation for the next chunk
    return s;
  }

  std::string file_;
  BagBuilder& builder_;
  std::map<std::uint32_t, std::size_t> connections_;  // conn id -> topic
  std::vector<std::uint8_t> buffer_;
};

}  // namespace

Status read_ros1_bag_file(const std::filesystem::path& path, BagBuilder& builder) {
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return decode_ros1_bag(*bytes, path.string(), builder);
}

Status decode_ros1_bag(std::string_view bytes, const std::string& file, BagBuilder& builder) {
  if (!bytes.starts_with(kMagic)) {
    return input_error(file + ": not a ROS bag 2.0 (expected '#ROSBAG V2.0')");
  }
  const Bytes all = as_bytes(bytes);
  Ros1BagReader reader(file, builder);
  RecordReader first(all.subspan(kMagic.size()), kMagic.size(), file + ": ");
  Result<Record> header = first.next();
  if (!header) return header.error();
  if (field_uint<std::uint8_t>(header->fields, "op") != kBagHeader) {
    return first.error(kMagic.size(), "the first record is not the bag header (op 0x03)");
  }
  const auto index_pos = field_uint<std::uint64_t>(header->fields, "index_pos");
  if (!index_pos) return first.error(kMagic.size(), "bag header without index_pos");
  if (*index_pos == 0) {  // never indexed (recording cut off): every whole record, in order
    RecordReader records(all.subspan(kMagic.size()), kMagic.size(), file + ": ");
    return reader.read_records(records, false);
  }
  if (*index_pos < kMagic.size() + first.position() || *index_pos > all.size()) {
    return first.error(kMagic.size(), "index_pos " + std::to_string(*index_pos) +
                                          " lies outside the file (" + std::to_string(all.size()) +
                                          " bytes)");
  }
  return reader.read_indexed(all, static_cast<std::size_t>(*index_pos));
}
}  // namespace tessera::io_internal
