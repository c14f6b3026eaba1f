#pragma once
// Where an exploring robot of a team drives next, on the team's merged map (issue 14): lecture
// Algo 9.1's "move to the nearest frontier cell", made drivable for a round robot and shared
// across a team.
//  - Drivable: the robot's centre may only be in known free cells at least clearance_m from every
//    occupied cell (the map dilated by the robot's size, a configuration space), so a route never
//    scrapes a wall and a gap narrower than the robot is not a way through.
//  - Frontier: a drivable cell with an unknown 4-neighbour (Algo 9.1 lines 2-6), unless that
//    unknown cell is a lone hole between known cells: a lidar's beams fan out with range and leave
//    such holes in open space, which the next pass fills; chasing them is wasted driving.
//  - Nearest: by path length over drivable cells, 8-connected (nav/route_planner.hpp's Dijkstra),
//    the route string-pulled to straight legs that stay drivable.
//  - Shared (the lecture: "each robot explores the portion of the frontier closest to its
//    position"): a robot first looks for frontier cells nearer to it than to every teammate (a
//    Voronoi partition of the frontier by straight-line distance) and away from teammates'
//    claimed targets; then for any frontier cell away from the claims; then for any. So robots
//    spread out, and none waits while frontier is left. Cells near a target this robot gave up on
//    are never taken.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera::team {

struct FrontierRouteOptions {
  /// The robot's centre stays at least this far from every occupied cell: its radius and a margin
  /// for the map's and the pose's errors.
  double clearance_m = 0.25;
  /// Known cells with p >= occupied_from are obstacles; known cells below free_below are free.
  double occupied_from = 0.5;
  double free_below = 0.5;
  /// Frontier cells this close to a teammate's claimed target are a fallback only.
  double claim_radius_m = 2.0;
  /// Frontier cells this close to a given-up target are never chosen.
  double give_up_radius_m = 0.5;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const FrontierRouteOptions& o);

/// The cells the robot's centre may be in and the frontier among them, for one map.
struct DrivableMap {
  GridGeometry geometry;
  std::vector<std::uint8_t> drivable;  // per cell: 1 = known free and clear of obstacles
  std::vector<std::uint8_t> frontier;  // per cell: 1 = drivable with an unknown 4-neighbour
  std::size_t frontier_cells = 0;
};

/// Cost: O(cells + occupied cells x (clearance / resolution)^2).
[[nodiscard]] DrivableMap drivable_map(const OccupancyGrid& map, const FrontierRouteOptions& o);

struct FrontierRoute {
  Vec2 target_m;                  // the frontier cell's centre
  std::vector<Vec2> waypoints_m;  // the robot's position first, target_m last
  double length_m = 0.0;
};

/// The nearest eligible frontier cell from robot_m and the route there (see the file comment);
/// teammates_m are the teammates' positions.
/// A robot outside the drivable cells (pushed against a wall, or a map that has just grown an
/// obstacle beside it) starts from the nearest drivable cell within entry_radius_m, straight.
/// nullopt when no eligible frontier cell is reachable. Cost: one Dijkstra search over the
/// drivable cells nearer than the target (up to three when the robot's own share is explored).
[[nodiscard]] std::optional<FrontierRoute> plan_frontier_route(
    const DrivableMap& map, Vec2 robot_m, std::span<const Vec2> teammates_m,
    std::span<const Vec2> teammate_claims_m, std::span<const Vec2> given_up_m,
    const FrontierRouteOptions& o, double entry_radius_m = 0.5);

/// A drivable route from robot_m to the drivable cell nearest goal_m within entry_radius_m (the
/// way home); nullopt when there is none.
[[nodiscard]] std::optional<std::vector<Vec2>> plan_drivable_route(const DrivableMap& map,
                                                                   Vec2 robot_m, Vec2 goal_m,
                                                                   double entry_radius_m = 0.5);

/// True while every leg of `waypoints_m` from leg `from_leg` on still runs through drivable cells
/// (a route made on an older map is checked against a newer one).
[[nodiscard]] bool route_still_drivable(const DrivableMap& map, std::span<const Vec2> waypoints_m,
                                        std::size_t from_leg);

/// True when a frontier cell lies within radius_m of p.
[[nodiscard]] bool frontier_near(const DrivableMap& map, Vec2 p_m, double radius_m);

}  // namespace tessera::team
