#include "recording.hpp"

#include "tessera/io/atomic_file.hpp"

namespace tessera::cli {

void add_record_option(CLI::App& command, std::optional<std::filesystem::path>& record) {
  command.add_option("--record", record,
                     "Also record the run as ROS 2 messages to this MCAP file (zstd chunks, "
                     "summary; opens in Foxglove and with the mcap tools)");
}

Result<Recording> Recording::open(const std::optional<std::filesystem::path>& path) {
  Recording r;
  if (!path) return r;
  if (path->has_parent_path()) {
    if (Status s = ensure_directory(path->parent_path()); !s) return s.error();
  }
  Result<McapWriter> writer = McapWriter::open(*path);
  if (!writer) return writer.error();
  r.writer_.emplace(std::move(*writer));
  return r;
}

void Recording::note(Status s) {
  if (!s && first_error_.ok()) first_error_ = std::move(s);
}

Status Recording::finish() {
  if (!writer_) return Ok{};
  if (!first_error_.ok()) return first_error_;
  return writer_->finish();
}

}  // namespace tessera::cli
