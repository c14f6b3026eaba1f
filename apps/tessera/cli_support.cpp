#include "cli_support.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <sstream>

#include "tessera/io/map_file.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera::cli {

int exit_code(const Error& e) {
  switch (e.kind) {
    case ErrorKind::kUsage:
      return kExitUsage;
    case ErrorKind::kInput:
      return kExitInput;
    case ErrorKind::kRuntime:
      return kExitRuntime;
  }
  return kExitRuntime;
}

int report_error(const Error& e) {
  fmt::print(stderr, "tessera: {}\n", e.message);
  return exit_code(e);
}

namespace {

volatile std::sig_atomic_t g_stop_requested = 0;
extern "C" void request_stop(int) { g_stop_requested = 1; }

}  // namespace

StopSignals::StopSignals()
    : old_int_(std::signal(SIGINT, request_stop)), old_term_(std::signal(SIGTERM, request_stop)) {
  g_stop_requested = 0;
}

StopSignals::~StopSignals() {
  std::signal(SIGINT, old_int_);
  std::signal(SIGTERM, old_term_);
}

bool StopSignals::requested() { return g_stop_requested != 0; }

bool stderr_is_terminal() { return isatty(fileno(stderr)) != 0; }

ProgressLine::ProgressLine(bool enabled)
    : enabled_(enabled), start_(std::chrono::steady_clock::now()) {}

ProgressLine::~ProgressLine() { finish(); }

void ProgressLine::show(const std::string& text) {
  if (!enabled_) return;
  if (!shown_ && std::chrono::steady_clock::now() - start_ < std::chrono::seconds(1)) return;
  fmt::print(stderr, "\r\033[K{}", text);
  std::fflush(stderr);
  shown_ = true;
}

namespace {

// "m:ss" (or "h:mm:ss") of a duration.
std::string clock_text(double seconds) {
  const auto s = static_cast<long long>(std::max(0.0, seconds) + 0.5);
  if (s >= 3600) return fmt::format("{}:{:02}:{:02}", s / 3600, (s / 60) % 60, s % 60);
  return fmt::format("{}:{:02}", s / 60, s % 60);
}

}  // namespace

void ProgressLine::show(const std::string& text, std::int64_t done, std::int64_t total,
                        const std::string& unit) {
  if (!enabled_) return;
  const double elapsed_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  const double fraction =
      total > 0 ? std::clamp(static_cast<double>(done) / static_cast<double>(total), 0.0, 1.0)
                : 0.0;
  constexpr int kWidth = 24;
  const int filled = static_cast<int>(fraction * kWidth);
  std::string line =
      "[" + std::string(static_cast<std::size_t>(filled), '#') +
      std::string(static_cast<std::size_t>(kWidth - filled), '.') + "] " +
      fmt::format("{:3.0f}%  {}  {} elapsed", 100.0 * fraction, text, clock_text(elapsed_s));
  if (elapsed_s > 0.0 && done > 0) {
    const double rate = static_cast<double>(done) / elapsed_s;
    line += fmt::format("  {:.0f} {}/s  {} left", rate, unit,
                        clock_text(static_cast<double>(total - done) / rate));
  }
  show(line);
}

void ProgressLine::finish() {
  if (shown_) fmt::print(stderr, "\r\033[K");
  shown_ = false;
}

void add_world_options(CLI::App& command, WorldSource& source) {
  command.add_option("--world", source.file,
                     "Ground-truth map: ROS map_server .yaml, Stage .world, Moving AI .map, "
                     "HouseExpo .json, or a .png/.pgm floor plan (needs --map-resolution-m). "
                     "Default: the built-in world --builtin.");
  command.add_option("--builtin", source.builtin, "Built-in world when --world is not given")
      ->capture_default_str();
  command.add_option("--map-resolution-m", source.map_resolution_m,
                     "Cell size of a --world file that carries none (image, Moving AI: 1.0)");
  command.add_option("--crop", source.crop,
                     "X0,Y0,X1,Y1 in metres: use only this rectangle of the world (a room cut "
                     "from a floor plan); its edge bounds the space");
}

namespace {

Result<World> crop_world(const World& world, const std::string& text) {
  std::istringstream in(text);
  double v[4] = {};
  char comma[3] = {};
  if (!(in >> v[0] >> comma[0] >> v[1] >> comma[1] >> v[2] >> comma[2] >> v[3]) ||
      comma[0] != ',' || comma[1] != ',' || comma[2] != ',' || !(in >> std::ws).eof()) {
    return usage_error(fmt::format("--crop expects X0,Y0,X1,Y1 in metres, got '{}'", text));
  }
  if (!(v[2] > v[0] && v[3] > v[1])) {
    return usage_error(fmt::format("--crop {}: needs X1 > X0 and Y1 > Y0", text));
  }
  World cropped = world.cropped({v[0], v[1]}, {v[2], v[3]});
  if (cropped.free_count() == 0) {
    return input_error(fmt::format("--crop {}: no free cell of the world inside it", text));
  }
  return cropped;
}

}  // namespace

Result<World> load_world(const WorldSource& source, double builtin_resolution_m) {
  if (!source.file) {
    World w = builtin_world(source.builtin, builtin_resolution_m);
    if (w.geometry().size() == 0) {
      std::string names;
      for (const auto& n : builtin_world_names()) names += (names.empty() ? "" : ", ") + n;
      return usage_error(
          fmt::format("unknown built-in world '{}' (built-in worlds: {})", source.builtin, names));
    }
    return source.crop ? crop_world(w, *source.crop) : Result<World>(std::move(w));
  }
  MapLoadOptions options;
  options.resolution_m = source.map_resolution_m;
  Result<LoadedMap> loaded = load_map(*source.file, options);
  if (!loaded) return loaded.error();
  World w = World::from_map(loaded->map, 0.5, source.file->string());
  if (!source.crop) return w;
  Result<World> cropped = crop_world(w, *source.crop);
  if (!cropped) {
    Error e = cropped.error();
    if (e.kind == ErrorKind::kInput) e.message = source.file->string() + ": " + e.message;
    return e;
  }
  return cropped;
}

Result<Vec2> parse_point(const std::string& text, const std::string& option) {
  std::istringstream in(text);
  Vec2 p;
  char comma = 0;
  if (!(in >> p.x >> comma >> p.y) || comma != ',' || !(in >> std::ws).eof()) {
    return usage_error(fmt::format("{} expects X,Y in metres, got '{}'", option, text));
  }
  return p;
}

Result<Pose2> parse_pose(const std::string& text, const std::string& option) {
  double x = 0.0, y = 0.0, theta = 0.0;
  char extra = 0;
  const int n = std::sscanf(text.c_str(), "%lf,%lf,%lf%c", &x, &y, &theta, &extra);
  if ((n != 2 && n != 3) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(theta)) {
    return usage_error(fmt::format(
        "{}: expected X,Y or X,Y,THETA in metres and radians, got '{}'", option, text));
  }
  return Pose2{x, y, theta};
}

}  // namespace tessera::cli
