#pragma once
// The team's map from its robots' maps (issue 14; the lecture: robots exploring in parallel share
// partial maps). Each robot publishes its own SLAM map (nav_msgs/OccupancyGrid) in its own map
// frame; with the pose of each map frame in the team's frame (known start poses, or found by map
// matching), the merged map holds, per cell of one grid over all of them, the sum of the robots'
// log-odds at the cell's centre: each robot's evidence counts once (their sensors are independent),
// unknown where no robot has seen the cell. One exception keeps obstacles: where a robot's map
// holds a cell occupied (p >= kKeptOccupied), the merge keeps the most occupied robot's value, so
// two robots whose maps sit a centimetre apart cannot erase a wall between them by adding one's
// free rays to the other's hits (an obstacle shown free is the error a planner drives into;
// decision 0022). Maps of another resolution than the team's are refused (the caller counts
// them): resampling would blur walls the team relies on.
#include <cstdint>
#include <map>
#include <string>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/io/ros_message_encoders.hpp"

namespace tessera::team {

/// A robot's occupied cell stays occupied in the merge (see above).
inline constexpr double kKeptOccupied = 0.65;

class MapMerger {
 public:
  /// Precondition: resolution_m > 0.
  explicit MapMerger(double resolution_m);

  /// Keeps `map` as `robot`'s latest, its frame at T_team_map. kInput error, naming the robot and
  /// both resolutions, when the map's resolution differs from the team's by more than 0.1 %, and
  /// when its size or data do not agree (width x height != data size, non-finite origin). O(1)
  /// besides the copy.
  [[nodiscard]] Status update(const std::string& robot, const OccupancyGridMessage& map,
                              const Pose2& T_team_map);
  /// The checks of update() alone, keeping nothing: for a map held aside until it can be placed.
  [[nodiscard]] Status check(const std::string& robot, const OccupancyGridMessage& map,
                             const Pose2& T_team_map) const;
  /// How many robots have a map in the team's. A robot that dies keeps its last map here.
  [[nodiscard]] std::size_t robots() const { return maps_.size(); }

  /// The merged grid over the union of the maps' extents (empty without maps), axis-aligned with
  /// the team frame. Cost: O(cells of the merged grid x robots).
  [[nodiscard]] OccupancyGrid merged() const;
  /// The same on a grid of the caller's in the team frame, e.g. a truth grid to score against or
  /// the union extent grown by a margin for planning. A robot whose cells are cells of `into`
  /// (same size, no rotation, origins whole cells apart: robots planning on their team's maps
  /// with known starts) adds each cell to its cell of `into`, O(its cells); any other robot's
  /// value at a cell of `into` is its most occupied at n x n points spread over the cell, n
  /// twice the ratio of the cell sizes (at least 2), O(cells of `into` under its map x n^2).
  /// The robots' values then combine as above.
  [[nodiscard]] OccupancyGrid merged(const GridGeometry& into) const;
  /// The union of the maps' extents in the team frame as a grid of the team's resolution
  /// (empty geometry without maps), grown by margin_m on every side.
  [[nodiscard]] GridGeometry extent(double margin_m = 0.0) const;

 private:
  struct RobotMap {
    OccupancyGridMessage map;
    Pose2 T_team_map;
  };
  double resolution_m_;
  std::map<std::string, RobotMap> maps_;
};

}  // namespace tessera::team
