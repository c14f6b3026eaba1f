#include "tessera/sim/p3dx_body.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

bool positive_finite(double v) { return std::isfinite(v) && v > 0.0; }

// Rays per bumper sector: about 3 cm apart at the body's edge.
constexpr int kBumperRays = 7;

// Whether a solid cell lies within reach_m of `centre` inside the sector [lo_rad, hi_rad] (world
// frame).
bool sector_touches(const World& world, Vec2 centre, double lo_rad, double hi_rad, double reach_m) {
  for (int k = 0; k < kBumperRays; ++k) {
    const double a = lo_rad + (hi_rad - lo_rad) * k / (kBumperRays - 1);
    if (world.cast_ray(centre, a, reach_m) < reach_m) return true;
  }
  return false;
}

}  // namespace

std::optional<std::string> validate(const P3dxBodyOptions& o) {
  if (!positive_finite(o.body_radius_m)) return "body_radius_m must be > 0";
  if (!(std::isfinite(o.sonar_radius_m) && o.sonar_radius_m >= 0.0 &&
        o.sonar_radius_m <= o.body_radius_m)) {
    return "sonar_radius_m must be within [0, body_radius_m]";
  }
  for (double b : o.sonar_bearings_rad) {
    if (!std::isfinite(b)) return "sonar_bearings_rad must be finite";
  }
  if (!(std::isfinite(o.sonar_half_cone_rad) && o.sonar_half_cone_rad >= 0.0 &&
        o.sonar_half_cone_rad < std::numbers::pi / 2)) {
    return "sonar_half_cone_rad must be within [0, pi/2)";
  }
  if (o.sonar_rays < 1) return "sonar_rays must be >= 1";
  if (!positive_finite(o.sonar_max_range_m)) return "sonar_max_range_m must be > 0";
  if (!(std::isfinite(o.sonar_noise_m) && o.sonar_noise_m >= 0.0)) {
    return "sonar_noise_m must be >= 0";
  }
  if (!(std::isfinite(o.bumper_contact_m) && o.bumper_contact_m >= 0.0)) {
    return "bumper_contact_m must be >= 0";
  }
  if (!(std::isfinite(o.bumper_half_arc_rad) && o.bumper_half_arc_rad > 0.0 &&
        o.bumper_half_arc_rad <= std::numbers::pi / 2)) {
    return "bumper_half_arc_rad must be within (0, pi/2]";
  }
  return std::nullopt;
}

ObstacleSensing sense_p3dx(const World& world, const Pose2& T_world_robot, const P3dxBodyOptions& o,
                           Rng& rng) {
  TESSERA_ASSERT(!validate(o));
  ObstacleSensing s;
  const Vec2 centre{T_world_robot.x, T_world_robot.y};
  for (double bearing : o.sonar_bearings_rad) {
    const double axis = T_world_robot.theta + bearing;
    const Vec2 mount = centre + Vec2{std::cos(axis), std::sin(axis)} * o.sonar_radius_m;
    double nearest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < o.sonar_rays; ++k) {
      const double f = o.sonar_rays == 1 ? 0.0 : -1.0 + 2.0 * k / (o.sonar_rays - 1);
      const double r = world.cast_ray(mount, axis + f * o.sonar_half_cone_rad, o.sonar_max_range_m);
      if (r < o.sonar_max_range_m) nearest = std::min(nearest, r);
    }
    if (std::isfinite(nearest)) nearest = std::max(0.0, nearest + rng.gaussian(o.sonar_noise_m));
    s.sonar.push_back({bearing, nearest});
  }
  const double reach = o.body_radius_m + o.bumper_contact_m;
  const double sector = 2.0 * o.bumper_half_arc_rad / 5.0;
  for (int i = 0; i < 5; ++i) {
    // Front bumper i spans bearings [half arc - (i + 1) sector, half arc - i sector]; rear bumper
    // i (left-most seen from above) spans the mirror image behind.
    const double front_hi = T_world_robot.theta + o.bumper_half_arc_rad - i * sector;
    const double rear_lo =
        T_world_robot.theta + std::numbers::pi - o.bumper_half_arc_rad + i * sector;
    const auto idx = static_cast<std::size_t>(i);
    s.bumpers.front[idx] = sector_touches(world, centre, front_hi - sector, front_hi, reach);
    s.bumpers.rear[idx] = sector_touches(world, centre, rear_lo, rear_lo + sector, reach);
  }
  return s;
}

bool body_overlaps(const World& world, Vec2 p_m, double body_radius_m) {
  return world.distance_to_solid(p_m, body_radius_m) < body_radius_m;
}

Pose2 blocked_motion(const World& world, const Pose2& from, const Pose2& to, double body_radius_m) {
  const Vec2 p{to.x, to.y};
  const double d_to = world.distance_to_solid(p, body_radius_m);
  if (d_to >= body_radius_m) return to;
  const double d_from = world.distance_to_solid({from.x, from.y}, body_radius_m);
  if (d_to >= d_from) return to;  // moving out of (or along) a contact
  return {from.x, from.y, to.theta};
}

}  // namespace tessera
