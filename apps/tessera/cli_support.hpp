#pragma once
// Glue shared by the subcommands: exit codes, error lines, progress on a terminal, loading a world.
#include <CLI/CLI.hpp>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::cli {

inline constexpr int kExitOk = 0;
inline constexpr int kExitUsage = 2;
inline constexpr int kExitInput = 3;
inline constexpr int kExitRuntime = 4;

/// 2 usage, 3 input, 4 runtime.
[[nodiscard]] int exit_code(const Error& e);
/// Prints "tessera: <message>" on stderr and returns exit_code(e).
int report_error(const Error& e);

/// Wall-clock seconds since t0 (the `timing.wall_s` of every report).
[[nodiscard]] inline double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

/// Ctrl-C and SIGTERM, while an object lives, ask the command to stop instead of killing it
/// (a node finishes its step and exits cleanly; the live view stops lingering). The handlers that
/// were there before come back when it goes.
class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  [[nodiscard]] static bool requested();

 private:
  void (*old_int_)(int);
  void (*old_term_)(int);
};

/// True when stderr is a terminal (progress lines are shown only there).
[[nodiscard]] bool stderr_is_terminal();

/// A one-line progress display that appears only on a terminal, only after the run has lasted a
/// second, and is erased when done.
class ProgressLine {
 public:
  explicit ProgressLine(bool enabled);
  ~ProgressLine();
  void show(const std::string& text);
  /// A bar for `done` of `total` units of work, then `text`, the elapsed time, the rate in
  /// `unit`s per second and the time left at that rate: "[#####.......]  41%  scan 2262/5505
  /// 0:16 elapsed  141 scans/s  0:23 left".
  void show(const std::string& text, std::int64_t done, std::int64_t total,
            const std::string& unit);
  void finish();

 private:
  bool enabled_;
  bool shown_ = false;
  std::chrono::steady_clock::time_point start_;
};

struct WorldSource {
  std::optional<std::filesystem::path> file;  // empty: the built-in world
  std::string builtin = "office";
  std::optional<double> map_resolution_m;  // for files that carry none (images, Moving AI)
  std::optional<std::string> crop;         // "X0,Y0,X1,Y1" in metres
};

/// Adds --world, --builtin, --map-resolution-m and --crop, which fill `source`.
void add_world_options(CLI::App& command, WorldSource& source);

/// Loads the ground-truth world from a map file (any format io::load_map reads) or a built-in one,
/// cropped to source.crop when given (usage error for a malformed or empty rectangle).
[[nodiscard]] Result<World> load_world(const WorldSource& source, double builtin_resolution_m);

/// "3.5,2" -> {3.5, 2}; usage error otherwise.
[[nodiscard]] Result<Vec2> parse_point(const std::string& text, const std::string& option);
/// "X,Y" or "X,Y,THETA" (metres, radians) -> a pose; usage error naming the option otherwise.
[[nodiscard]] Result<Pose2> parse_pose(const std::string& text, const std::string& option);

}  // namespace tessera::cli
