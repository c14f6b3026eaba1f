#pragma once
// Bounded lifelong mapping (issue 16): a session resumed again and again in the same building
// keeps only what the newest passes have not seen again. A submap of an earlier trajectory whose
// cells later trajectories have observed almost all of is trimmed, with the nodes that are in no
// kept submap and their scans; what is left of each earlier trajectory is a set of contiguous
// segments, each replayed as a trajectory started where the session had it. The rule is
// Cartographer's overlapping-submaps trimmer (Hess et al.; cartographer/mapping/internal/2d/
// overlapping_submaps_trimmer_2d.cc: each cell belongs to the newest submaps that saw it, and a
// submap that owns too little is dropped), judged by trajectory rather than by submap so that a
// single run, which revisits its own rooms, is never trimmed. Decision 0029 records the choices.
#include <vector>

#include "tessera/core/stamped_pose2.hpp"
#include "tessera/posegraph/pose_graph.hpp"
#include "tessera/sensors/laser_log.hpp"
#include "tessera/slam/laser_slam.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::slam {

struct SubmapTrimOptions {
  /// A submap of an earlier trajectory is trimmed when less than this share of the cells its
  /// scans observed (hit or passed through) was observed by no later trajectory (its fresh
  /// cells), and those hold no patch that matters: less than min_fresh_area_m2 of fresh cells
  /// whose 8 neighbours are fresh too. The second test keeps a submap that alone saw a small room
  /// beside a corridor the newer pass drove again; it ignores the fringes where two passes' views
  /// end a cell apart and the gaps between a far fan of beams, which are thin.
  double min_fresh_share = 0.1;
  double min_fresh_area_m2 = 1.0;
  /// Cells of the coverage grid: coarser than the map, so that the same wall seen by two passes
  /// whose poses differ by a few centimetres falls in the same cell.
  double cell_m = 0.1;
  /// The rays as the SLAM inserts them.
  ScanPointsOptions points = LaserSlamOptions{}.points;
};

/// What a session keeps: scan indices (increasing, into the session's scans) and the starts of
/// the trajectories they form, indexed into `kept_scans`. A start at 0 places the first kept scan
/// where the session had it (when the session's own first scan was trimmed).
struct SubmapTrim {
  std::vector<int> kept_scans;
  std::vector<TrajectoryStart> starts;
  /// Per submap of an earlier trajectory, in creation order: the share of its observed cells
  /// that no later trajectory observed (what the rule compares with min_fresh_share).
  std::vector<double> fresh_shares;
  /// Per submap of an earlier trajectory: the area of its fresh cells inside fresh patches (m^2).
  std::vector<double> fresh_areas_m2;
  int submaps = 0;
  int submaps_trimmed = 0;
  int nodes = 0;
  int nodes_trimmed = 0;
};

/// Which scans of a finished session to keep. `scans` and `trajectory` (optimised T_map_robot per
/// scan) are the session's; `starts` its trajectory starts after the first (increasing
/// first_scan); `graph` and `vertex_scan` as LaserSlamResult has them (a node is in the submaps
/// with a non-robust edge from the submap's vertex to it). The newest trajectory is always kept
/// whole. Precondition: trajectory.size() == scans.size(), vertex_scan.size() ==
/// graph.poses.size(), options.cell_m > 0.
[[nodiscard]] SubmapTrim trim_covered_submaps(const std::vector<StampedScan>& scans,
                                              const std::vector<StampedPose2>& trajectory,
                                              const std::vector<TrajectoryStart>& starts,
                                              const posegraph::PoseGraph& graph,
                                              const std::vector<int>& vertex_scan,
                                              const SubmapTrimOptions& options);

/// A finished run's scans as a session keeps them after trim_covered_submaps, and the state they
/// rebuild: the kept scans replayed through the laser SLAM (run_laser_slam with the trim's
/// starts), so that what is saved is exactly what the next resume of the saved file rebuilds.
struct TrimmedRun {
  SubmapTrim trim;
  LaserLog log;  // the kept scans
  LaserSlamResult result;
};

/// Trims the run `result` of `log` with `starts` and replays what is kept with `options` (its
/// progress callback reports the replay). When nothing is trimmed there is nothing to replay:
/// log and result stay empty (the run as it is is the session). Errors as run_laser_slam's.
[[nodiscard]] Result<TrimmedRun> trim_and_replay(const LaserLog& log,
                                                 const std::vector<TrajectoryStart>& starts,
                                                 const LaserSlamResult& result,
                                                 const LaserSlamOptions& options,
                                                 const SubmapTrimOptions& trim_options);

}  // namespace tessera::slam
