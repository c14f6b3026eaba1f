#include "tessera/sensors/lidar.hpp"

#include <cmath>

#include "tessera/core/assert.hpp"
#include "tessera/grid/ray_cast.hpp"

namespace tessera {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;
/// How far beyond the measured range the hit cell is looked up, so a return exactly on a cell
/// border lands in the wall cell behind it rather than in the free cell in front. Far above the
/// rounding of the traversal (~1e-15 m at map scale), far below any cell size.
constexpr double kHitEpsilonM = 1e-9;
/// A traversed length below this is a corner touch, not a crossing (see insert_scan).
constexpr double kCornerTouchM = 1e-6;

}  // namespace

std::optional<std::string> validate(const LidarOptions& o) {
  if (o.beams < 1) return "beams must be >= 1, got " + std::to_string(o.beams);
  if (!(o.fov_rad > 0.0 && o.fov_rad <= kTwoPi + 1e-9)) {
    return "fov_rad must be in (0, 2 pi], got " + std::to_string(o.fov_rad);
  }
  if (!(o.min_range_m >= 0.0) || !std::isfinite(o.min_range_m)) {
    return "min_range_m must be >= 0, got " + std::to_string(o.min_range_m);
  }
  if (!(o.max_range_m > o.min_range_m) || !std::isfinite(o.max_range_m)) {
    return "max_range_m must be finite and > min_range_m, got " + std::to_string(o.max_range_m);
  }
  if (!(o.range_noise_stddev_m >= 0.0) || !std::isfinite(o.range_noise_stddev_m)) {
    return "range_noise_stddev_m must be >= 0, got " + std::to_string(o.range_noise_stddev_m);
  }
  return std::nullopt;
}

RangeScan empty_scan(const LidarOptions& o) {
  TESSERA_ASSERT(!validate(o).has_value());
  RangeScan scan;
  scan.min_range_m = o.min_range_m;
  scan.max_range_m = o.max_range_m;
  if (o.beams == 1) {
    scan.angle_min_rad = 0.0;
    scan.angle_increment_rad = 0.0;
  } else if (o.fov_rad >= kTwoPi - 1e-9) {
    scan.angle_min_rad = -0.5 * o.fov_rad;
    scan.angle_increment_rad = o.fov_rad / o.beams;
  } else {
    scan.angle_min_rad = -0.5 * o.fov_rad;
    scan.angle_increment_rad = o.fov_rad / (o.beams - 1);
  }
  scan.ranges_m.assign(static_cast<std::size_t>(o.beams), o.max_range_m);
  return scan;
}

void insert_scan(OccupancyGrid& map, const Pose2& T_map_sensor, const RangeScan& scan,
                 const ScanInsertOptions& options, std::vector<Cell>* touched) {
  TESSERA_ASSERT(!validate(options.model).has_value());
  TESSERA_ASSERT(options.free_margin_m >= 0.0);
  const GridGeometry& geometry = map.geometry();
  // Log-odds once per scan, not per cell (OctoMap's precomputed hit/miss updates).
  const float hit = log_odds(options.model.p_hit);
  const float miss = log_odds(options.model.p_miss);
  const float clamp_min = log_odds(options.model.p_clamp_min);
  const float clamp_max = log_odds(options.model.p_clamp_max);

  const auto update = [&](Cell c, float delta) {
    if (touched == nullptr) {
      map.add_log_odds(c, delta, clamp_min, clamp_max);
      return;
    }
    const bool was_known = map.known(c);
    const float before = map.log_odds_at(c);
    map.add_log_odds(c, delta, clamp_min, clamp_max);
    if (!was_known || map.log_odds_at(c) != before) touched->push_back(c);
  };

  const Vec2 origin_m = T_map_sensor.translation();
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double r = scan.ranges_m[i];
    if (std::isnan(r) || r < scan.min_range_m) continue;  // invalid reading
    const bool no_return = r >= scan.max_range_m;
    const double angle =
        T_map_sensor.theta + scan.angle_min_rad + static_cast<double>(i) * scan.angle_increment_rad;
    const Vec2 dir{std::cos(angle), std::sin(angle)};
    const double range_m = no_return ? scan.max_range_m : r;

    // The hit cell, if any: the cell holding the point free_margin_m beyond the return. Noise can
    // put a return up to the margin short of the wall; looking that far ahead keeps the hit in the
    // wall cell instead of darkening the free cell in front of it, which would otherwise get a hit
    // from every short reading and end up occupied (kHitEpsilonM handles margin 0).
    Cell hit_cell{};
    bool has_hit = false;
    if (!no_return) {
      hit_cell = geometry.cell_at_unchecked(origin_m +
                                            dir * (range_m + options.free_margin_m + kHitEpsilonM));
      has_hit = true;
    }

    // Misses: the cells the beam enters at least free_margin_m before the range. Traversing the
    // segment up to that distance visits exactly the cells with t_enter <= clear_m.
    const double clear_m = range_m - options.free_margin_m;
    if (clear_m >= 0.0) {
      bool entered = false;
      traverse_ray(geometry, origin_m, origin_m + dir * clear_m,
                   [&](Cell c, double t_enter_m, double t_exit_m) {
                     // The grid is convex: once the beam has left it, it cannot come back.
                     if (!geometry.contains(c)) return !entered;
                     entered = true;
                     // A cell the beam only touches at a corner is not evidence of free space:
                     // which of the two cells at an exact corner a traversal visits depends on
                     // rounding, and the other one may be the solid cell the beam squeezed past.
                     if (t_exit_m - t_enter_m < kCornerTouchM) return true;
                     if (!(has_hit && c == hit_cell)) update(c, miss);  // a long reading's wall
                     return true;
                   });
    }
    if (has_hit && geometry.contains(hit_cell)) update(hit_cell, hit);
  }
}

}  // namespace tessera
