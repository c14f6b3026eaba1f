// MCAP (mcap.dev/spec, version 0), read front to back: the magic "\x89MCAP0\r\n", then records
// <opcode u8><length u64><content> up to the Footer (0x02) and the closing magic. Used: Schema
// (0x03: id u16, name, encoding, data), Channel (0x04: id u16, schema_id u16, topic,
// message_encoding, metadata), Message (0x05: channel_id u16, sequence u32, log_time u64,
// publish_time u64, data) and Chunk (0x06: message_start_time, message_end_time,
// uncompressed_size u64, uncompressed_crc u32, compression "" | "zstd" | "lz4", records
// u64-prefixed) whose records are Schemas, Channels and Messages. Index, statistics, attachment,
// metadata and summary records are skipped (the summary repeats schemas and channels; repeats are
// ignored). Strings are u32-length-prefixed UTF-8. CRCs are not checked.
#include <map>
#include <string>

#include "internal/bag_builder.hpp"
#include "internal/decompress.hpp"
#include "internal/file_util.hpp"

namespace tessera::io_internal {
namespace {

constexpr std::string_view kMagic = "\x89MCAP0\r\n";
enum Opcode : std::uint8_t {
  kHeader = 0x01,
  kFooter = 0x02,
  kSchema = 0x03,
  kChannel = 0x04,
  kMessage = 0x05,
  kChunk = 0x06,
};

/// Reads the fields of one record's content; the first failure names the field.
class Fields {
 public:
  explicit Fields(Bytes content) : c_(content) {}
  [[nodiscard]] bool ok() const { return what_.empty(); }
  [[nodiscard]] const std::string& what() const { return what_; }

  std::uint16_t u16(const char* name) {
    std::uint16_t v = 0;
    if (ok() && !c_.u16(v)) cut(name);
    return v;
  }
  std::uint32_t u32(const char* name) {
    std::uint32_t v = 0;
    if (ok() && !c_.u32(v)) cut(name);
    return v;
  }
  std::uint64_t u64(const char* name) {
    std::uint64_t v = 0;
    if (ok() && !c_.u64(v)) cut(name);
    return v;
  }
  std::string string(const char* name) { return std::string(as_text(prefixed(u32(name), name))); }
  /// A u32- or u64-length-prefixed byte field.
  Bytes prefixed(std::uint64_t n, const char* name) {
    Bytes b;
    if (!ok()) return b;
    if (n > c_.remaining() || !c_.take(static_cast<std::size_t>(n), b)) {
      what_ = std::string(name) + " of " + std::to_string(n) + " bytes runs past its record (" +
              std::to_string(c_.remaining()) + " bytes left)";
    }
    return b;
  }
  Bytes rest() const { return c_.rest(); }

 private:
  void cut(const char* name) { what_ = std::string(name) + " cut off"; }
  ByteCursor c_;
  std::string what_;
};

class McapReader {
 public:
  McapReader(std::string file, BagBuilder& builder) : file_(std::move(file)), builder_(builder) {}

  /// Records of the data section (the file after the magic) or of one chunk. Returns true in
  /// `footer` when the Footer was reached.
  Status read_records(Bytes bytes, std::size_t base, bool in_chunk, const std::string& where,
                      bool& footer) {
    ByteCursor c(bytes);
    while (!c.at_end()) {
      const std::size_t offset = base + c.position();
      auto error = [&](const std::string& what) {
        return input_error(where + "byte " + std::to_string(offset) + ": " + what);
      };
      std::uint8_t op = 0;
      std::uint64_t length = 0;
      Bytes content;
      if (!c.u8(op) || !c.u64(length)) return error("record opcode or length cut off");
      if (length > c.remaining() || !c.take(static_cast<std::size_t>(length), content)) {
        return error("record of " + std::to_string(length) + " bytes runs past the end (" +
                     std::to_string(c.remaining()) + " bytes left)");
      }
      std::string what;
      switch (op) {
        case kSchema:
          what = schema(content);
          break;
        case kChannel:
          what = channel(content);
          break;
        case kMessage:
          what = message(content);
          break;
        case kChunk:
          if (in_chunk) return error("chunk inside a chunk");
          if (Status s = chunk(content, offset); !s) return s;
          break;
        case kFooter:
          if (in_chunk) return error("footer inside a chunk");
          footer = true;
          if (c.remaining() != kMagic.size() || as_text(c.rest()) != kMagic) {
            return error("the footer is not followed by the closing magic");
          }
          return Ok{};
        default:
          break;  // header, indexes, statistics, attachments, metadata, summary offsets, data end
      }
      if (!what.empty()) return error(what);
    }
    return Ok{};
  }

