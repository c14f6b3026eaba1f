#include "tessera/nav/detour_planner.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "tessera/core/assert.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/nav/cell_polyline.hpp"
#include "tessera/nav/route_planner.hpp"

namespace tessera {
namespace {

// Cells of g within radius_m of p, marked 0 in mask.
void clear_disk(const GridGeometry& g, std::vector<std::uint8_t>& mask, Vec2 p, double radius_m) {
  const double res = g.resolution_m();
  const Cell lo = g.cell_at_unchecked({p.x - radius_m, p.y - radius_m});
  const Cell hi = g.cell_at_unchecked({p.x + radius_m, p.y + radius_m});
  for (int y = std::max(lo.y, 0); y <= std::min(hi.y, g.height() - 1); ++y) {
    for (int x = std::max(lo.x, 0); x <= std::min(hi.x, g.width() - 1); ++x) {
      if ((g.center_of({x, y}) - p).norm() <= radius_m + 0.5 * res) {
        mask[g.index_of({x, y})] = 0;
      }
    }
  }
}

bool in_mask(const GridGeometry& g, const std::vector<std::uint8_t>& mask, Vec2 p) {
  const std::optional<Cell> c = g.cell_at(p);
  return c && mask[g.index_of(*c)] != 0;
}

// The free cell nearest p within radius_m (p itself when it is free).
std::optional<Vec2> nearest_free(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                                 Vec2 p, double radius_m) {
  if (in_mask(g, mask, p)) return p;
  std::optional<Vec2> best;
  double best_d = radius_m;
  const Cell lo = g.cell_at_unchecked({p.x - radius_m, p.y - radius_m});
  const Cell hi = g.cell_at_unchecked({p.x + radius_m, p.y + radius_m});
  for (int y = std::max(lo.y, 0); y <= std::min(hi.y, g.height() - 1); ++y) {
    for (int x = std::max(lo.x, 0); x <= std::min(hi.x, g.width() - 1); ++x) {
      if (mask[g.index_of({x, y})] == 0) continue;
      const double d = (g.center_of({x, y}) - p).norm();
      if (d < best_d) {
        best_d = d;
        best = g.center_of({x, y});
      }
    }
  }
  return best;
}

}  // namespace

std::optional<std::string> validate(const DetourOptions& o) {
  const auto positive = [](double v) { return std::isfinite(v) && v > 0.0; };
  if (!positive(o.look_ahead_m)) return "look_ahead_m must be > 0";
  if (!std::isfinite(o.skip_m) || o.skip_m < 0.0) return "skip_m must be >= 0";
  if (!positive(o.block_radius_m)) return "block_radius_m must be > 0";
  if (!positive(o.replan_radius_m)) return "replan_radius_m must be > 0";
  if (!positive(o.off_path_m)) return "off_path_m must be > 0";
  if (!positive(o.give_up_after_s)) return "give_up_after_s must be > 0";
  if (!positive(o.replan_look_ahead_m)) return "replan_look_ahead_m must be > 0";
  if (!std::isfinite(o.min_replan_interval_s) || o.min_replan_interval_s < 0.0) {
    return "min_replan_interval_s must be >= 0";
  }
  if (!std::isfinite(o.rejoin_after_m) || o.rejoin_after_m < 0.0) {
    return "rejoin_after_m must be >= 0";
  }
  if (!positive(o.window_margin_m)) return "window_margin_m must be > 0";
  if (!positive(o.corridor_m)) return "corridor_m must be > 0";
  if (o.clearances_m.empty()) return "clearances_m is empty";
  for (const double c : o.clearances_m) {
    if (!positive(c)) return "clearances_m must all be > 0";
  }
  if (!positive(o.sample_step_m)) return "sample_step_m must be > 0";
  return std::nullopt;
}

std::optional<PathBlockage> find_blockage(const std::vector<Vec2>& path, double from_m,
                                          const SonarGrid& grid, const DetourOptions& options,
                                          const std::function<bool(Vec2)>& counts) {
  if (path.empty()) return std::nullopt;
  const double end_m = std::min(polyline_length_m(path), from_m + options.look_ahead_m);
  from_m += options.skip_m;
  if (from_m > end_m) return std::nullopt;
  // The occupied cells that can matter: within reach of the stretch's middle.
  const Vec2 mid = polyline_point_at(path, 0.5 * (from_m + end_m));
  std::vector<Vec2> cells = grid.occupied_within(
      mid, 0.5 * (end_m - from_m) + options.block_radius_m + options.sample_step_m);
  if (counts) std::erase_if(cells, [&](Vec2 c) { return !counts(c); });
  if (cells.empty()) return std::nullopt;
  std::optional<PathBlockage> out;
  for (double s = from_m; s <= end_m + 1e-9; s += options.sample_step_m) {
    const Vec2 p = polyline_point_at(path, s);
    const bool blocked = std::any_of(cells.begin(), cells.end(), [&](Vec2 c) {
      return (c - p).norm() <= options.block_radius_m;
    });
    if (!blocked) continue;
    if (!out) out = PathBlockage{s, s};
    out->last_m = s;
  }
  return out;
}

std::optional<Detour> plan_detour(const std::vector<Vec2>& path, Vec2 robot_m,
                                  const PathBlockage& blockage, const SonarGrid& grid,
                                  const DetourOptions& options, const std::vector<Vec2>& seen_m) {
  TESSERA_ASSERT(!path.empty() && !validate(options));
  const double length_m = polyline_length_m(path);
  const double rejoin_from_m = std::min(length_m, blockage.last_m + options.rejoin_after_m);
  // The window: the robot and the path from the blockage to a metre past the rejoin point.
  const double res = grid.options().resolution_m;
  Vec2 lo = robot_m, hi = robot_m;
  for (double s = blockage.first_m; s <= std::min(length_m, rejoin_from_m + 1.0); s += res) {
    const Vec2 p = polyline_point_at(path, s);
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double m = options.window_margin_m;
  const Vec2 origin{std::floor((lo.x - m) / res) * res, std::floor((lo.y - m) / res) * res};
  const GridGeometry g(origin, res, static_cast<int>(std::ceil((hi.x + m - origin.x) / res)),
                       static_cast<int>(std::ceil((hi.y + m - origin.y) / res)));
  const double widest = *std::max_element(options.clearances_m.begin(), options.clearances_m.end());
  const Vec2 centre = (lo + hi) * 0.5;
  const std::vector<Vec2> occupied =
      grid.occupied_within(centre, (hi - lo).norm() * 0.5 + m * 1.5 + widest);

  // The corridor: cells near the old path, the robot or the route driven before.
  std::vector<std::uint8_t> corridor(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Vec2 c = g.center_of(g.cell_of(i));
    corridor[i] = (c - robot_m).norm() <= options.corridor_m ||
                          distance_to_polyline(c, path) <= options.corridor_m ||
                          (!seen_m.empty() && distance_to_polyline(c, seen_m) <= options.corridor_m)
                      ? 1
                      : 0;
  }
  for (const double clearance : options.clearances_m) {
    std::vector<std::uint8_t> mask = corridor;
    for (const Vec2 c : occupied) clear_disk(g, mask, c, clearance);
    // A robot standing within the clearance first steps to the nearest cell outside it.
    const std::optional<Vec2> start = nearest_free(g, mask, robot_m, clearance + 2.0 * res);
    if (!start) continue;
    std::optional<Vec2> rejoin;
    double rejoin_m = rejoin_from_m;
    for (; rejoin_m <= length_m + 1e-9; rejoin_m += options.sample_step_m) {
      const Vec2 p = polyline_point_at(path, rejoin_m);
      if (!g.cell_at(p)) break;
      if (in_mask(g, mask, p)) {
        rejoin = p;
        break;
      }
    }
    if (!rejoin) continue;
    Result<std::vector<Vec2>> route = plan_mask_route(g, mask, *start, *rejoin);
    if (!route) continue;
    Detour out;
    out.path = std::move(*route);
    out.rejoin_m = polyline_length_m(out.path);
    out.rejoin_on_old_path_m = rejoin_m;
    double s = 0.0;
    for (std::size_t i = 1; i < path.size(); ++i) {
      s += (path[i] - path[i - 1]).norm();
      if (s > rejoin_m + 1e-9) out.path.push_back(path[i]);
    }
    return out;
  }
  return std::nullopt;
}

}  // namespace tessera
