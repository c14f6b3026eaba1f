// read_ros_bag: decides what the path is (a ROS 1 bag, a rosbag2 folder, a .db3 or an .mcap file)
// and runs the format reader on each storage file. rosbag2's metadata.yaml (rosbag2_storage,
// metadata_io.cpp, versions 1 to 9): storage_identifier, relative_file_paths, compression_format
// and compression_mode (rosbag2_compression: zstd, each storage file compressed whole (FILE) or
// each message's bytes (MESSAGE)).
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <fstream>
#include <limits>

#include "internal/bag_builder.hpp"
#include "internal/decompress.hpp"
#include "internal/file_util.hpp"
#include "tessera/core/time_ns.hpp"

namespace tessera {
namespace {

using io_internal::BagBuilder;

/// The first bytes of a file (fewer when it is shorter); empty when it cannot be read.
std::string file_head(const std::filesystem::path& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string head(n, '\0');
  in.read(head.data(), static_cast<std::streamsize>(n));
  head.resize(static_cast<std::size_t>(std::max<std::streamsize>(0, in.gcount())));
  return head;
}

constexpr std::string_view kMcapMagic = "\x89MCAP0\r\n";
constexpr std::string_view kSqliteMagic = "SQLite format 3";
constexpr std::string_view kRos1Magic = "#ROSBAG V2.0\n";
constexpr std::string_view kRos1LegacyMagic = "#ROSRECORD V1.2";

/// One storage file, by its first bytes.
Status read_storage_file(const std::filesystem::path& path, BagBuilder& builder,
                         std::string_view format) {
  const std::string head = file_head(path, 16);
  builder.add_file(path);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  builder.set_size_hint(ec ? 0 : static_cast<std::size_t>(size));
  if (head.starts_with(kMcapMagic)) {
    if (format.empty()) builder.set_format("MCAP");
    return io_internal::read_mcap_file(path, builder);
  }
  if (head.starts_with(kSqliteMagic)) {
    if (format.empty()) builder.set_format("rosbag2 (sqlite3)");
    return io_internal::read_rosbag2_sqlite_file(path, builder);
  }
  if (head.starts_with(kRos1Magic)) {
    if (format.empty()) builder.set_format("ROS 1 bag 2.0");
    return io_internal::read_ros1_bag_file(path, builder);
  }
  if (head.starts_with(kRos1LegacyMagic)) {
    return input_error(path.string() +
                       ": legacy ROS bag format 1.2 (#ROSRECORD V1.2) is not supported; "
                       "convert it with 'rosbag fix' or 'rosbag reindex' to format 2.0");
  }
  if (!std::filesystem::exists(path, ec)) return input_error(path.string() + ": no such file");
  return input_error(path.string() +
                     ": not a ROS bag (expected '#ROSBAG V2.0', an MCAP or a sqlite3 file)");
}

/// The most a compressed rosbag2 storage file may decompress to (it is read into memory): 4 GiB.
constexpr std::uint64_t kMaxStorageFileBytes = std::uint64_t{1} << 32;

/// A storage file that rosbag2 compressed whole (compression_mode FILE): "run_0.db3.zstd" or
/// "run_0.mcap.zstd", decompressed in memory and read by its first bytes.
Status read_zstd_storage_file(const std::filesystem::path& path, BagBuilder& builder) {
  Result<std::string> bytes = io_internal::read_file_bytes(path);
  if (!bytes) return bytes.error();
  std::vector<std::uint8_t> plain;
  const auto* data = reinterpret_cast<const std::uint8_t*>(bytes->data());
  if (std::string e = io_internal::decompress_zstd(io_internal::Bytes(data, bytes->size()),
                                                   kMaxStorageFileBytes, plain);
      !e.empty()) {
    return input_error(path.string() + ": " + e);
  }
  builder.add_file(path);
  builder.set_size_hint(plain.size());
  const std::string_view view(reinterpret_cast<const char*>(plain.data()), plain.size());
  if (view.starts_with(kMcapMagic)) return io_internal::decode_mcap(view, path.string(), builder);
  if (view.starts_with(kSqliteMagic)) {
    return io_internal::decode_rosbag2_sqlite(view, path.string(), builder);
  }
  return input_error(path.string() +
                     ": decompressed, neither an MCAP nor a sqlite3 file (expected rosbag2's)");
}

/// A rosbag2 folder: metadata.yaml names the storage and the files.
Status read_rosbag2_folder(const std::filesystem::path& dir, BagBuilder& builder) {
  const std::filesystem::path yaml = dir / "metadata.yaml";
  const std::string name = yaml.string();
  YAML::Node info;
  try {
    info = YAML::LoadFile(yaml.string())["rosbag2_bagfile_information"];
  } catch (const YAML::BadFile&) {
    return input_error(dir.string() + ": a folder without metadata.yaml is not a rosbag2 bag");
  } catch (const YAML::Exception& e) {
    return input_error(name + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (!info || !info.IsMap()) {
    return input_error(name + ": expected the key rosbag2_bagfile_information");
  }
  std::string storage, compression, mode;
  std::vector<std::string> files;
  try {
    storage = info["storage_identifier"] ? info["storage_identifier"].as<std::string>() : "";
    compression = info["compression_format"] ? info["compression_format"].as<std::string>() : "";
    mode = info["compression_mode"] ? info["compression_mode"].as<std::string>() : "";
    if (info["relative_file_paths"]) {
      for (const YAML::Node& f : info["relative_file_paths"]) files.push_back(f.as<std::string>());
    }
  } catch (const YAML::Exception& e) {
    return input_error(name + ":" + std::to_string(e.mark.line + 1) + ": " + e.msg);
  }
  if (storage != "sqlite3" && storage != "mcap") {
    return input_error(name + ": storage_identifier is '" + storage +
                       "', expected sqlite3 or mcap");
  }
  std::transform(mode.begin(), mode.end(), mode.begin(),
                 [](unsigned char c) { return static_cast<char>(std::toupper(c)); });
  if (!compression.empty() && compression != "zstd") {
    return input_error(name + ": compression_format '" + compression +
                       "' is not supported (rosbag2 compresses with zstd); decompress with 'ros2 "
                       "bag convert'");
  }
  const bool compressed = !compression.empty();
  if (compressed && mode != "FILE" && mode != "MESSAGE" && !mode.empty()) {
    return input_error(name + ": compression_mode '" + mode + "', expected FILE or MESSAGE");
  }
  const bool per_message = compressed && mode == "MESSAGE";
  const bool whole_files = compressed && !per_message;  // FILE, rosbag2's default mode
  if (files.empty()) return input_error(name + ": relative_file_paths lists no file");
  builder.set_format("rosbag2 (" + storage + (compressed ? ", zstd" : "") + ")");
  if (per_message) builder.zstd_messages();
  for (const std::string& f : files) {
    const std::filesystem::path p = dir / f;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(p, ec)) {
      return input_error(name + ": storage file " + f + " is missing");
    }
    Status read =
        whole_files ? read_zstd_storage_file(p, builder) : read_storage_file(p, builder, "rosbag2");
    if (!read) return read;
    if (!builder.message_error().empty()) {
      return input_error(p.string() + ": " + builder.message_error());
    }
  }
  return Ok{};
}

}  // namespace

double BagTopic::rate_hz() const {
  if (message_count < 2 || last_ns <= first_ns) return 0.0;
  const double span_s = 1e-9 * ns_difference(last_ns, first_ns);
  return static_cast<double>(message_count - 1) / span_s;
}

double RosBag::duration_s() const { return 1e-9 * ns_difference(end_ns(), start_ns()); }

std::uint64_t RosBag::message_count() const {
  std::uint64_t n = 0;
  for (const BagTopic& t : topics) n += t.message_count;
  return n;
}

std::int64_t RosBag::start_ns() const {
  std::int64_t t = std::numeric_limits<std::int64_t>::max();
  for (const BagTopic& topic : topics) {
    if (topic.message_count > 0) t = std::min(t, topic.first_ns);
  }
  return t == std::numeric_limits<std::int64_t>::max() ? 0 : t;
}

std::int64_t RosBag::end_ns() const {
  std::int64_t t = std::numeric_limits<std::int64_t>::min();
  for (const BagTopic& topic : topics) {
    if (topic.message_count > 0) t = std::max(t, topic.last_ns);
  }
  return t == std::numeric_limits<std::int64_t>::min() ? 0 : t;
}

bool is_ros_bag_path(const std::filesystem::path& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    return std::filesystem::exists(path / "metadata.yaml", ec);
  }
  const std::string ext = io_internal::lower_extension(path);
  return ext == ".bag" || ext == ".db3" || ext == ".mcap";
}

Result<RosBag> read_ros_bag(const std::filesystem::path& path, const BagReadOptions& options) {
  BagBuilder builder(options);
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) return input_error(path.string() + ": no such file");
  const Status read = std::filesystem::is_directory(status) ? read_rosbag2_folder(path, builder)
                                                            : read_storage_file(path, builder, "");
  if (!read) return read.error();
  return std::move(builder).finish();
}

}  // namespace tessera
