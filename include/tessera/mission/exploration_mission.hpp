#pragma once
// Frontier exploration (lecture Algo 9.1) by one robot or a team sharing one map, as a step
// machine. ExplorationMission is the robots' side of the run: the shared map, the frontier, the
// targets and the plans. It takes what the robots sensed and how their moves went, and decides the
// next moves; it never sees the world, so a simulator in this process (run_exploration below) or
// robots behind a link can feed it alike. Scoring against the truth is eval's
// (eval/exploration_score.hpp). Decision 0015.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/eval/exploration_metrics.hpp"
#include "tessera/eval/map_accuracy.hpp"
#include "tessera/explore/frontier_explorer.hpp"
#include "tessera/explore/frontier_set.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/sensors/cell_sensor.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sensors/range_scan.hpp"
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
  /// kLidar robots: scan_insert.free_margin_m is taken as 3 sigma of lidar.range_noise_stddev_m
  /// plus 0.1 mm (the simulator truncates range noise at 3 sigma, so every wall cell a beam hits
  /// stays a hit, decision 0003); false: scan_insert.free_margin_m as given.
  bool free_margin_from_noise = true;
  double low = kDefaultFrontierLow;  // open cells: known and p < low (Algo 9.1)
  /// Robots spread out: see FrontierExplorerOptions::spread_radius_cells.
  int spread_radius_cells = 4;
  std::uint64_t seed = 1;
  /// Cell of the first robot; default: the free cell nearest the centroid of the largest
  /// 4-connected free component. Further robots start at the next free cells in BFS order from it.
  std::optional<Cell> start;
  /// 0: no limit (run_exploration: a safety bound of 50 steps per free cell of the world).
  std::int64_t max_steps = 0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const ExplorationMissionOptions& o);

/// The scan insertion the mission uses: o.scan_insert, with the margin of free_margin_from_noise.
[[nodiscard]] ScanInsertOptions effective_scan_insert(const ExplorationMissionOptions& o);

inline constexpr const char* kStopNoReachableFrontier = "no reachable frontier";
inline constexpr const char* kStopStepLimit = "step limit";

/// One robot's move of a step: into `to`, a 4-neighbour of the robot's cell.
struct ExplorationMove {
  int robot = 0;
  Cell to;
};

/// What a robot sensed where it stands: the cell robot's 8 neighbours (lecture) or one lidar scan
/// in the robot's frame.
using ExplorationReading = std::variant<CellReading, RangeScan>;

/// The robots' side of a frontier exploration. A step: decide() replans the robots that need it
/// and returns their moves; for each move, in order, the caller reports moved() (with what the
/// robot then sensed) or refused(); end_step() closes the step. Before the first step every robot
/// reports sense() at its start.
///
/// Rules (lecture Algo 9.1 and what noise needs): a robot replans (FrontierExplorer) when it
/// reaches its target, when the target is no longer a frontier cell, or when its next cell is no
/// longer known free. A cell a robot has stood in stays free whatever a later reading says
/// (BOBMapping's re-sensing rule), so a robot can always go back the way it came. A refused move
/// writes the refused cell into the map as an obstacle (as a bumper would report it) and the
/// robot replans. A target that is still a frontier cell after the robot stood on it and sensed is
/// blacklisted, and so is a cell chosen as a target more than three times (sensor noise can make
/// a cell at a wall a frontier again and again). A robot that found nothing waits 1, 2, 4, ... (at
/// most 32) steps before it searches again while other robots are busy; when no robot has a plan,
/// all search again before the run stops. The run stops when no robot can reach an eligible
/// frontier cell (kStopNoReachableFrontier) or at options.max_steps (kStopStepLimit).
///
/// Cost per step: one map update per sensing robot (O(touched) frontier upkeep) plus a BFS per
/// replanning robot over the cells nearer than its new target. Deterministic: the same calls give
/// the same decisions (planning_time_s() aside).
class ExplorationMission {
 public:
  /// Robot i at starts[i], on an all-unknown map of `geometry`.
  /// Preconditions: validate(options) is empty; starts.size() == options.robots; every start is
  /// inside geometry.
  ExplorationMission(const GridGeometry& geometry, const ExplorationMissionOptions& options,
                     std::vector<Cell> starts);

