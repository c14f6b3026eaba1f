#include "tessera/sim/simulator.hpp"

#include <algorithm>
#include <numbers>
#include <optional>
#include <utility>

#include "tessera/core/assert.hpp"
#include "tessera/grid/ray_cast.hpp"
#include "tessera/sim/lidar_scan.hpp"

namespace tessera {
namespace {

std::string cell_text(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

/// Heading of a unit move, exact and in [-pi, pi): +x is 0, +y is pi/2, -x is -pi, -y is -pi/2.
double heading_of(Cell step) {
  constexpr double kPi = std::numbers::pi;
  if (step.x > 0) return 0.0;
  if (step.x < 0) return -kPi;
  return step.y > 0 ? 0.5 * kPi : -0.5 * kPi;
}

}  // namespace

Simulator::Simulator(World world, std::uint64_t seed) : world_(std::move(world)), seed_(seed) {}

Result<int> Simulator::add_robot(Cell start, const RobotSpec& spec) {
  if (!world_.geometry().contains(start)) {
    return input_error("start " + cell_text(start) + " is outside the map");
  }
  if (world_.solid(start))
    return input_error("start " + cell_text(start) + " is inside an obstacle");
  if (spec.kind == RobotKind::kLidar) {
    if (const auto problem = validate(spec.lidar)) return input_error("lidar: " + *problem);
  }
  const int id = robot_count();
  const Vec2 centre = world_.geometry().center_of(start);
  robots_.push_back(Robot{spec, Pose2{centre.x, centre.y, 0.0}, start,
                          Rng(seed_).fork(static_cast<std::uint64_t>(id))});
  return id;
}

const RobotSpec& Simulator::spec(int robot) const {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  return robots_[static_cast<std::size_t>(robot)].spec;
}

Pose2 Simulator::pose(int robot) const {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  return robots_[static_cast<std::size_t>(robot)].pose;
}

Cell Simulator::cell(int robot) const {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  return robots_[static_cast<std::size_t>(robot)].cell;
}

MoveOutcome Simulator::move_to_adjacent(int robot, Cell next) {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  Robot& r = robots_[static_cast<std::size_t>(robot)];
  MoveOutcome out;
  if (manhattan(r.cell, next) != 1) {
    out.reason = "cell " + cell_text(next) + " is not a 4-neighbour of " + cell_text(r.cell);
    return out;
  }
  if (!world_.geometry().contains(next)) {
    out.reason = "cell " + cell_text(next) + " is outside the map";
    return out;
  }
  if (world_.solid(next)) {
    out.reason = "cell " + cell_text(next) + " is solid";
    return out;
  }
  const Vec2 from_m = r.pose.translation();
  const Vec2 to_m = world_.geometry().center_of(next);
  if (r.spec.kind == RobotKind::kLidar) {
    // The drive is a straight segment between the centres; for a 4-neighbour it lies in the two
    // cells, but check every cell it passes through (a zero-length corner visit included).
    std::optional<Cell> blocked;
    traverse_ray(world_.geometry(), from_m, to_m, [&](Cell c, double, double) {
      if (!world_.solid(c)) return true;
      blocked = c;
      return false;
    });
    if (blocked.has_value()) {
      out.reason = "cell " + cell_text(*blocked) + " is solid";
      return out;
    }
  }
  // Cell robot: teleports to the neighbour's centre facing the move. Lidar robot: turns in place
  // to face it, then drives straight one cell. Both end in the same pose.
  const double heading = heading_of(next - r.cell);
  out.moved = true;
  out.turn_rad = normalize_angle(heading - r.pose.theta);
  out.distance_m = (to_m - from_m).norm();
  r.pose = Pose2{to_m.x, to_m.y, heading};
  r.cell = next;
  return out;
}

CellReading Simulator::sense_cells(int robot) const {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  CellReading reading;
  reading.center = robots_[static_cast<std::size_t>(robot)].cell;
  for (std::size_t k = 0; k < kNeighbors8.size(); ++k) {
    const Cell n = reading.center + kNeighbors8[k];
    reading.inside_map[k] = world_.geometry().contains(n);
    reading.occupied[k] = reading.inside_map[k] && world_.solid(n);
  }
  return reading;
}

RangeScan Simulator::scan(int robot) {
  TESSERA_ASSERT(0 <= robot && robot < robot_count());
  Robot& r = robots_[static_cast<std::size_t>(robot)];
  return simulate_lidar_scan(world_, r.pose, r.spec.lidar, r.rng);
}

}  // namespace tessera
