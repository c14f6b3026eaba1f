#pragma once
// What `tessera localize` and `tessera slam --resume` both do with a saved session (issue 16):
// check that a log's laser is the session's, freeze the session's map for the localizer, and
// find where a new log starts in it.
#include <optional>
#include <string>

#include "tessera/core/result.hpp"
#include "tessera/io/session_file.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/localizer.hpp"

namespace tessera::cli {

/// Input error naming `log_name` and `session_name` when the log's laser is not the session's
/// (beam count, first angle, angle step): a map made with one laser cannot be matched with the
/// scans of another laid out otherwise. Precondition: both hold scans.
[[nodiscard]] Status check_same_laser(const Session& session, const LaserLog& log,
                                      const std::string& session_name, const std::string& log_name);

/// The session's frozen map (slam::frozen_map with the SLAM's point and submap settings, at the
/// session map's resolution). Input error naming the session when it knows no cell.
[[nodiscard]] Result<slam::ProbabilityGrid> session_frozen_map(
    const Session& session, const slam::LocalizerOptions& options, const std::string& session_name);

/// Where a log starts in a session's map, found by global relocalization (no initial pose).
struct FoundStart {
  Pose2 T_map_robot;     // of the log's first scan
  double found_after_s;  // data time from the first scan to the first confident pose
};

/// Runs a localizer over `log` until its first confident pose, and carries that pose back to the
/// first scan through the odometry between them. nullopt when no scan of the log is confidently
/// placed.
[[nodiscard]] std::optional<FoundStart> find_log_start(slam::Localizer& localizer,
                                                       const LaserLog& log);

}  // namespace tessera::cli
