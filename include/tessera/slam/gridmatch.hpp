#pragma once
// gridmatch: the lecture's SLAM algorithm as written (Ben-Ari & Mondada, lecture "Numerical example
// for a SLAM algorithm", "Formalization of the SLAM algorithm", "More complicated in practice").
//
//   01: loop
//   02:   move a short distance
//   03:   n <- odometry(c)                   the caller: T_map_odometry
//   04:   p <- analyze sensor data           perception_map.hpp: perception_from_scan / _cells
//   05:   for every t in T                   candidate_offsets(), candidate_pose()
//   06:     e <- expected(m, t)              perception_map.hpp: expected_map()
//   07:     if compare(p, e) better than b   similarity(): S = sum over cells of m(i,j) p(i,j)
//   08:       b <- t
//   09:   n <- b                             match() returns every candidate's S and the best
//   10:   m <- update(m, p, n)               update_map()
//   11:   c <- n                             the caller
//
// match_and_update() is lines 05-10 in one call. Everything here is deterministic and allocation
// is per call; nothing is cached between calls.
#include <cstddef>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/slam/perception_map.hpp"

namespace tessera::slam {

/// The set T of test poses around the odometry pose, and how the current map is read.
/// Defaults are the lecture's example: 5 positions (the expected cell and its four neighbours up,
/// down, left and right, one cell away) times 3 headings (as odometry says, 15 degrees clockwise,
/// 15 degrees counter-clockwise) = 15 test poses. They suit the example's one step; over a long
/// run the estimate's heading is always a multiple of heading_step_rad away from odometry, so a
/// turn error below half a step is never corrected and the map turns with it. 5 degree steps with
/// heading_radius_steps = 3 (the same +-15 degrees) keep a 92-move run within a cell
/// (gridmatch_test, GridMatchRun).
struct GridMatchOptions {
  /// Candidate positions lie on a lattice of steps around the odometry position, in the map's
  /// axes (the lecture's "up, down, left, right" are the map's): offsets (dx, dy) in steps with
  /// |dx| + |dy| <= position_radius_steps, or max(|dx|, |dy|) <= it when square_positions.
  int position_radius_steps = 1;
  bool square_positions = false;
  /// One step, in cells of the current map (the lecture: one cell).
  double position_step_cells = 1.0;
  /// The lecture's robot is "in the expected cell or in any of its four neighbours": the lattice
  /// is centred on the centre of the map cell that holds the odometry position, so positions are
  /// cell centres (with whole-cell steps) and an error below half a cell cannot creep into the
  /// estimate step after step. false centres the lattice on the odometry position itself.
  bool snap_to_cell_centre = true;
  /// Candidate headings: the odometry heading plus k * heading_step_rad for |k| <=
  /// heading_radius_steps.
  int heading_radius_steps = 1;
  double heading_step_rad = 15.0 * std::numbers::pi / 180.0;
  /// Reading the current map: a known cell with p >= occupied_threshold is +1, below it -1.
  double occupied_threshold = 0.5;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const GridMatchOptions& o);

/// Where one test pose lies relative to the odometry pose, in steps: dx_steps and dy_steps along
/// the map's x and y axes (position_step_cells each), dheading_steps counter-clockwise
/// (heading_step_rad each; negative is clockwise).
struct CandidateOffset {
  int dx_steps = 0;
  int dy_steps = 0;
  int dheading_steps = 0;
  [[nodiscard]] bool operator==(const CandidateOffset&) const = default;
};

/// The test poses T in the order they are tried: positions in rings of growing distance from the
/// odometry position (ring r holds the offsets with |dx| + |dy| == r, or max(|dx|, |dy|) == r for
/// square_positions), each ring in reading order (top row first, left to right); within a position
/// the headings 0, -1 (clockwise), +1, -2, +2, ... steps. For the defaults that is the odometry
/// position, up, left, right, down, each with the odometry heading, 15 deg CW and 15 deg CCW.
/// Size: positions x (2 * heading_radius_steps + 1). Precondition: validate(o) is empty.
[[nodiscard]] std::vector<CandidateOffset> candidate_offsets(const GridMatchOptions& o);

/// The test pose T_map_robot of `offset` around the odometry pose T_map_odometry on a map with
/// `map_geometry` (its cell size sets the step; with snap_to_cell_centre the lattice starts at the
/// centre of the cell holding the odometry position). Precondition: validate(o) is empty.
[[nodiscard]] Pose2 candidate_pose(const GridGeometry& map_geometry, const Pose2& T_map_odometry,
                                   const CandidateOffset& offset, const GridMatchOptions& o);

/// compare(p, e) of the lecture. S(i,j) = m(i,j) p(i,j) is +1 where both maps know the cell and
/// agree, -1 where both know it and disagree, 0 where either does not know it; S is their sum.
/// Only cells both maps know count, so a perception map limited by the sensor's range is compared
/// only where it overlaps the current map ("More complicated in practice"). S is the lecture's
/// plain sum, not a rate: a test pose whose expected map knows more of the perceived cells can
/// beat one that agrees everywhere but overlaps less.
struct Similarity {
  int score = 0;          // S = agree_cells - (overlap_cells - agree_cells)
  int overlap_cells = 0;  // cells known in both maps
  int agree_cells = 0;    // cells with S(i,j) = +1
  [[nodiscard]] int disagree_cells() const { return overlap_cells - agree_cells; }
  [[nodiscard]] bool operator==(const Similarity&) const = default;
};

/// S of two maps on the same window. Precondition: equal geometries. Cost: O(cells).
[[nodiscard]] Similarity similarity(const TernaryGrid& perception, const TernaryGrid& expected);

/// The lecture's "Matrix (c)": S(i,j) = m(i,j) p(i,j) cell by cell, on the same window.
/// Precondition: equal geometries.
[[nodiscard]] TernaryGrid similarity_cells(const TernaryGrid& perception,
                                           const TernaryGrid& expected);

/// One test pose and how well its expected map fits the perception map.
struct GridMatchCandidate {
  CandidateOffset offset;
  Pose2 T_map_robot;
  Similarity similarity;
};

/// Everything one search computed, for a student (or a renderer) to see every step: the odometry
/// pose, every test pose in the order tried with its S, and the winner. A picture of candidate k
/// is expected_map(map, perception.geometry(), candidates[k].T_map_robot) beside the perception
/// map and similarity_cells() of the two; call it before update_map() changes the map.
struct GridMatchResult {
  Pose2 T_map_odometry;
  std::vector<GridMatchCandidate> candidates;
  /// Index into candidates of the best test pose: the highest S; on a tie the first in the order of
  /// candidate_offsets() (line 07 replaces b only when a pose is strictly better), which prefers
  /// the odometry position, then nearer rings, then within a ring the reading order, and at one
  /// position the odometry heading, then clockwise before counter-clockwise.
  std::size_t best = 0;
  /// The best S minus the best S of any other test pose (0 on a tie; 0 with a single candidate).
  int margin = 0;

