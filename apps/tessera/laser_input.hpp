#pragma once
// A real robot's laser input on the command line, shared by `slam` and `localize`: a CARMEN log
// (--log) or a ROS bag (--bag with its topics and frame), optionally cut to a time window
// (--from-s / --to-s, seconds from the first scan).
#include <CLI/CLI.hpp>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera::cli {

struct LaserInput {
  std::optional<std::filesystem::path> log;
  std::optional<std::filesystem::path> bag;
  std::string scan_topic;  // --bag: empty chooses by type
  std::string odom_topic;
  std::string base_frame;  // --bag: empty is the odometry's child frame; --ros: with no_odometry
  std::optional<double> from_s;
  std::optional<double> to_s;
  bool no_odometry = false;  // --no-odometry: read the log as if it recorded none

  void add_options(CLI::App& command);
  [[nodiscard]] bool given() const { return log || bag; }
  /// The file read.
  [[nodiscard]] std::string name() const;
  /// Usage error for options that do not go together (topics without a bag, both inputs, an
  /// empty window). `live`: the input is ROS 2 topics (--ros; the caller refuses a file), which
  /// take --no-odometry and, with it, --base-frame, but no bag topic or window.
  [[nodiscard]] Status check(bool live = false) const;
  /// Reads the input and cuts it to the window; `bag_report` (may be null) gets a bag's topics
  /// and frames. Input error when the window holds no scan. With no_odometry the log comes back
  /// without odometry (sensors/laser_log.hpp's without_odometry).
  [[nodiscard]] Result<LaserLog> read(nlohmann::json* bag_report) const;
};

/// Usage error when a window's --from-s is not before its --to-s.
[[nodiscard]] Status check_window(std::optional<double> from_s, std::optional<double> to_s);

/// Keeps the scans (and odometry) of `log` from `from_s` to `to_s` seconds after its first scan
/// (either may be open). Input error naming `name` when none is left.
[[nodiscard]] Status cut_to_window(LaserLog& log, std::optional<double> from_s,
                                   std::optional<double> to_s, const std::string& name);

}  // namespace tessera::cli
