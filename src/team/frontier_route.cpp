// Frontier routes for a round robot on the team's map (team/frontier_route.hpp).
#include "tessera/team/frontier_route.hpp"

#include <cmath>
#include <deque>
#include <limits>

#include "tessera/core/cell.hpp"
#include "tessera/nav/route_planner.hpp"

namespace tessera::team {
namespace {

bool within(Vec2 a, Vec2 b, double r) {
  const Vec2 d = a - b;
  return d.x * d.x + d.y * d.y <= r * r;
}

bool near_any(Vec2 p, std::span<const Vec2> points, double r) {
  for (const Vec2 q : points) {
    if (within(p, q, r)) return true;
  }
  return false;
}

// The drivable cell nearest robot_m by a breadth-first search over cells that are not obstacles,
// up to entry_radius_m; the robot's own cell when it is drivable.
std::optional<Cell> entry_cell(const DrivableMap& map, Vec2 robot_m, double entry_radius_m) {
  const GridGeometry& g = map.geometry;
  const std::optional<Cell> start = g.cell_at(robot_m);
  if (!start) return std::nullopt;
  const auto max_steps = static_cast<int>(std::ceil(entry_radius_m / g.resolution_m()));
  std::vector<int> depth(g.size(), -1);
  std::deque<Cell> queue{*start};
  depth[g.index_of(*start)] = 0;
  while (!queue.empty()) {
    const Cell c = queue.front();
    queue.pop_front();
    const std::size_t i = g.index_of(c);
    if (map.drivable[i] != 0) return c;
    if (depth[i] >= max_steps) continue;
    for (const Cell d : kNeighbors8) {
      const Cell n = c + d;
      if (!g.contains(n) || depth[g.index_of(n)] >= 0) continue;
      depth[g.index_of(n)] = depth[i] + 1;
      queue.push_back(n);
    }
  }
  return std::nullopt;
}

std::vector<Vec2> route_points(const DrivableMap& map, const MaskDijkstra& search, Vec2 robot_m,
                               Cell goal, Vec2 goal_m) {
  std::vector<Vec2> points{robot_m};
  for (const Cell c : search.path_to(goal)) points.push_back(map.geometry.center_of(c));
  points.push_back(goal_m);
  // The robot's own point may lie outside the drivable cells (entry_cell): keep the first leg as
  // it is and pull the rest.
  std::vector<Vec2> pulled =
      string_pull(map.geometry, map.drivable, std::vector<Vec2>(points.begin() + 1, points.end()));
  pulled.insert(pulled.begin(), robot_m);
  return pulled;
}

double length_m(const std::vector<Vec2>& points) {
  double sum = 0.0;
  for (std::size_t i = 1; i < points.size(); ++i) sum += (points[i] - points[i - 1]).norm();
  return sum;
}

}  // namespace

std::optional<std::string> validate(const FrontierRouteOptions& o) {
  if (!(o.clearance_m >= 0.0) || !std::isfinite(o.clearance_m)) return "clearance_m must be >= 0";
  if (!(o.free_below > 0.0 && o.free_below <= o.occupied_from && o.occupied_from < 1.0)) {
    return "need 0 < free_below <= occupied_from < 1";
  }
  if (!(o.claim_radius_m >= 0.0) || !(o.give_up_radius_m >= 0.0)) {
    return "claim_radius_m and give_up_radius_m must be >= 0";
  }
  return std::nullopt;
}

DrivableMap drivable_map(const OccupancyGrid& map, const FrontierRouteOptions& o) {
  const GridGeometry& g = map.geometry();
  DrivableMap out{g, std::vector<std::uint8_t>(g.size(), 0), std::vector<std::uint8_t>(g.size(), 0),
                  0};
  const float occupied = log_odds(o.occupied_from);
  const float free = log_odds(o.free_below);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    out.drivable[i] = map.is_free_below(c, free) ? 1 : 0;
  }
  // Dilation: every cell whose centre is within clearance of an occupied cell's centre, plus half
  // a cell diagonal (any point of the occupied cell), is not drivable.
  const double reach_cells = o.clearance_m / g.resolution_m() + 0.7072;
  const int k = static_cast<int>(std::ceil(reach_cells));
  const double reach2 = reach_cells * reach_cells;
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    if (!map.known(c) || map.log_odds_at(c) < occupied) continue;
    for (int dy = -k; dy <= k; ++dy) {
      for (int dx = -k; dx <= k; ++dx) {
        const Cell n{c.x + dx, c.y + dy};
        if (dx * dx + dy * dy > reach2 || !g.contains(n)) continue;
        out.drivable[g.index_of(n)] = 0;
      }
    }
  }
  // Frontier: a drivable cell beside an unknown cell that is not a lone hole.
  const auto unknown = [&](Cell c) { return g.contains(c) && !map.known(c); };
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (out.drivable[i] == 0) continue;
    const Cell c = g.cell_of(i);
    for (const Cell d : kNeighbors4) {
      const Cell u = c + d;
      if (!unknown(u)) continue;
      bool hole = true;
      for (const Cell e : kNeighbors4) hole = hole && !unknown(u + e);
      if (!hole) {
        out.frontier[i] = 1;
        ++out.frontier_cells;
        break;
      }
    }
  }
  return out;
}

