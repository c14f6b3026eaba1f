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

// One IR reading placed in the map: distance along the beam from `origin` (believed pose).
struct Reading {
  double s_m = 0.0;  // how far the robot had moved
  double distance_m = 0.0;
  double sigma_m = 0.0;  // noise standard deviation of distance_m
  Vec2 origin;
  Vec2 dir;
};

// A reading that gave no distance: nothing up to max_range_m along the beam from `origin`.
struct NoReturn {
  double max_range_m = 0.0;
  Vec2 origin;
  Vec2 dir;
};

// A sensor that sweeps one flat surface while the robot drives straight reads distances that are
// a linear function of how far the robot has moved (the forward beam l reads one point coming
// nearer, a lateral or angled beam slides along a wall). When every reading lies within 3 sigma
// of a weighted least-squares line d = a + b s, each reading is replaced by the line's value and
// its sigma by the line's prediction sigma, which is several times smaller: far fewer cells are
// marked by noise alone. Readings of more than one surface (an edge, a corner, a post) fail the
// test and are kept as read. Needs 4 or more readings with noise.
void fit_one_surface(std::vector<Reading>& rs) {
  if (rs.size() < 4) return;
  double sw = 0.0, sws = 0.0, swss = 0.0, swd = 0.0, swsd = 0.0;
  for (const Reading& r : rs) {
    if (!(r.sigma_m > 0.0)) return;  // exact readings need no smoothing
    const double w = 1.0 / (r.sigma_m * r.sigma_m);
    sw += w;
    sws += w * r.s_m;
    swss += w * r.s_m * r.s_m;
    swd += w * r.distance_m;
    swsd += w * r.s_m * r.distance_m;
  }
  const double det = sw * swss - sws * sws;
  if (!(det > 0.0)) return;
  // (X^T W X)^-1 = [swss, -sws; -sws, sw] / det
  const double b = (sw * swsd - sws * swd) / det;
  const double a = (swd - b * sws) / sw;
  for (const Reading& r : rs) {
    if (std::abs(r.distance_m - (a + b * r.s_m)) > 3.0 * r.sigma_m) return;
  }
  for (Reading& r : rs) {
    const double var = (swss - 2.0 * sws * r.s_m + sw * r.s_m * r.s_m) / det;
    r.distance_m = a + b * r.s_m;
    r.sigma_m = std::sqrt(std::max(var, 0.0));
  }
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
                                     Rng& rng, const PoseUncertainty& uncertainty) {
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

  // Pass 1: every sensor's readings over the move.
  const std::array<IrMount, 5> mounts = snowplow_layout(o.layout);
  std::array<std::vector<Reading>, 5> readings;
  std::vector<NoReturn> no_returns;
  for (int k = 0; k < o.samples_per_move; ++k) {
    const double s_m = (k + 0.5) / o.samples_per_move * c;
    const Pose2 step{s_m, 0.0, 0.0};
    const Pose2 T_world_robot = T_world_robot_start * step;
    const Pose2 T_map_robot = T_map_robot_start * step;
    for (std::size_t m = 0; m < mounts.size(); ++m) {
      const IrMount& mount = mounts[m];
      const IrSensorOptions& ir = mount.front ? o.front : o.lateral;
      const Pose2 T_world_sensor = T_world_robot * mount.T_robot_sensor;
      const double true_m = world.cast_ray(T_world_sensor.translation(), T_world_sensor.theta,
                                           ir.curve.back().distance_m);
      const IrReading r = read(true_m, ir, rng);
      const Pose2 T_map_sensor = T_map_robot * mount.T_robot_sensor;
      const Vec2 dir{std::cos(T_map_sensor.theta), std::sin(T_map_sensor.theta)};
      if (!r.distance_m) {
        no_returns.push_back({ir.max_range_m, T_map_sensor.translation(), dir});
        continue;
      }
      ++out.in_range_readings;
      readings[m].push_back(
          {s_m, *r.distance_m, noise_stddev_m(*r.distance_m, ir), T_map_sensor.translation(), dir});
    }
  }

  // A beam that met nothing crossed every cell up to its maximum range. (A reflector nearer than
  // the minimum range also reads as nothing, ir_sensor.hpp; Figure 3 keeps the minimum ranges
  // inside the robot's clearance, so only an obstacle grazing the robot's own cell can blind it.)
  bool hidden[3] = {false, false, false};
  for (const NoReturn& n : no_returns) {
    for (int t = 0; t < 3; ++t) {
      const Interval in = ray_box(n.origin, n.dir, lo[t], hi[t]);
      if (in.leave > in.enter && in.leave <= n.max_range_m) targets[t]->seen = true;
    }
  }

  // Pass 2: smooth each sensor's readings where they lie on one surface, then place them.
  for (std::vector<Reading>& rs : readings) {
    fit_one_surface(rs);
    for (const Reading& r : rs) {
      const double d = r.distance_m + kFaceEpsilonM;
      // Where the reflector may really be: along the beam within the IR noise and the position
      // uncertainty, across it within the position and heading uncertainty, all at 3 sigma, less
      // the edge tolerance (an obstacle that close to an edge may be mapped in either cell).
      const double tol = o.edge_tolerance_m;
      const double near_m =
          std::max(0.0, o.near_sigmas * r.sigma_m + 3.0 * uncertainty.position_stddev_m - tol);
      const double far_m =
          std::max(0.0, o.far_sigmas * r.sigma_m + 3.0 * uncertainty.position_stddev_m - tol);
      const double across_m = std::max(0.0, 3.0 * (uncertainty.position_stddev_m +
                                                   r.distance_m * uncertainty.heading_stddev_rad) -
                                                tol);
      const Vec2 grow{across_m, across_m};
      for (int t = 0; t < 3; ++t) {
        const Interval wide = ray_box(r.origin, r.dir, lo[t] - grow, hi[t] + grow);
        if (wide.leave > wide.enter && d + near_m >= wide.enter && d - far_m < wide.leave) {
          targets[t]->occupied = true;
        }
        const Interval in = ray_box(r.origin, r.dir, lo[t], hi[t]);
        if (in.leave <= in.enter || targets[t]->occupied) continue;
        if (d >= in.leave) {
          targets[t]->seen = true;  // the beam crossed the cell and was reflected beyond it
        } else {
          hidden[t] = true;  // reflected before the cell: what lies behind is not known
        }
      }
      const Cell hit = cells.cell_at_unchecked(r.origin + r.dir * d);
      if (hit != out.left.cell && hit != out.front.cell && hit != out.right.cell &&
          std::find(out.also_occupied.begin(), out.also_occupied.end(), hit) ==
              out.also_occupied.end()) {
        out.also_occupied.push_back(hit);
      }
    }
  }
  // A cell is free only when beams crossed it and none was stopped in front of it; occupied
  // whenever a reflector may lie inside it.
  for (int t = 0; t < 3; ++t) {
    targets[t]->seen = targets[t]->occupied || (targets[t]->seen && !hidden[t]);
  }
  return out;
}

}  // namespace tessera
