#pragma once
// A simulated BOBMapping run (BOBMapping sections 3.1-3.4, Table 1): the freestanding explorer of
// bob/ driven by a simulated robot on a World whose cells are the robot's cells. The loop
// `tessera bob` runs, kept in the library so the app stays thin.
//
// Scope of this simulation (what it models and what it does not):
//  - Motion is exact: every move ends centred in the next cell, turns are exact 90-degree turns.
//  - Localisation is perfect: the believed pose is the true pose (no encoders, no beacons yet).
//  - Sensing is the five-IR snowplow of Figure 3 (sim::sense_cells_while_moving), sampled while
//    the robot moves, with or without the IR noise model.
//  - At the start pose the robot senses the three cells around its start cell (left, front,
//    right), simulated as the move into the start cell from the cell behind it (that cell is
//    taken as free for this one sensing; nothing else changes).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/bob/explorer.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/result.hpp"
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

struct BobMissionOptions {
  BobVariant variant = BobVariant::kTrail;
  bool noise = true;  // IR noise (sensors/ir_sensor.hpp) on or off
  std::uint64_t seed = 1;
  /// Start cell, facing North. Default: in the largest 4-connected free area, the first cell in
  /// row-major order (lowest row, then lowest column) whose North neighbour is free.
  std::optional<Cell> start;
  /// Robot footprint (BOBMapping 4.1); the cell side is the world's resolution.
  double robot_length_m = 0.16;
  double robot_width_m = 0.15;
  int samples_per_move = 12;
};

/// BOBMapping Table 1 for one configuration, plus the comparison with the SmartDFS bound.
struct BobTableRow {
  int cells = 0;                   // cells in the configuration: every cell of the grid (W x H)
  int sensed_cells = 0;            // cells sensed at least once
  int resensed = 0;                // readings that changed an already sensed cell
  int empty_as_occupied = 0;       // over sensed cells: map occupied where the world is free
  int occupied_as_empty = 0;       // over sensed cells: map free where the world is solid
  double success_rate = 0.0;       // (cells - both errors) / cells, as the paper computes it
  int path_cells = 0;              // one-cell moves ("length path")
  int turns = 0;                   // heading changes, each counts one whatever its angle
  int visited_cells = 0;           // distinct cells stood in
  double path_share = 0.0;         // path_cells / cells (the paper's "68% of the cells")
  double visited_share = 0.0;      // visited_cells / cells
  int free_reachable = 0;          // C: free cells 4-connected to the start
  int boundary_edges = 0;          // E: edges between a C cell and a non-C cell (or the outside)
  double path_per_c = 0.0;         // path_cells / C
  double path_per_smartdfs = 0.0;  // path_cells / (C + E/2 - 3), Icking et al. 2005
};

struct BobResult {
  std::vector<Cell> route;  // cells the robot stood in, start first, one per move
  int width = 0;            // grid of the run (the world's)
  int height = 0;
  std::vector<std::uint8_t> final_map;  // bob::FinalMap layout: 1 = occupied or unsensed
  std::vector<std::uint8_t> sensed;     // one byte per cell, row-major: 1 = sensed
  BobTableRow row;
  bob::StopReason stop_reason = bob::StopReason::kNone;
  Cell start;
};

/// Runs the explorer until it stops. Deterministic for a given seed.
///
/// Errors (kInput): "world is W x H = N cells, more than the robot's buffers hold (4096)";
/// "cell 0.1 m does not fit the robot (0.16 x 0.15 m)"; "start (x, y) is outside the map" /
/// "is inside an obstacle"; "start (x, y): the cell in front must be free (BOBMapping 3.4)"; no
/// start cell with a free North neighbour. kRuntime: the robot drove into an obstacle or the
/// explorer did not stop within 64 moves per cell (both would be bugs).
/// Cost: O(moves) with kTrail, O(moves * cells) with kMapAware.
[[nodiscard]] Result<BobResult> run_bob(const World& world_in_cells,
                                        const BobMissionOptions& options);

}  // namespace tessera
