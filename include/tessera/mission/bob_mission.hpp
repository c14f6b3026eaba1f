#pragma once
// A simulated BOBMapping run (BOBMapping sections 3.1-3.4): the freestanding explorer of bob/
// driven by a simulated robot on a ground-truth World of any resolution, under a grid of
// robot-sized cells laid over it from the world's origin. The run `tessera bob` makes, kept in the
// library so the app stays thin; its Table 1 scoring is eval's (eval/bob_table.hpp).
//
// What it models:
//  - Ground truth per robot cell: occupied when any solid cell of the world overlaps it
//    (World::resampled), the paper's "any detection inside a cell marks it occupied". Obstacles
//    straddle robot cells wherever the world is finer than the robot's grid.
//  - Sensing: the five-IR snowplow of Figure 3 (sim::sense_cells_while_moving), rays cast in the
//    fine world from the true pose, readings placed in the robot's grid from the believed pose.
//  - Localisation (3.3), unless `perfect_localisation`: the robot turns in place to face the
//    centre of the next cell and drives to it; wheel encoders dead-reckon while it moves (their
//    scale errors and slip make the belief drift from the truth); an ultrasonic beacon fix is
//    taken after two linear moves or after the linear move that follows a turn, and replaces the
//    believed position. When the fix disagrees with odometry by more than
//    `reposition_threshold_m`, the robot drives back to the centre of the previous cell and
//    repeats the step, sensing again; the readings of the rejected step are discarded.
//  - Bumps: when the true body would touch a solid cell on the way, the move stops there, the
//    robot backs to the cell it left and bob::Explorer::blocked() marks the target occupied. A
//    cell it has stood in stays traversable (marked occupied in the final map only, decision
//    0008), so after three bumps into one the robot squeezes through (counted in
//    BobLocalisationStats::collisions).
//  - At the start the robot is placed by hand (belief = truth) centred in its cell, facing North,
//    and senses the three cells around it as if it had just driven in from the cell behind (that
//    cell is taken as free for this one sensing; nothing else changes).
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/bob/explorer.hpp"
#include "tessera/sim/bob_explorer_port.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/sensors/beacon_trilateration.hpp"
#include "tessera/sensors/wheel_encoders.hpp"
#include "tessera/sim/bob_sensing.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// The robot's fixed buffers hold at most this many cells (64 x 64, the paper's grids are
/// 11 x 14): 4096 bytes of packed map, 8704 bytes of path-search scratch, 4096 bytes of final map.
inline constexpr int kMaxBobCells = 4096;

enum class BobVariant {
  kTrail,     // the paper's Tremaux backtracking (bob::Backtrack::kTrail)
  kMapAware,  // shortest known-free path backtracking (bob::Backtrack::kShortestKnownPath)
};

/// "trail" / "map-aware".
[[nodiscard]] const char* bob_variant_name(BobVariant v);

struct BobResult;

