#pragma once
#include <cstdint>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/cell_sensor.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sensors/range_scan.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// The two robot kinds of the foundation: the lecture's cell robot (moves one cell, senses its 8
/// neighbours) and a differential-drive robot with a 2D lidar (turns in place, then drives straight
/// to the next cell centre).
enum class RobotKind { kCell, kLidar };

struct RobotSpec {
  RobotKind kind = RobotKind::kCell;
  LidarOptions lidar;  // used by kLidar
};

/// What happened to a requested move. A move into a solid cell, off the map, or to a cell that is
/// not a 4-neighbour is refused: the robot stays where it was and `reason` says why.
struct MoveOutcome {
  bool moved = false;
  double distance_m = 0.0;  // travelled
  double turn_rad = 0.0;    // signed in-place rotation before driving (lidar robot)
  std::string reason;       // empty when moved
};

/// A world with one or more robots. Deterministic for a seed: robot i draws its noise from
/// Rng(seed).fork(i), so adding a robot does not change the others' noise.
class Simulator {
 public:
  Simulator(World world, std::uint64_t seed);

  [[nodiscard]] const World& world() const { return world_; }

  /// Places a robot at the centre of `start`, heading along +x. Input error when the cell is
  /// outside the map ("start (x, y) is outside the map"), solid ("start (x, y) is inside an
  /// obstacle"), or a lidar robot's options do not validate ("lidar: <what is wrong>").
  [[nodiscard]] Result<int> add_robot(Cell start, const RobotSpec& spec);
  [[nodiscard]] int robot_count() const { return static_cast<int>(robots_.size()); }
  [[nodiscard]] const RobotSpec& spec(int robot) const;
  [[nodiscard]] Pose2 pose(int robot) const;  // ground truth, T_world_robot
  [[nodiscard]] Cell cell(int robot) const;

  /// Moves the robot to the 4-neighbour `next` (see MoveOutcome for refusals), ending at its centre
  /// heading along the move. Cell robot: teleports. Lidar robot: turns in place by turn_rad, then
  /// drives straight one cell (refused if that segment crosses a solid cell). Refusal reasons:
  /// "cell (x, y) is not a 4-neighbour of (x, y)", "cell (x, y) is outside the map",
  /// "cell (x, y) is solid", checked in that order.
  MoveOutcome move_to_adjacent(int robot, Cell next);

  /// The cell robot's reading of its 8 neighbours (exact).
  [[nodiscard]] CellReading sense_cells(int robot) const;
  /// A lidar scan from the robot's pose with the robot's range noise; the sensor sits at the
  /// robot's centre. Each beam is World::cast_ray plus a Gaussian draw from the robot's Rng (one
  /// draw per beam, hit or not), clamped to [0, max_range_m]; a beam that hits nothing within
  /// max_range_m reports exactly max_range_m ("no return"). Uses spec(robot).lidar for any kind.
  [[nodiscard]] RangeScan scan(int robot);

 private:
  struct Robot {
    RobotSpec spec;
    Pose2 pose;
    Cell cell;
    Rng rng;
  };
  World world_;
  std::uint64_t seed_;
  std::vector<Robot> robots_;
};

}  // namespace tessera
