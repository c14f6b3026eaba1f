#include "recording.hpp"

#include <fmt/core.h>

#include <chrono>

#include "cli_support.hpp"
#include "tessera/io/atomic_file.hpp"

namespace tessera::cli {

void add_output_stream_options(CLI::App& command, OutputStreams& streams) {
  command.add_option("--record", streams.record,
                     "Also record the run as ROS 2 messages to this MCAP file (zstd chunks, "
                     "summary; opens in Foxglove and with the mcap tools)");
  CLI::Option* serve =
      command.add_option("--serve", streams.serve_port,
                         "Serve the run live on this port (0: any free port): a page at "
                         "http://ADDRESS:PORT/ and the Foxglove WebSocket protocol for Foxglove "
                         "or Lichtblick at ws://ADDRESS:PORT");
  command.add_option("--serve-address", streams.serve_address, "Address the live view listens on")
      ->capture_default_str()
      ->needs(serve);
  command
      .add_option("--serve-linger", streams.serve_linger_s,
                  "Seconds to keep serving after the run (negative: until Ctrl-C)")
      ->capture_default_str()
      ->needs(serve);
  command
      .add_option("--step-delay-ms", streams.step_delay_ms,
                  "Wait this long after each step so that a viewer can follow the run")
      ->check(CLI::Range(0, 60000))
      ->needs(serve);
}

Result<Recording> Recording::open(const OutputStreams& streams, const std::string& view) {
  Recording r;
  r.streams_ = streams;
  if (streams.record) {
    const std::filesystem::path& path = *streams.record;
    if (path.has_parent_path()) {
      if (Status s = ensure_directory(path.parent_path()); !s) return s.error();
    }
    Result<McapWriter> writer = McapWriter::open(path);
    if (!writer) return writer.error();
    r.writer_ = std::make_unique<McapWriter>(std::move(*writer));
  }
  if (streams.serve_port) {
    live::LiveServerOptions o;
    o.address = streams.serve_address;
    o.port = *streams.serve_port;
    o.view = view;
    Result<std::unique_ptr<live::LiveServer>> server = live::LiveServer::start(o);
    if (!server) return server.error();
    r.server_ = std::move(server).value();
    const std::string host =
        o.address.find(':') != std::string::npos ? "[" + o.address + "]" : o.address;
    // stdout, flushed: scripts and tests read the port from this line.
    fmt::print("live view: http://{}:{}/ (Foxglove: ws://{}:{})\n", host, r.server_->port(), host,
               r.server_->port());
    std::fflush(stdout);
  }
  if (r.writer_ && r.server_) {
    r.tee_ =
        std::make_unique<MessageTee>(std::vector<MessageSink*>{r.writer_.get(), r.server_.get()});
  }
  return r;
}

Recording::Recording(Recording&&) noexcept = default;
Recording& Recording::operator=(Recording&&) noexcept = default;
Recording::~Recording() = default;

MessageSink* Recording::sink() {
  if (tee_) return tee_.get();
  if (writer_) return writer_.get();
  return server_.get();
}

void Recording::step_done() {
  if (!server_) return;
  if (streams_.step_delay_ms > 0) {
    server_->serve_for(std::chrono::milliseconds(streams_.step_delay_ms));
  } else {
    server_->poll();
  }
}

void Recording::note(Status s) {
  if (!s && first_error_.ok()) first_error_ = std::move(s);
}

Status Recording::finish() {
  if (server_) server_->finish(first_error_.ok() ? "run finished" : "run failed");
  if (!first_error_.ok()) return first_error_;
  if (!writer_) return Ok{};
  return writer_->finish();
}

void Recording::linger(bool announce) {
  if (!server_) return;
  const double linger_s = streams_.serve_linger_s;
  std::fflush(stdout);  // the command's summary first
  if (announce) {
    if (linger_s < 0) {
      fmt::print(stderr, "live view: the run finished; serving until Ctrl-C\n");
    } else {
      fmt::print(stderr, "live view: the run finished; serving {:g} s more\n", linger_s);
    }
  }
  const StopSignals stop;
  const auto end =
      std::chrono::steady_clock::now() +
      std::chrono::milliseconds(static_cast<std::int64_t>(1000.0 * std::max(linger_s, 0.0)));
  while (!StopSignals::requested() && (linger_s < 0 || std::chrono::steady_clock::now() < end)) {
    server_->serve_for(std::chrono::milliseconds(100));
  }
  server_.reset();
}

}  // namespace tessera::cli
