#pragma once
// Where a teammate's map lies in ours when neither robot knows where the other started (issue 14:
// "unknown start poses through map matching"; the lecture's robots that explore in parallel and
// share partial maps). Two steps:
//  1. Search: the teammate's obstacle cells, as a point cloud, are matched against our map over
//     every translation that overlaps it and a full turn, by the branch-and-bound correlative
//     matcher of the laser SLAM's loop closure (Olson 2009; Hess et al. 2016, Algorithm 3) on a
//     coarse copy of our map, then refined at full resolution.
//  2. Acceptance: the best pose of any search is only the least bad one, so it is checked cell by
//     cell, as Birk & Carpin (2006, "Merging occupancy grid maps from multiple robots") check a
//     merge by the agreement of the two maps where both know the space: the maps must share a
//     large enough area, hardly ever hold an obstacle where the other holds free space, and most
//     of the teammate's walls inside our known space must lie on our walls.
// A robot that places a teammate on one accepted match can still be fooled by a building that
// repeats itself; the explorer (nodes/explorer_node.hpp) therefore also asks that successive
// matches on the growing maps agree before it merges.
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera::team {

struct MapMatchOptions {
  /// Cell size of the global search (our map is max-pooled to it); the result is refined at the
  /// maps' own resolution. Coarser is faster and more tolerant of small map distortions.
  double search_resolution_m = 0.1;
  /// A cell with p >= this is an obstacle, with p <= free_below free space.
  double occupied_from = 0.65;
  double free_below = 0.35;
  /// Acceptance: the area both maps know (m^2) ...
  double min_overlap_m2 = 6.0;
  /// ... the share of it where one map holds an obstacle that the other holds free with no
  /// obstacle in the 3 x 3 cells around ...
  double max_conflict = 0.01;
  /// ... and the share of the teammate's obstacle cells inside our known space that have one of
  /// ours within one cell.
  double min_wall_agreement = 0.85;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const MapMatchOptions& o);

/// The best pose found and how well the maps agree there.
struct MapMatch {
  Pose2 T_fixed_moving;     // the moving map's frame in the fixed map's frame
  double score = 0.0;       // the search's mean probability at the moved obstacle points
  double overlap_m2 = 0.0;  // area known in both maps
  double conflict = 0.0;    // share of the overlap
  double wall_agreement = 0.0;
  bool accepted = false;  // every acceptance rule holds
};

/// Matches `moving` (a teammate's map in its own frame) against `fixed` (ours). nullopt when
/// either map has no obstacle cell or no pose scores above chance. kInput error when the
/// resolutions differ or the options are invalid. Cost: dominated by the search, about
/// O(turn steps x points x coarse cells / 4^depth) plus the branches it cannot prune; 21 ms for
/// two robots' 15 x 10 m maps on this project's machine (docs/benchmarks.md).
[[nodiscard]] Result<std::optional<MapMatch>> match_maps(const OccupancyGrid& fixed,
                                                         const OccupancyGrid& moving,
                                                         const MapMatchOptions& options = {});

/// The acceptance figures of `moving` placed at T_fixed_moving in `fixed` (step 2 above), for a
/// pose from anywhere (a test, a known start). Cost: O(cells of moving).
[[nodiscard]] MapMatch judge_map_match(const OccupancyGrid& fixed, const OccupancyGrid& moving,
                                       const Pose2& T_fixed_moving,
                                       const MapMatchOptions& options = {});

}  // namespace tessera::team
