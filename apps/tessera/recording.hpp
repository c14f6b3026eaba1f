#pragma once
// --record FILE.mcap on the commands that run something: the MCAP writer while the command runs.
// The file appears only when the run and the recording both succeed (McapWriter writes to a
// temporary name); a failed run leaves nothing.
#include <CLI/CLI.hpp>
#include <filesystem>
#include <optional>

#include "tessera/core/result.hpp"
#include "tessera/io/mcap_writer.hpp"

namespace tessera::cli {

/// Adds --record to `command`.
void add_record_option(CLI::App& command, std::optional<std::filesystem::path>& record);

class Recording {
 public:
  /// Opens `path` when given (kRuntime error naming it when it cannot be created).
  [[nodiscard]] static Result<Recording> open(const std::optional<std::filesystem::path>& path);
  /// The writer, or nullptr when not recording.
  [[nodiscard]] MessageSink* sink() { return writer_ ? &*writer_ : nullptr; }
  /// Keeps the first failure of a step callback, which cannot return one; later steps are not
  /// recorded once one failed.
  void note(Status s);
  [[nodiscard]] bool failed() const { return !first_error_.ok(); }
  /// The first noted failure, else the writer's finish(). Ok when not recording.
  [[nodiscard]] Status finish();

 private:
  std::optional<McapWriter> writer_;
  Status first_error_ = Ok{};
};

}  // namespace tessera::cli
