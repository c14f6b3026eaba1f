#pragma once
// --record FILE.mcap and --serve PORT on the commands that run something: the MCAP writer and the
// live view's server while the command runs. The file appears only when the run and the
// recording both succeed (McapWriter writes to a temporary name); a failed run leaves nothing.
// The live view prints its address when it starts, tells its viewers when the run finished, and
// keeps serving after the command's outputs are written until Ctrl-C (or --serve-linger).
#include <CLI/CLI.hpp>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/io/mcap_writer.hpp"
#include "tessera/io/message_tee.hpp"
#include "tessera/live/live_server.hpp"

namespace tessera::cli {

struct OutputStreams {
  std::optional<std::filesystem::path> record;
  std::optional<std::uint16_t> serve_port;
  std::string serve_address = "127.0.0.1";
  /// Seconds to keep serving after the run; negative: until Ctrl-C or SIGTERM.
  double serve_linger_s = -1.0;
  /// Wall milliseconds each step waits (serving) so that a viewer can follow a fast run.
  int step_delay_ms = 0;
};

/// Adds --record, --serve, --serve-address, --serve-linger and --step-delay-ms.
void add_output_stream_options(CLI::App& command, OutputStreams& streams);

class Recording {
 public:
  /// Opens the recording and starts the live view as asked (kRuntime error naming the file or
  /// the address when either cannot be opened); prints the live view's address. `view` names
  /// the kind of run for the page ("explore", "slam", "bob", "fusion").
  [[nodiscard]] static Result<Recording> open(const OutputStreams& streams,
                                              const std::string& view);

  Recording() = default;
  Recording(Recording&&) noexcept;
  Recording& operator=(Recording&&) noexcept;
  ~Recording();

  /// The recording and the live view together, or the one there is; nullptr when neither.
  [[nodiscard]] MessageSink* sink();
  /// The MCAP recording alone; nullptr when not recording.
  [[nodiscard]] MessageSink* file_sink() { return writer_.get(); }
  /// The live view alone (for messages only a viewer wants, such as SLAM's per-scan estimate);
  /// nullptr when not serving.
  [[nodiscard]] MessageSink* live_sink() { return server_.get(); }
  /// After each step of the run: lets the live view serve (for --step-delay-ms).
  void step_done();
  /// `on_step` followed by step_done() when serving, else `on_step` as it is. The Recording must
  /// outlive the callback.
  template <typename Step>
  [[nodiscard]] std::function<void(const Step&)> paced(std::function<void(const Step&)> on_step) {
    if (!server_) return on_step;
    return [this, on_step = std::move(on_step)](const Step& s) {
      if (on_step) on_step(s);
      step_done();
    };
  }
  /// Keeps the first failure of a step callback, which cannot return one; later steps are not
  /// recorded once one failed.
  void note(Status s);
  [[nodiscard]] bool failed() const { return !first_error_.ok(); }
  /// The first noted failure, else the writer's finish(); tells live viewers the run ended.
  /// Ok when neither recording nor serving.
  [[nodiscard]] Status finish();
  /// When serving: keeps serving (after the command printed its summary) until Ctrl-C, SIGTERM
  /// or the linger time, then closes. Prints what it waits for when `announce`.
  void linger(bool announce);

 private:
  // Behind pointers: the tee points at them and a Recording moves.
  std::unique_ptr<McapWriter> writer_;
  std::unique_ptr<live::LiveServer> server_;
  std::unique_ptr<MessageTee> tee_;
  OutputStreams streams_;
  Status first_error_ = Ok{};
};

}  // namespace tessera::cli