  [[nodiscard]] const GridMatchCandidate& winner() const { return candidates[best]; }
  /// The corrected pose, n <- b (line 09).
  [[nodiscard]] const Pose2& T_map_robot() const { return candidates[best].T_map_robot; }
};

/// Lines 05-09: tries every test pose around T_map_odometry, computes its expected map and S
/// against `perception` (whose window is in the robot frame), and keeps the best. The map is only
/// read. Precondition: validate(o) is empty. Cost: O(candidates * window cells).
[[nodiscard]] GridMatchResult match(const OccupancyGrid& map, const TernaryGrid& perception,
                                    const Pose2& T_map_odometry, const GridMatchOptions& o = {});

/// How update() writes the perception map into the current map.
enum class MapUpdateRule {
  /// The lecture's rule: a cell the perception map knows is set outright to p_free or p_occupied,
  /// whatever the map held ("use data from perception map to update current map").
  kOverwrite,
  /// Occupancy-grid evidence instead: a hit (p_hit) or a miss (p_miss) added in log-odds and
  /// clamped (the `model`), so one wrong perception cannot erase what many agreed on.
  kLogOdds,
  /// Only cells the map does not know yet are written (at p_free or p_occupied); what the map
  /// knows is kept as first seen and never corrected. The lecture's "areas not previously in the
  /// map will be added" without the overwrite.
  kAddUnknown,
};

struct MapUpdateOptions {
  MapUpdateRule rule = MapUpdateRule::kOverwrite;
  /// kOverwrite and kAddUnknown: the probabilities written (the lecture's figures use 0.1 for open,
  /// 0.9 for obstacle cells, as the cell sensor does).
  double p_free = 0.1;
  double p_occupied = 0.9;
  /// kLogOdds: the inverse sensor model (OctoMap's defaults).
  SensorModelOptions model;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const MapUpdateOptions& o);

/// What update_map() changed.
struct MapUpdateStats {
  std::size_t written_cells = 0;      // map cells that received a perception value
  std::size_t newly_known_cells = 0;  // of those, cells that were unknown before: new area
  std::size_t flipped_cells = 0;      // known cells whose ternary value changed (free <-> occupied)
  [[nodiscard]] bool operator==(const MapUpdateStats&) const = default;
};

/// Line 10, m <- update(m, p, n): writes the perception map into the map with the robot at
/// T_map_robot, including cells the map did not know yet ("areas not previously in the map will be
/// added"). The perception is resampled onto the map's cells: every map cell whose centre, moved
/// into the robot frame, falls in a known perception cell receives that cell's value, so a rotated
/// window leaves no holes and no map cell is written twice. Map cells the perception does not know
/// (beyond the sensor's range) are left alone; the map does not grow, so perception beyond the
/// map's edge is dropped. `occupied_threshold` is the threshold used to count flipped cells.
/// Precondition: validate(o) is empty. Cost: O(map cells under the window's footprint).
MapUpdateStats update_map(OccupancyGrid& map, const TernaryGrid& perception,
                          const Pose2& T_map_robot, const MapUpdateOptions& o = {},
                          double occupied_threshold = 0.5);

/// One result of match_and_update(): the search and what the update changed.
struct GridMatchStep {
  GridMatchResult match;
  MapUpdateStats update;
};

/// Lines 05-10 in one call: match(), then update_map() at the winning pose. The caller keeps the
/// loop: c <- result.match.T_map_robot(), and the next odometry pose is c * (odometry increment).
/// Preconditions: validate(match_options) and validate(update_options) are empty.
[[nodiscard]] GridMatchStep match_and_update(OccupancyGrid& map, const TernaryGrid& perception,
                                             const Pose2& T_map_odometry,
                                             const GridMatchOptions& match_options = {},
                                             const MapUpdateOptions& update_options = {});

}  // namespace tessera::slam