  /// Robot `robot` sensed `reading` standing in its cell at T_map_robot (before the first step).
  /// The reading's kind is options().sensor's.
  void sense(int robot, const Pose2& T_map_robot, const ExplorationReading& reading);

  /// Algo 9.1's choice of this step: replans, then the moves of the robots that have a plan (robot
  /// order), or none once the run is over (finished()). The moves stay valid until the next call.
  [[nodiscard]] const std::vector<ExplorationMove>& decide();
  /// The move of `robot` in this step's decide() happened: the robot now stands at T_map_robot in
  /// the move's cell, having driven distance_m, and sensed `reading` there.
  void moved(int robot, const Pose2& T_map_robot, double distance_m,
             const ExplorationReading& reading);
  /// The move of `robot` in this step's decide() was refused (a bump).
  void refused(int robot);
  /// Closes the step. Precondition: every move of decide() was reported.
  void end_step();

  [[nodiscard]] const ExplorationMissionOptions& options() const { return options_; }
  [[nodiscard]] int robots() const { return options_.robots; }
  [[nodiscard]] bool finished() const { return stop_reason_ != nullptr; }
  /// kStopNoReachableFrontier or kStopStepLimit once finished(); "" before.
  [[nodiscard]] const char* stop_reason() const { return stop_reason_ ? stop_reason_ : ""; }
  /// Steps closed so far.
  [[nodiscard]] std::int64_t steps() const { return step_; }
  [[nodiscard]] const OccupancyGrid& map() const { return map_; }
  [[nodiscard]] const FrontierSet& frontier() const { return frontier_; }
  /// Cells whose map value may have changed in the current step (since the last decide(); before
  /// the first, since construction): what a scorer re-examines (eval/exploration_score.hpp).
  /// Repeats possible.
  [[nodiscard]] const std::vector<Cell>& changed_cells() const { return changed_; }
  [[nodiscard]] const std::vector<Cell>& starts() const { return starts_; }
  [[nodiscard]] Cell cell(int robot) const { return robot_at(robot).cell; }
  /// The plan `robot` follows (its frontier target, the path there, a, d and the priority
  /// a / d of lecture Algo 9.1), if it has one.
  [[nodiscard]] const std::optional<FrontierPlan>& plan(int robot) const {
    return robot_at(robot).plan;
  }
  /// Per robot: the poses reported, start first, one per move.
  [[nodiscard]] const std::vector<std::vector<Pose2>>& paths() const { return paths_; }
  /// The robots' own trip log, summed over robots: moves made, metres driven, heading changes
  /// between consecutive moves of a robot, moves refused.
  [[nodiscard]] std::int64_t moves() const { return moves_; }
  [[nodiscard]] double distance_m() const { return distance_m_; }
  [[nodiscard]] std::int64_t turns() const { return turns_; }
  [[nodiscard]] std::int64_t refused_moves() const { return refused_moves_; }
  /// Wall time spent in decide() (not deterministic).
  [[nodiscard]] double planning_time_s() const { return planning_time_s_; }
  [[nodiscard]] const std::vector<Cell>& blacklisted_targets() const {
    return explorer_.blacklisted_cells();
  }
  /// Frontier cells no robot can reach through known free cells, row-major. Cost: one BFS per
  /// connected group of robots.
  [[nodiscard]] std::vector<Cell> unreachable_frontier() const;

 private:
  struct RobotState {
    Cell cell;
    std::optional<FrontierPlan> plan;
    std::size_t next = 1;           // index into plan->path of the next cell to enter
    std::optional<Cell> last_step;  // direction of the previous move, for counting turns
    // An idle robot (its last plan failed) retries at this step; the wait doubles with each
    // failure while other robots are busy, so idle robots do not search their whole free
    // component every step. When no robot has a plan, every idle robot retries at once.
    std::int64_t retry_step = 0;
    std::int64_t backoff_steps = 0;
  };
  [[nodiscard]] const RobotState& robot_at(int r) const;
  RobotState& robot_at(int r);
  void insert(const Pose2& T_map_robot, const ExplorationReading& reading);
  void apply_touched();
  [[nodiscard]] bool needs_plan(int r) const;
  void replan(int r);
  bool plan_all();

