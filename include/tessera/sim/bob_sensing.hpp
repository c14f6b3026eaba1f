#pragma once
#include <array>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/sensors/ir_sensor.hpp"
#include "tessera/sim/ir_layout.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// Sensing of one BOBMapping step (3.2): the five IR sensors of Figure 3 sampled while the robot
/// moves one cell forward, and the readings turned into the occupancy of the three cells around
/// the next cell.
struct BobSensingOptions {
  SnowplowLayoutOptions layout;
  IrSensorOptions lateral = lateral_ir_options();
  IrSensorOptions front = front_ir_options();
  int samples_per_move = 12;  // readings per sensor, evenly spread over the move (cell midpoints)
  /// A reading d says the reflector lies within [d - k sigma(d), d + k sigma(d)] along the beam
  /// (the IR noise is clipped at 3 sigma), widened by the pose uncertainty (PoseUncertainty).
  /// It marks a target cell occupied when that region, shrunk by edge_tolerance_m, meets the
  /// cell; errors thus fall on the safe side. With noise off and an exact pose the rule is exact.
  double near_sigmas = 3.0;
  double far_sigmas = 3.0;
  /// An obstacle closer than this to a cell edge may be mapped in either cell (the robot's
  /// clearance in its cell: it fits beside such an obstacle). 0: every detection that may lie in
  /// a cell marks it.
  double edge_tolerance_m = 0.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const BobSensingOptions& o);

/// One sensed cell. occupied: some reading fell inside it (BOBMapping 3.2: any detection inside a
/// cell marks it occupied, so errors fall on the safe side, empty read as occupied).
struct CellDetection {
  Cell cell;
  bool occupied = false;
  /// False when nothing was read inside the cell and either no beam crossed it or a beam that
  /// would have was stopped in front of it (an obstacle that only grazes the cell the robot
  /// drives into can hide part of the next one). Such a cell is not reported as free.
  bool seen = false;
};

/// The three cells a step senses, in the paper's names for a move C1 -> C2 (Figure 3).
struct StepSensing {
  CellDetection left;   // B2, swept by i
  CellDetection front;  // C3, swept by k, l and m
  CellDetection right;  // D2, swept by j
  /// Other cells in which a reading placed its reflector (B1, C2's far neighbours, the strip of
  /// B2 and D2 the previous step did not sweep...): detections only, never "free", since the
  /// beams do not cover them.
  std::vector<Cell> also_occupied;
  int in_range_readings = 0;  // readings that gave a distance, of 5 * samples_per_move
};

/// How well the robot knows its believed pose (standard deviations). Readings are placed from the
/// believed pose, so a reflector may lie 3 (position + distance * heading) from where it is
/// placed: a cell within that of a placed reading is marked occupied too.
struct PoseUncertainty {
  double position_stddev_m = 0.0;
  double heading_stddev_rad = 0.0;
};

/// The robot moves one cell (cells.resolution_m()) straight ahead, and its five sensors are read
/// samples_per_move times. Rays are cast in `world` from the true poses T_world_robot_start *
/// (s, 0, 0); readings are placed in the map from the believed poses T_map_robot_start * (s, 0, 0).
/// The map frame is the world frame, and the cells are those of `cells`: C1 is the cell of the
/// believed start, the heading is the believed theta rounded to the nearest axis.
///
/// Coverage limits of Figure 3's layout, kept as the paper has it: i and j at the front corners
/// sweep B2 and D2 between x = L/2 and L/2 + c from C1's centre, so the last c/2 - L/2 (3 cm) of
/// B2 and D2 is not swept in this step; k and m see the near corners of C3 only in the previous
/// straight step, and l covers the triangle between them on its centre line only (beams are rays).
/// On a world whose solid cells are whole cells of `cells`, with exact readings and an exact pose,
/// every case is sensed exactly; with noise a wall on a cell face may also mark the cell before it.
///
/// Cost: 5 * samples_per_move ray casts. Draws one Gaussian per reading when noise is on.
/// Precondition: validate(o) is empty and cells.resolution_m() == o.layout.cell_m.
[[nodiscard]] StepSensing sense_cells_while_moving(const World& world, const GridGeometry& cells,
                                                   const Pose2& T_world_robot_start,
                                                   const Pose2& T_map_robot_start,
                                                   const BobSensingOptions& o, Rng& rng,
                                                   const PoseUncertainty& uncertainty = {});

/// The same with perfect localisation: the believed start is the true start.
[[nodiscard]] inline StepSensing sense_cells_while_moving(const World& world,
                                                          const GridGeometry& cells,
                                                          const Pose2& T_world_robot_start,
                                                          const BobSensingOptions& o, Rng& rng) {
  return sense_cells_while_moving(world, cells, T_world_robot_start, T_world_robot_start, o, rng);
}

/// The pose of the robot centred in `cell` and facing neighbour kNeighbors4[heading]
/// (0 North, 1 East, 2 South, 3 West). Precondition: 0 <= heading < 4.
[[nodiscard]] Pose2 centred_pose(const GridGeometry& cells, Cell cell, int heading);

}  // namespace tessera
