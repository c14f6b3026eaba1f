#include "tessera/sim/bob_sensing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

// A reading d is placed just beyond d, so that a hit on a cell's face lands in the cell behind
// the face whichever way the beam travels.
constexpr double kFaceEpsilonM = 1e-6;

struct Interval {
  double enter = 0.0;
  double leave = -1.0;  // empty when leave <= enter
};

// Where the ray origin + t * dir (t >= 0) is inside the axis-aligned box [lo, hi] (slab method).
Interval ray_box(Vec2 origin, Vec2 dir, Vec2 lo, Vec2 hi) {
  double t0 = 0.0;
  double t1 = std::numeric_limits<double>::infinity();
  const double o[2] = {origin.x, origin.y};
  const double d[2] = {dir.x, dir.y};
  const double l[2] = {lo.x, lo.y};
  const double h[2] = {hi.x, hi.y};
  for (int a = 0; a < 2; ++a) {
    if (std::abs(d[a]) < 1e-15) {
      if (o[a] < l[a] || o[a] >= h[a]) return {};
      continue;
    }
    double ta = (l[a] - o[a]) / d[a];
    double tb = (h[a] - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  return {t0, t1};
}

// Index into kNeighbors4 (0 N, 1 E, 2 S, 3 W) of the axis nearest to theta.
int heading_of(double theta_rad) {
  const double quarter = 0.5 * std::numbers::pi;
  // East is theta 0 and index 1; North is pi/2 and index 0: index = 1 - round(theta / quarter).
  const int k = static_cast<int>(std::lround(theta_rad / quarter));
  return ((1 - k) % 4 + 4) % 4;
}

}  // namespace

std::optional<std::string> validate(const BobSensingOptions& o) {
  if (auto e = validate(o.layout)) return "layout." + *e;
  if (auto e = validate(o.lateral)) return "lateral." + *e;
  if (auto e = validate(o.front)) return "front." + *e;
  if (o.samples_per_move < 1) return "samples_per_move: must be >= 1";
  if (!(o.near_sigmas >= 0.0) || !(o.far_sigmas >= 0.0)) return "near/far_sigmas: must be >= 0";
  return std::nullopt;
}

Pose2 centred_pose(const GridGeometry& cells, Cell cell, int heading) {
  TESSERA_ASSERT(0 <= heading && heading < 4);
  const Vec2 c = cells.center_of(cell);
  const double theta = normalize_angle((1 - heading) * 0.5 * std::numbers::pi);
  return {c.x, c.y, theta};
}

StepSensing sense_cells_while_moving(const World& world, const GridGeometry& cells,
                                     const Pose2& T_world_robot_start,
                                     const Pose2& T_map_robot_start, const BobSensingOptions& o,
                                     Rng& rng) {
  TESSERA_ASSERT(!validate(o).has_value());
  TESSERA_ASSERT(std::abs(cells.resolution_m() - o.layout.cell_m) < 1e-9);
  const double c = cells.resolution_m();

  // The cells of Figure 3 from the believed start.
  const int h = heading_of(T_map_robot_start.theta);
  const Cell fwd = kNeighbors4[static_cast<std::size_t>(h)];
  const Cell left_dir = kNeighbors4[static_cast<std::size_t>((h + 3) % 4)];
  const Cell c1 = cells.cell_at_unchecked(T_map_robot_start.translation());
  const Cell c2 = c1 + fwd;
  StepSensing out;
  out.left.cell = c2 + left_dir;
  out.front.cell = c2 + fwd;
  out.right.cell = c2 - left_dir;
  CellDetection* targets[3] = {&out.left, &out.front, &out.right};
  Vec2 lo[3], hi[3];
  for (int t = 0; t < 3; ++t) {
    const Vec2 centre = cells.center_of(targets[t]->cell);
    lo[t] = centre - Vec2{0.5 * c, 0.5 * c};
    hi[t] = centre + Vec2{0.5 * c, 0.5 * c};
  }

  const std::array<IrMount, 5> mounts = snowplow_layout(o.layout);
  for (int k = 0; k < o.samples_per_move; ++k) {
    const Pose2 step{(k + 0.5) / o.samples_per_move * c, 0.0, 0.0};
    const Pose2 T_world_robot = T_world_robot_start * step;
    const Pose2 T_map_robot = T_map_robot_start * step;
    for (const IrMount& mount : mounts) {
      const IrSensorOptions& ir = mount.front ? o.front : o.lateral;
      const Pose2 T_world_sensor = T_world_robot * mount.T_robot_sensor;
      const double true_m = world.cast_ray(T_world_sensor.translation(), T_world_sensor.theta,
                                           ir.curve.back().distance_m);
      const IrReading r = read(true_m, ir, rng);
      if (!r.distance_m) continue;
      ++out.in_range_readings;
      const double d = *r.distance_m + kFaceEpsilonM;
      const double sigma = noise_stddev_m(*r.distance_m, ir);
      const Pose2 T_map_sensor = T_map_robot * mount.T_robot_sensor;
      const Vec2 origin = T_map_sensor.translation();
      const Vec2 dir{std::cos(T_map_sensor.theta), std::sin(T_map_sensor.theta)};
      for (int t = 0; t < 3; ++t) {
        const Interval in = ray_box(origin, dir, lo[t], hi[t]);
        if (in.leave <= in.enter) continue;
        if (d + o.near_sigmas * sigma >= in.enter && d < in.leave - o.far_sigmas * sigma) {
          targets[t]->occupied = true;
        }
      }
    }
  }
  return out;
}

}  // namespace tessera
