#pragma once
// Worlds and ideal scans for the laser SLAM tests: a room with furniture built in code, so every
// test knows the true pose of every scan.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/sensors/range_scan.hpp"
#include "tessera/sim/world.hpp"
#include "tessera/slam/laser_slam.hpp"
#include "tessera/slam/probability_grid.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::slam::testing {

/// Fills the cells of `solid` (on `g`) whose centres lie in [x0, x1) x [y0, y1).
inline void fill_box(const GridGeometry& g, std::vector<std::uint8_t>& solid, double x0, double y0,
                     double x1, double y1) {
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const Vec2 c = g.center_of({x, y});
      if (c.x >= x0 && c.x < x1 && c.y >= y0 && c.y < y1) solid[g.index_of({x, y})] = 1;
    }
  }
}

/// A 12 m x 8 m room with boxes and a partition, at 0.02 m: asymmetric, so that a scan fixes the
/// pose. The room's interior is about [0.14, 11.86] x [0.12, 7.94].
inline World furnished_room() {
  constexpr double kRes = 0.02;
  const GridGeometry g({0.0, 0.0}, kRes, 600, 400);
  std::vector<std::uint8_t> solid(g.size(), 0);
  const auto fill = [&](double x0, double y0, double x1, double y1) {
    fill_box(g, solid, x0, y0, x1, y1);
  };
  // Wall faces at varied offsets from the 0.05 m grids the tests build, so that where a wall
  // falls inside a cell averages out (a wall exactly on a cell border biases the map by half a
  // cell).
  fill(0.0, 0.0, 12.0, 0.12);  // walls
  fill(0.0, 7.94, 12.0, 8.0);
  fill(0.0, 0.0, 0.14, 8.0);
  fill(11.86, 0.0, 12.0, 8.0);
  fill(6.02, 0.1, 6.08, 3.46);   // a partition with a door above it
  fill(2.04, 5.02, 3.06, 5.62);  // boxes
  fill(8.02, 5.54, 8.36, 7.9);
  fill(9.48, 1.52, 10.26, 1.98);
  fill(3.52, 1.22, 3.78, 1.46);
  return World(g, std::move(solid), "furnished room");
}

/// Laser SLAM options for short simulated runs: small submaps, frequent optimisation. Enough to
/// close a small loop with little odometry error per scan; keeps the sanitizer runs short.
inline LaserSlamOptions small_submaps() {
  LaserSlamOptions o;
  o.submaps.scans_per_submap = 25;
  o.optimize_every_n_nodes = 20;
  o.loop_sampling_ratio = 0.1;
  o.real_time.angular_window_rad = 0.1;
  return o;
}

/// A 360-beam scan (one per degree, 12 m range) from T_world_laser, exact ranges plus optional
/// Gaussian noise.
inline RangeScan ideal_scan(const World& world, const Pose2& T_world_laser, Rng* rng = nullptr,
                            double noise_m = 0.0) {
  RangeScan scan;
  scan.angle_min_rad = -std::numbers::pi;
  scan.angle_increment_rad = 2.0 * std::numbers::pi / 360.0;
  scan.min_range_m = 0.0;
  scan.max_range_m = 12.0;
  for (int i = 0; i < 360; ++i) {
    const double a = T_world_laser.theta + scan.angle_min_rad + i * scan.angle_increment_rad;
    double r = world.cast_ray(T_world_laser.translation(), a, scan.max_range_m);
    if (rng != nullptr && r < scan.max_range_m) r += rng->gaussian(noise_m);
    scan.ranges_m.push_back(r);
  }
  return scan;
}

/// Where the test grids lie in the world: turned, so that the room's walls cross the grid's cells
/// at an angle. Walls parallel to the cells would all be quantised the same way and bias matches
/// by a fraction of a cell, which real maps (walls at every angle and offset) average out.
inline const Pose2 kT_grid_world{0.37, -0.21, 0.3};

/// A submap-like grid in the frame kT_grid_world: scans taken at the world poses `poses`,
/// inserted with the default (Cartographer) model.
inline ProbabilityGrid grid_from_scans(const World& world, const std::vector<Pose2>& poses,
                                       double resolution_m = 0.05) {
  ProbabilityGrid grid(GridGeometry({0.0, 0.0}, resolution_m, 64, 64));
  const RangeInserter inserter;
  for (const Pose2& T_world_laser : poses) {
    inserter.insert(grid, kT_grid_world * T_world_laser,
                    scan_to_points(ideal_scan(world, T_world_laser), {}, ScanPointsOptions{}));
  }
  return grid;
}

}  // namespace tessera::slam::testing
