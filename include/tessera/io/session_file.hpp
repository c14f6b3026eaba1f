#pragma once
// A saved laser SLAM session (issue 16), the `.tsm` file `tessera slam --save` writes: everything
// a later run needs to continue the session, and what `tessera info` and `tessera session export`
// show of it. The layout is docs/session-format.md: a signature, a format version, tagged
// records, and a CRC-32 over all of it at the end. A session keeps the scans it took in (as they
// were read: the laser SLAM's result depends only on its scans and options, so they rebuild its
// whole state exactly) beside what they gave (trajectory, pose graph, map).
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/posegraph/pose_graph.hpp"
#include "tessera/sensors/laser_log.hpp"

namespace tessera {

/// The newest format version this tessera reads and writes: 4 when a scan was swept beam by beam
/// (its beams' times and its robot's velocity, the SWEP record), 3 otherwise, so that a session of
/// scans taken at once stays readable by a tessera of format 3.
inline constexpr std::uint32_t kSessionFormatVersion = 4;

/// A trajectory's start: its first scan's index in Session::scans and the T_map_robot it was
/// started at (a resumed log's, found by relocalization or given; a trimmed session's segment's,
/// where the session had it). Only a trimmed session (format 3) has a start at scan 0.
struct SessionTrajectoryStart {
  int first_scan = 0;
  Pose2 T_map_robot;
};

struct Session {
  /// The format version of the file it was read from (written: 4 with a swept scan, else 3).
  std::uint32_t format_version = kSessionFormatVersion;
  std::string tessera_version;  // of the tessera that wrote it
  std::string command;          // the command that wrote it ("slam")
  /// The command's effective configuration as --print-config writes it (read back by --config).
  std::string options_yaml;
  /// Every scan the session took in, in input order, as read (stamps, odometry, ranges).
  std::vector<StampedScan> scans;
  /// Where each trajectory after the first begins, and where the first one does when the
  /// session was trimmed (a start at scan 0), by increasing first_scan (empty: one trajectory
  /// from the origin). Replaying the scans with these starts rebuilds the session exactly.
  std::vector<SessionTrajectoryStart> trajectory_starts;
  /// T_map_robot at every scan, as optimised at the end.
  std::vector<StampedPose2> trajectory;
  /// Submaps and scan nodes (LaserSlamResult::graph) and, per vertex, its scan index or -1.
  posegraph::PoseGraph graph;
  std::vector<int> vertex_scan;
  OccupancyGrid map;
};

/// The bytes of `session` in the format of docs/session-format.md. Precondition: graph.ids is
/// empty or has one id per pose.
[[nodiscard]] std::string encode_session(const Session& session);

/// Parses a session; `name` (the file) begins every error. kInput errors: no session signature, a
/// format newer than kSessionFormatVersion, a record that runs past the end (truncated), a CRC-32
/// that does not match (damaged), a missing record, and contents that do not agree (a trajectory
/// not one pose per scan, an edge to a missing vertex, a non-finite number, a map whose size is
/// not its cells, a trajectory start that is not a scan after the first in order).
[[nodiscard]] Result<Session> decode_session(std::string_view bytes, const std::string& name);

/// Writes encode_session(session) to `path` atomically (io/atomic_file.hpp): a run killed while
/// it saves leaves the previous file as it was.
[[nodiscard]] Status write_session(const std::filesystem::path& path, const Session& session);

/// Reads and decodes `path` (kInput error naming it when it cannot be read).
[[nodiscard]] Result<Session> read_session(const std::filesystem::path& path);

/// True for a path ending in ".tsm".
[[nodiscard]] bool is_session_path(const std::filesystem::path& path);

}  // namespace tessera