struct BobMissionOptions {
  BobVariant variant = BobVariant::kTrail;
  double cell_m = 0.22;  // side of the robot's cells (BOBMapping 4.1)
  /// Noise of every sensor: IR (sensors/ir_sensor.hpp), encoder slip and scale errors, beacon
  /// ranges. Off: exact readings, so motion and localisation are exact too.
  bool noise = true;
  std::uint64_t seed = 1;
  /// BOBMapping 3.4 re-sensing (bob::ExplorerOptions::resense): off keeps each cell's first
  /// reading, the paper's "20 errors ... dropped to six" ablation.
  bool resense = true;
  /// Exact motion and localisation whatever `noise` says (the robot knows its true pose).
  bool perfect_localisation = false;
  WheelEncoderOptions encoders;
  /// Default: three emitters 2.5 m up over three corners of the world (0.2 m in from its edges).
  std::optional<BeaconOptions> beacons;
  /// BOBMapping 3.4 "if it exceeds a threshold, a repositioning is carried out" (the paper gives
  /// no figure): above the 3.5 cm mean error of a fix, so that a good fix seldom triggers it.
  double reposition_threshold_m = 0.05;
  int max_step_attempts = 4;  // a step is repeated at most this many times in all
  /// Edge band: a reflector this close to a cell edge may be placed in either cell when sensing
  /// (BobSensingOptions::edge_tolerance_m), and Table 1's band scoring forgives it
  /// (eval/bob_table.hpp). Below the beacons' 3.5 cm mean error.
  double boundary_tolerance_m = 0.03;
  /// The robot's grid covers only this rectangle {lo, hi} of the world, metres (snapped outwards
  /// to the world's cells, as World::cropped does); the world outside it is still there for the
  /// sensors and the body. An open configuration cut from a floor plan ("the limit of the space is
  /// limited by the grid size", BOBMapping 4.3) then sees the floor plan beyond the grid's edge,
  /// as the paper's robot saw the room, instead of a wall on the edge. Default: the whole world.
  std::optional<std::array<Vec2, 2>> grid_rect_m;
  /// Start cell of the robot's grid, facing North. Default: in the largest 4-connected free area,
  /// the first cell in row-major order (lowest row, then lowest column) whose eight neighbours
  /// are free, or failing that whose North neighbour is free.
  std::optional<Cell> start;
  /// Robot footprint (BOBMapping 4.1); the cell side is the world's resolution.
  double robot_length_m = 0.16;
  double robot_width_m = 0.15;
  int samples_per_move = 12;
  /// Called by run_bob with the run so far at the start and after every step (a move or a bump):
  /// BobMission::snapshot(). For a monitor (io/bob_monitor.hpp); unset: not called.
  std::function<void(const BobResult&)> on_step;
};

/// How the localisation of 3.3 went.
struct BobLocalisationStats {
  int fixes = 0;             // beacon fixes taken
  int failed_fixes = 0;      // trilateration gave no position (belief kept)
  int repositionings = 0;    // steps repeated because the fix disagreed with odometry
  int unresolved_steps = 0;  // steps still disagreeing after max_step_attempts (kept)
  int bumps = 0;             // moves stopped by an obstacle and taken back (bob::Explorer::blocked)
  int collisions = 0;        // moves into a visited cell made although the body touched an obstacle
  double mean_fix_error_m = 0.0;       // |fix - true position|
  double max_drift_m = 0.0;            // largest |odometry position - true position| before a fix
  double max_position_error_m = 0.0;   // largest |believed - true position| at the end of a step
  double max_heading_error_rad = 0.0;  // largest |believed - true heading| at the end of a step
};

struct BobResult {
  std::vector<Cell> route;  // cells the robot stood in, start first, one per move
  int width = 0;            // the robot's grid
  int height = 0;
  /// bob::FinalMap layout: 1 = occupied, unsensed, or stood in with an obstacle detected inside
  /// (decision 0008). The Table 1 errors are counted on this map (eval/bob_table.hpp).
  std::vector<std::uint8_t> final_map;
  std::vector<std::uint8_t> sensed;    // one byte per cell, row-major: 1 = sensed
  std::vector<std::uint8_t> occupied;  // one byte per cell, row-major: final_map's bit of the cell
  // The explorer's counters (bob::Explorer): one-cell moves, heading changes, readings that
  // changed a sensed cell, readings ignored with re-sensing off.
  int moves = 0;
  int turns = 0;
  int resensed = 0;
  int ignored_readings = 0;
  BobLocalisationStats localisation;
  bob::StopReason stop_reason = bob::StopReason::kNone;
  Cell start;
};

/// The robot's grid laid over `world` (or over options.grid_rect_m of it) from its origin, and the
/// ground truth of each of its cells: occupied when any solid cell of `world` overlaps it
/// (World::resampled's rule; a cell reaching past the rectangle looks at the world there, not at
/// the rectangle's edge). Computed once per run: BobMission and eval/bob_table.hpp take it.
/// kUsage: cell_m <= 0. Cost: O(cells of world).
[[nodiscard]] Result<World> bob_grid_truth(const World& world, const BobMissionOptions& options);

