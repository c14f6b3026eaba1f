#pragma once
// A simulated frontier exploration from start to finish (lecture Algo 9.1, run by one robot or a
// team sharing one map): the loop the `tessera explore` command runs, kept in the library so the
// app stays thin.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/eval/exploration_metrics.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/explore/frontier_explorer.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/sensors/cell_sensor.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/simulator.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct ExplorationMissionOptions {
  FrontierStrategy strategy = FrontierStrategy::kNearest;
  int robots = 1;
  RobotKind sensor = RobotKind::kCell;
  LidarOptions lidar;                // kLidar robots
  CellSensorOptions cell_sensor;     // kCell robots
  ScanInsertOptions scan_insert;     // kLidar robots
  double low = kDefaultFrontierLow;  // open cells: known and p < low (Algo 9.1)
  /// Robots spread out: see FrontierExplorerOptions::spread_radius_cells.
  int spread_radius_cells = 4;
  std::uint64_t seed = 1;
  /// Cell of the first robot; default: the free cell nearest the centroid of the largest
  /// 4-connected free component. Further robots start at the next free cells in BFS order from it.
  std::optional<Cell> start;
  /// 0: no limit beyond a safety bound of 50 steps per free cell of the world.
  std::int64_t max_steps = 0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ExplorationMissionOptions& o);

/// Reported about every 0.5 s of wall time while the run lasts.
struct ExplorationProgress {
  std::int64_t step = 0;
  double coverage = 0.0;
  std::size_t frontier_size = 0;
};

inline constexpr const char* kStopNoReachableFrontier = "no reachable frontier";
inline constexpr const char* kStopStepLimit = "step limit";

struct ExplorationResult {
  OccupancyGrid map;                       // the robots' shared map, geometry of the world
  std::vector<std::vector<Pose2>> paths;   // per robot: true poses, start first, one per move
  std::vector<Cell> frontier_left;         // frontier at the end, row-major
  std::vector<Cell> unreachable_frontier;  // of frontier_left: found unreachable by the robots
  std::vector<Cell> blacklisted_targets;   // targets still frontier after the robot sensed on them
  std::vector<Cell> starts;                // per robot
  ExplorationMetrics metrics;              // figures and the coverage series
  MapAccuracy accuracy;                    // map vs world, threshold 0.5
  std::size_t free_cells = 0;              // of the world
  std::size_t reachable_free_cells = 0;    // 4-connected to the first start
  std::int64_t refused_moves = 0;          // moves the world refused (each triggered a replan)
  double planning_time_s = 0.0;            // wall time spent choosing targets (not deterministic)
};

/// Runs a simulated exploration of `world`.
///
/// The shared map has the world's geometry and starts all unknown; each robot senses at its start.
/// Each step every robot that has a path advances one cell (Simulator::move_to_adjacent) and senses
/// (cell robot: the 8 neighbours; lidar robot: one scan), and the touched cells update the frontier
/// and the coverage incrementally. A robot replans (FrontierExplorer) when it reaches its target,
/// when the target is no longer a frontier cell, or when its next cell is no longer known free. A
/// cell a robot has stood in stays free whatever a later reading says (BOBMapping's re-sensing
/// rule), so a robot can always go back the way it came. A refused move is counted, the refused
/// cell is written into the map as an obstacle (as a bumper would report it) and the robot replans.
/// A target that is still a frontier cell after the robot stood on it and sensed is blacklisted,
/// and so is a cell chosen as a target more than three times (sensor noise can make a cell at a
/// wall a frontier again and again). A robot that found nothing waits 1, 2, 4, ... (at most 32)
/// steps before it searches again while other robots are busy; when no robot has a plan, all search
/// again before the run stops. The run stops when no robot can reach an eligible frontier cell ("no
/// reachable frontier") or at the step limit ("step limit").
///
/// Cost per step: one sensor update per robot (O(touched) frontier and coverage upkeep) plus a BFS
/// per replanning robot over the cells nearer than its new target.
///
/// Errors (kInput): "world has no free cell"; "start (x, y) is outside the map"; "start (x, y) is
/// inside an obstacle"; fewer free cells reachable from the start than robots. kUsage: options that
/// fail validate(). Deterministic for a given seed (except planning_time_s); the progress callback
/// does not influence the run.
[[nodiscard]] Result<ExplorationResult> run_exploration(
    const World& world, const ExplorationMissionOptions& options,
    const std::function<void(const ExplorationProgress&)>& progress = {});

/// The start cells run_exploration would use: options.start (checked) or the default, followed by
/// the further robots' cells. Same errors as run_exploration.
[[nodiscard]] Result<std::vector<Cell>> exploration_starts(
    const World& world, const ExplorationMissionOptions& options);

}  // namespace tessera