std::optional<FrontierRoute> plan_frontier_route(const DrivableMap& map, Vec2 robot_m,
                                                 std::span<const Vec2> teammates_m,
                                                 std::span<const Vec2> teammate_claims_m,
                                                 std::span<const Vec2> given_up_m,
                                                 const FrontierRouteOptions& o,
                                                 double entry_radius_m) {
  if (map.frontier_cells == 0) return std::nullopt;
  const std::optional<Cell> start = entry_cell(map, robot_m, entry_radius_m);
  if (!start) return std::nullopt;
  const GridGeometry& g = map.geometry;
  MaskDijkstra search(g, map.drivable);
  // Pass 0: this robot's share away from claims; 1: anywhere away from claims; 2: anywhere.
  for (int pass = 0; pass < 3; ++pass) {
    if (pass > 0 && teammates_m.empty() && teammate_claims_m.empty()) break;
    const std::optional<Cell> goal = search.search(*start, [&](Cell c) {
      if (map.frontier[g.index_of(c)] == 0) return false;
      const Vec2 p = g.center_of(c);
      if (near_any(p, given_up_m, o.give_up_radius_m)) return false;
      if (pass < 2 && near_any(p, teammate_claims_m, o.claim_radius_m)) return false;
      if (pass == 0) {
        const Vec2 d = p - robot_m;
        const double mine2 = d.x * d.x + d.y * d.y;
        for (const Vec2 t : teammates_m) {
          const Vec2 e = p - t;
          if (e.x * e.x + e.y * e.y < mine2) return false;
        }
      }
      return true;
    });
    if (!goal) continue;
    FrontierRoute route;
    route.target_m = g.center_of(*goal);
    route.waypoints_m = route_points(map, search, robot_m, *goal, route.target_m);
    route.length_m = length_m(route.waypoints_m);
    return route;
  }
  return std::nullopt;
}

std::optional<std::vector<Vec2>> plan_drivable_route(const DrivableMap& map, Vec2 robot_m,
                                                     Vec2 goal_m, double entry_radius_m) {
  const std::optional<Cell> start = entry_cell(map, robot_m, entry_radius_m);
  const std::optional<Cell> goal = entry_cell(map, goal_m, entry_radius_m);
  if (!start || !goal) return std::nullopt;
  MaskDijkstra search(map.geometry, map.drivable);
  if (!search.search(*start, [&](Cell c) { return c == *goal; })) return std::nullopt;
  return route_points(map, search, robot_m, *goal, map.geometry.center_of(*goal));
}

bool route_still_drivable(const DrivableMap& map, std::span<const Vec2> waypoints_m,
                          std::size_t from_leg) {
  // The first leg (from where the robot was) may start outside the drivable cells; the others
  // were drivable when planned.
  for (std::size_t i = std::max<std::size_t>(from_leg, 1); i + 1 < waypoints_m.size(); ++i) {
    const std::optional<Cell> a = map.geometry.cell_at(waypoints_m[i]);
    const std::optional<Cell> b = map.geometry.cell_at(waypoints_m[i + 1]);
    if (!a || !b) return false;
    if (!segment_in_mask(map.geometry, map.drivable, waypoints_m[i], waypoints_m[i + 1])) {
      return false;
    }
  }
  return true;
}

bool frontier_near(const DrivableMap& map, Vec2 p_m, double radius_m) {
  const GridGeometry& g = map.geometry;
  const Cell c = g.cell_at_unchecked(p_m);
  const auto k = static_cast<int>(std::ceil(radius_m / g.resolution_m()));
  for (int dy = -k; dy <= k; ++dy) {
    for (int dx = -k; dx <= k; ++dx) {
      const Cell n{c.x + dx, c.y + dy};
      if (g.contains(n) && map.frontier[g.index_of(n)] != 0 &&
          within(g.center_of(n), p_m, radius_m)) {
        return true;
      }
    }
  }
  return false;
}

}  // namespace tessera::team