/// A simulated BOBMapping run as a step machine: the simulator's side (the fine world, the
/// robot's body, its sensors and beacons, BOBMapping 3.3-3.4's localisation protocol) around the
/// robot's side, the explorer behind `BobExplorerPort` (bob::Explorer in this process, or the
/// firmware across a serial link). step() is one move of the explorer; the accessors show the run
/// so far. Decision 0015.
class BobMission {
 public:
  /// Places the robot by hand in its start cell (options.start or the default, see
  /// BobMissionOptions::start), facing North, and lets it sense the cells around it; the explorer
  /// starts there. `world`, `grid_truth` (bob_grid_truth(world, options)) and `explorer` must
  /// outlive the mission.
  ///
  /// Errors (kInput): "world is W x H = N cells, more than the robot's buffers hold (4096)" (cells
  /// of the robot's grid); "cell 0.1 m does not fit the robot (0.16 x 0.15 m)"; "start (x, y) is
  /// outside the map" / "is inside an obstacle"; "start (x, y): the cell in front must be free
  /// (BOBMapping 3.4)"; no start cell with a free North neighbour. kUsage: bad sensing, encoder or
  /// beacon options. The explorer link's errors.
  [[nodiscard]] static Result<BobMission> create(const World& world, const World& grid_truth,
                                                 const BobMissionOptions& options,
                                                 BobExplorerPort& explorer);
  BobMission(BobMission&&) noexcept;
  BobMission& operator=(BobMission&&) noexcept;
  ~BobMission();

  /// One move of the explorer: its next move, carried out by the body (turn, drive, sense while
  /// moving; a beacon fix after two linear moves or after the linear move that follows a turn,
  /// the step repeated when the fix disagrees with odometry), or a bump (the body met an obstacle:
  /// back to the cell it left, the explorer told). The call that finds the explorer finished sets
  /// finished() and moves nothing. Does nothing once finished().
  /// Errors: kRuntime when the explorer did not stop within 64 moves per cell or answered with an
  /// error status (a bug); the explorer link's errors. Cost: O(1) with kTrail, O(cells) with
  /// kMapAware (the explorer's search), plus the body's collision checks.
  [[nodiscard]] Status step();

  [[nodiscard]] bool finished() const;
  [[nodiscard]] const GridGeometry& grid() const;
  [[nodiscard]] Cell start() const;
  /// Cells stood in, start first, one per move.
  [[nodiscard]] const std::vector<Cell>& route() const;
  /// The localisation figures so far (mean_fix_error_m included).
  [[nodiscard]] BobLocalisationStats localisation() const;
  [[nodiscard]] Pose2 true_pose() const;
  [[nodiscard]] Pose2 believed_pose() const;
  /// The run so far as a monitor shows it: route, size, start, final_map, sensed and occupied from
  /// the explorer's maps (BobExplorerPort::snapshot); counters and localisation left empty.
  [[nodiscard]] Result<BobResult> snapshot();
  /// The run once finished(): the explorer's summary and maps, the route and the localisation.
  /// kRuntime when the explorer's maps have the wrong size (a link fault).
  [[nodiscard]] Result<BobResult> result();

 private:
  struct State;
  explicit BobMission(std::unique_ptr<State> state);
  std::unique_ptr<State> s_;
};

/// bob::Explorer in this process, in fixed buffers as on the microcontroller.
[[nodiscard]] std::unique_ptr<BobExplorerPort> local_bob_explorer();

/// Runs the mission to the end: create, then step() until finished(), options.on_step after the
/// start and after every step that moved or bumped; then result(). Deterministic for a given seed
/// when the explorer is. Errors: those of BobMission::create and step().
/// Cost: O(moves) with kTrail, O(moves * cells) with kMapAware.
[[nodiscard]] Result<BobResult> run_bob(const World& world, const World& grid_truth,
                                        const BobMissionOptions& options,
                                        BobExplorerPort& explorer);

/// The same with bob_grid_truth(world, options) and local_bob_explorer().
[[nodiscard]] Result<BobResult> run_bob(const World& world, const BobMissionOptions& options);

}  // namespace tessera