  ExplorationMissionOptions options_;
  ScanInsertOptions scan_insert_;
  std::vector<Cell> starts_;
  OccupancyGrid map_;
  FrontierSet frontier_;
  FrontierExplorer explorer_;
  float low_log_odds_ = 0.0f;
  // Cells a robot has stood in: free for certain (BOBMapping 3.1: "a cell the robot has stood in
  // can never become occupied"). A grazing lidar return can otherwise darken the one-cell passage
  // a robot came through and shut it in.
  std::vector<std::uint8_t> stood_in_;
  std::vector<std::uint8_t> times_chosen_;
  std::vector<RobotState> robots_;
  std::vector<std::vector<Pose2>> paths_;
  std::vector<ExplorationMove> moves_this_step_;
  std::vector<Cell> touched_;  // of the last reading
  std::vector<Cell> changed_;  // since the last decide()
  const char* stop_reason_ = nullptr;
  std::int64_t step_ = 0;
  std::int64_t moves_ = 0;
  double distance_m_ = 0.0;
  std::int64_t turns_ = 0;
  std::int64_t refused_moves_ = 0;
  double planning_time_s_ = 0.0;
};

/// Reported about every 0.5 s of wall time while run_exploration lasts.
struct ExplorationProgress {
  std::int64_t step = 0;
  double coverage = 0.0;
  std::size_t frontier_size = 0;
};

struct ExplorationResult {
  OccupancyGrid map;                       // the robots' shared map, geometry of the world
  std::vector<std::vector<Pose2>> paths;   // per robot: true poses, start first, one per move
  std::vector<Cell> frontier_left;         // frontier at the end, row-major
  std::vector<Cell> unreachable_frontier;  // of frontier_left: found unreachable by the robots
  std::vector<Cell> blacklisted_targets;   // targets still frontier after the robot sensed on them
  std::vector<Cell> starts;                // per robot
  ExplorationMetrics metrics;              // figures and the coverage series (eval)
  MapAccuracy accuracy;                    // map vs world, threshold 0.5 (eval)
  std::size_t free_cells = 0;              // of the world
  std::size_t reachable_free_cells = 0;    // 4-connected to the first start
  std::int64_t refused_moves = 0;          // moves the world refused (each triggered a replan)
  double planning_time_s = 0.0;            // wall time spent choosing targets (not deterministic)
};

/// The simulated robots of an exploration: a Simulator on `world` with one robot of
/// options.sensor at each start, driven by an ExplorationMission. step_exploration() runs one
/// step; the mission is the robots' side and knows nothing of the world.
struct SimulatedExploration {
  Simulator sim;
  ExplorationMission mission;
};

/// The simulated team at its starts (exploration_starts), each robot having sensed there; the
/// mission's max_steps is options.max_steps or, when 0, 50 steps per free cell of the world.
/// Errors: those of exploration_starts; kUsage: options that fail validate().
[[nodiscard]] Result<SimulatedExploration> start_exploration(const World& world,
                                                             const ExplorationMissionOptions& options);

/// One step of the mission, the simulator carrying out its moves (Simulator::move_to_adjacent)
/// and each robot that moved sensing (cell robot: the 8 neighbours; lidar robot: one scan).
/// Does nothing once the mission is finished().
void step_exploration(SimulatedExploration& run);

/// Runs a simulated exploration of `world` to the end and scores it against the world
/// (eval/exploration_score.hpp, eval/map_accuracy.hpp): start_exploration, then
/// step_exploration until the mission finishes.
///
/// Errors (kInput): "world has no free cell"; "start (x, y) is outside the map"; "start (x, y) is
/// inside an obstacle"; fewer free cells reachable from the start than robots. kUsage: options that
/// fail validate(). Deterministic for a given seed (except planning_time_s); the callbacks do not
/// influence the run. `progress` is called at most twice a second; `on_step` with the mission
/// after the robots' first sensing, after every step, and once finished (a recording, the live
/// view).
[[nodiscard]] Result<ExplorationResult> run_exploration(
    const World& world, const ExplorationMissionOptions& options,
    const std::function<void(const ExplorationProgress&)>& progress = {},
    const std::function<void(const ExplorationMission&)>& on_step = {});

/// The start cells run_exploration would use: options.start (checked) or the default, followed by
/// the further robots' cells. Same errors as run_exploration.
[[nodiscard]] Result<std::vector<Cell>> exploration_starts(
    const World& world, const ExplorationMissionOptions& options);

}  // namespace tessera