 private:
  std::string schema(Bytes content) {
    Fields f(content);
    const std::uint16_t id = f.u16("schema id");
    std::string name = f.string("schema name");
    f.string("schema encoding");
    f.prefixed(f.u32("schema data length"), "schema data");
    if (!f.ok()) return "schema: " + f.what();
    if (id == 0) return "schema id 0 is reserved";
    schemas_.emplace(id, std::move(name));
    return {};
  }

  std::string channel(Bytes content) {
    Fields f(content);
    const std::uint16_t id = f.u16("channel id");
    const std::uint16_t schema_id = f.u16("channel schema_id");
    const std::string topic = f.string("channel topic");
    const std::string encoding = f.string("channel message_encoding");
    f.prefixed(f.u32("channel metadata length"), "channel metadata");
    if (!f.ok()) return "channel: " + f.what();
    if (channels_.count(id) != 0) return {};
    std::string type;
    if (schema_id != 0) {
      const auto it = schemas_.find(schema_id);
      if (it == schemas_.end()) {
        return "channel " + std::to_string(id) + " names schema " + std::to_string(schema_id) +
               ", which no schema record before it defines";
      }
      type = it->second;
    }
    channels_[id] = builder_.topic(topic, type, encoding);
    return {};
  }

  std::string message(Bytes content) {
    Fields f(content);
    const std::uint16_t channel = f.u16("message channel_id");
    f.u32("message sequence");
    const std::uint64_t log_time = f.u64("message log_time");
    f.u64("message publish_time");
    if (!f.ok()) return "message: " + f.what();
    const auto it = channels_.find(channel);
    if (it == channels_.end()) {
      return "message on channel " + std::to_string(channel) +
             ", which no channel record before it defines";
    }
    builder_.message(it->second, static_cast<std::int64_t>(log_time), f.rest());
    return {};
  }

  Status chunk(Bytes content, std::size_t offset) {
    const std::string at = file_ + ": byte " + std::to_string(offset) + ": chunk: ";
    Fields f(content);
    f.u64("message_start_time");
    f.u64("message_end_time");
    const std::uint64_t size = f.u64("uncompressed_size");
    f.u32("uncompressed_crc");
    const std::string compression = f.string("compression");
    const Bytes records = f.prefixed(f.u64("records length"), "records");
    if (!f.ok()) return input_error(at + f.what());
    const std::string where = file_ + ": chunk at byte " + std::to_string(offset) + ", ";
    bool footer = false;
    if (compression.empty()) {
      if (size != records.size()) {
        return input_error(at + "uncompressed chunk of " + std::to_string(records.size()) +
                           " bytes says uncompressed_size " + std::to_string(size));
      }
      return read_records(records, 0, true, where, footer);
    }
    if (compression != "zstd" && compression != "lz4") {
      return input_error(at + "compression '" + compression +
                         "' is unknown (expected none, zstd or lz4)");
    }
    if (std::string what = decompress(compression, records, size, buffer_); !what.empty()) {
      return input_error(at + what);
    }
    std::vector<std::uint8_t> uncompressed = std::move(buffer_);
    Status s = read_records(uncompressed, 0, true, where, footer);
    buffer_ = std::move(uncompressed);
    return s;
  }

  std::string file_;
  BagBuilder& builder_;
  std::map<std::uint16_t, std::string> schemas_;   // id -> schema name (the message type)
  std::map<std::uint16_t, std::size_t> channels_;  // id -> topic
  std::vector<std::uint8_t> buffer_;
};

}  // namespace

Status read_mcap_file(const std::filesystem::path& path, BagBuilder& builder) {
  Result<std::string> bytes = read_file_bytes(path);
  if (!bytes) return bytes.error();
  return decode_mcap(*bytes, path.string(), builder);
}

Status decode_mcap(std::string_view bytes, const std::string& file, BagBuilder& builder) {
  if (!bytes.starts_with(kMagic)) return input_error(file + ": not an MCAP file (no magic)");
  McapReader reader(file, builder);
  bool footer = false;
  const Bytes all = as_bytes(bytes);
  if (Status s = reader.read_records(all.subspan(kMagic.size()), kMagic.size(), false, file + ": ",
                                     footer);
      !s) {
    return s;
  }
  if (!footer) return input_error(file + ": ends without a footer record (truncated?)");
  return Ok{};
}

}  // namespace tessera::io_internal
