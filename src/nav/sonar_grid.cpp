#include "tessera/nav/sonar_grid.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {

std::optional<std::string> validate(const SonarGridOptions& o) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.resolution_m)) return "resolution_m must be > 0";
  if (!positive(o.half_cone_rad) || o.half_cone_rad >= std::numbers::pi / 2) {
    return "half_cone_rad must be in (0, pi/2)";
  }
  if (!positive(o.max_range_m)) return "max_range_m must be > 0";
  if (!std::isfinite(o.sensor_radius_m) || o.sensor_radius_m < 0.0) {
    return "sensor_radius_m must be >= 0";
  }
  if (!positive(o.arc_half_thickness_m)) return "arc_half_thickness_m must be > 0";
  if (!positive(o.hit_log_odds)) return "hit_log_odds must be > 0";
  if (!std::isfinite(o.free_log_odds) || o.free_log_odds >= 0.0) return "free_log_odds must be < 0";
  if (!positive(o.clamp_log_odds)) return "clamp_log_odds must be > 0";
  if (!std::isfinite(o.occupied_log_odds)) return "occupied_log_odds must be finite";
  return std::nullopt;
}

SonarGrid::SonarGrid(SonarGridOptions options) : options_(options) {
  TESSERA_ASSERT(!validate(options_));
}

std::uint64_t SonarGrid::key(int x, int y) {
  return (static_cast<std::uint64_t>(static_cast<std::uint32_t>(x)) << 32) |
         static_cast<std::uint32_t>(y);
}

void SonarGrid::add(int x, int y, double log_odds) {
  float& l = cells_[key(x, y)];
  const double c = options_.clamp_log_odds;
  l = static_cast<float>(std::clamp(static_cast<double>(l) + log_odds, -c, c));
}

void SonarGrid::insert(const Pose2& T_map_robot, const std::vector<ObstacleRange>& sonar) {
  const double res = options_.resolution_m;
  const double h = options_.half_cone_rad;
  const double thick = options_.arc_half_thickness_m;
  for (const ObstacleRange& r : sonar) {
    const bool echo =
        std::isfinite(r.range_m) && r.range_m > 0.0 && r.range_m <= options_.max_range_m;
    const double reach = echo ? r.range_m + thick : options_.max_range_m;
    const double axis = T_map_robot.theta + r.bearing_rad;
    const Vec2 o = T_map_robot * Vec2{options_.sensor_radius_m * std::cos(r.bearing_rad),
                                      options_.sensor_radius_m * std::sin(r.bearing_rad)};
    // The sector's bounding box: its apex, the ends of its arc and the axis point, and any
    // compass direction that lies inside the cone.
    double lo_x = o.x, hi_x = o.x, lo_y = o.y, hi_y = o.y;
    const auto extend = [&](double angle) {
      lo_x = std::min(lo_x, o.x + reach * std::cos(angle));
      hi_x = std::max(hi_x, o.x + reach * std::cos(angle));
      lo_y = std::min(lo_y, o.y + reach * std::sin(angle));
      hi_y = std::max(hi_y, o.y + reach * std::sin(angle));
    };
    extend(axis - h);
    extend(axis + h);
    extend(axis);
    for (int k = 0; k < 4; ++k) {
      const double compass = k * std::numbers::pi / 2;
      if (std::abs(normalize_angle(compass - axis)) <= h) extend(compass);
    }
    const int x0 = static_cast<int>(std::floor(lo_x / res));
    const int x1 = static_cast<int>(std::floor(hi_x / res));
    const int y0 = static_cast<int>(std::floor(lo_y / res));
    const int y1 = static_cast<int>(std::floor(hi_y / res));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const Vec2 v{(x + 0.5) * res - o.x, (y + 0.5) * res - o.y};
        const double d = v.norm();
        const double off = std::abs(normalize_angle(std::atan2(v.y, v.x) - axis));
        if (d > reach || off > h) continue;
        // The echo came most likely from near the axis: a Gaussian of the angle off it, half the
        // cone's half-width wide, weighs both the echo and the free space (Moravec and Elfes'
        // angular term in its usual Gaussian form).
        const double w = std::exp(-2.0 * (off / h) * (off / h));
        if (!echo || d < r.range_m - thick) {
          add(x, y, w * options_.free_log_odds);
        } else {
          add(x, y, w * options_.hit_log_odds);
        }
      }
    }
  }
}

double SonarGrid::log_odds(Vec2 p_m) const {
  const double res = options_.resolution_m;
  const auto it = cells_.find(
      key(static_cast<int>(std::floor(p_m.x / res)), static_cast<int>(std::floor(p_m.y / res))));
  return it == cells_.end() ? 0.0 : it->second;
}

bool SonarGrid::occupied(Vec2 p_m) const { return log_odds(p_m) > options_.occupied_log_odds; }

std::vector<Vec2> SonarGrid::occupied_within(Vec2 p_m, double radius_m) const {
  std::vector<Vec2> out;
  const double res = options_.resolution_m;
  for (const auto& [k, l] : cells_) {
    if (l <= options_.occupied_log_odds) continue;
    const int x = static_cast<std::int32_t>(static_cast<std::uint32_t>(k >> 32));
    const int y = static_cast<std::int32_t>(static_cast<std::uint32_t>(k & 0xffffffffu));
    const Vec2 c{(x + 0.5) * res, (y + 0.5) * res};
    if ((c - p_m).norm() <= radius_m) out.push_back(c);
  }
  // Hash order is not part of the result: sort so that callers see the same list every run.
  std::sort(out.begin(), out.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  return out;
}

}  // namespace tessera
