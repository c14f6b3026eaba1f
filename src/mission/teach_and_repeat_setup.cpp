#include "tessera/mission/teach_and_repeat_setup.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "tessera/grid/cell_region.hpp"
#include "tessera/nav/cell_polyline.hpp"
#include "tessera/nav/route_planner.hpp"
#include "tessera/sim/tour.hpp"

namespace tessera {

Result<std::vector<Vec2>> plan_route(const World& world, Vec2 from_m, Vec2 to_m,
                                     double clearance_m) {
  const GridGeometry& g = world.geometry();
  const std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
  const std::optional<Cell> a = g.cell_at(from_m);
  const std::optional<Cell> b = g.cell_at(to_m);
  auto describe = [](Vec2 p) {
    return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ")";
  };
  if (!a || room[g.index_of(*a)] == 0) {
    return input_error("route: start " + describe(from_m) + " m is closer than clearance_m = " +
                       std::to_string(clearance_m) + " m to a wall or outside the map");
  }
  if (!b || room[g.index_of(*b)] == 0) {
    return input_error("route: goal " + describe(to_m) + " m is closer than clearance_m = " +
                       std::to_string(clearance_m) + " m to a wall or outside the map");
  }
  Result<std::vector<Vec2>> route = plan_mask_route(g, room, from_m, to_m);
  if (!route) {
    return input_error("route: no path from " + describe(from_m) + " to " + describe(to_m) +
                       " keeps clearance_m = " + std::to_string(clearance_m) + " m from walls");
  }
  return route;
}

Result<StartAndGoal> choose_start_and_goal(const World& world, double clearance_m,
                                           double route_length_m, Rng& rng) {
  const Result<Pose2> start = random_start_pose(world, clearance_m, rng);
  if (!start) return start.error();
  const GridGeometry& g = world.geometry();
  const Cell sc = g.cell_at_unchecked({start->x, start->y});
  const std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
  MaskDijkstra search(g, room);
  (void)search.search(sc, [](Cell) { return false; });  // every reachable cell
  std::size_t best = g.index_of(sc);
  double best_gap = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < g.size(); ++i) {
    const double cells = search.cost_cells(g.cell_of(i));
    if (!std::isfinite(cells)) continue;
    const double gap = std::abs(cells * g.resolution_m() - route_length_m);
    if (gap < best_gap) {
      best_gap = gap;
      best = i;
    }
  }
  StartAndGoal out;
  out.goal_m = g.center_of(g.cell_of(best));
  const Result<std::vector<Vec2>> route =
      plan_route(world, {start->x, start->y}, out.goal_m, clearance_m);
  if (!route) return route.error();
  if (route->size() < 2 || polyline_length_m(*route) < 1.0) {
    return input_error(
        "start and goal: the robot's room around the start is too small for a route");
  }
  const Vec2 first = (*route)[1];
  out.start = {start->x, start->y, std::atan2(first.y - start->y, first.x - start->x)};
  out.route_length_m = polyline_length_m(*route);
  return out;
}

std::vector<Poster> place_poster_layers(const std::vector<WallFace>& faces,
                                        const std::vector<WallTexture>& textures,
                                        const PosterPlacementOptions& options, std::uint64_t seed,
                                        int layers) {
  std::vector<Poster> out;
  for (int layer = 0; layer < layers; ++layer) {
    for (const Poster& p :
         place_posters(faces, textures, options, seed + static_cast<std::uint64_t>(layer))) {
      const bool overlaps = std::any_of(out.begin(), out.end(), [&](const Poster& q) {
        return q.face == p.face &&
               std::abs(q.center_m - p.center_m) < 0.5 * (q.width_m + p.width_m) + options.margin_m;
      });
      if (!overlaps) out.push_back(p);
    }
  }
  return out;
}

Result<TeachAndRepeatScenario> set_up_teach_and_repeat(
    const World& world, const std::vector<WallTexture>& textures, std::optional<Vec2> start_m,
    std::optional<Vec2> goal_m, double clearance_m, double route_length_m, std::uint64_t seed) {
  if (start_m.has_value() != goal_m.has_value()) {
    return usage_error("fusion: give both --start and --goal, or neither");
  }
  // The same world for every run: posters placed by the seed, start and goal fixed (the thesis
  // repeated one route); runs differ in their seed (odometry noise, depth noise, RANSAC).
  TeachAndRepeatScenario out;
  PosterPlacementOptions placement;
  placement.probability = 0.9;
  out.posters = place_poster_layers(find_wall_faces(world).faces, textures, placement, seed, 3);
  if (start_m) {
    const Result<std::vector<Vec2>> route = plan_route(world, *start_m, *goal_m, clearance_m);
    if (!route) return route.error();
    if (route->size() < 2) return usage_error("fusion: --start and --goal are the same point");
    const Vec2 first = (*route)[1];
    out.start = {start_m->x, start_m->y, std::atan2(first.y - start_m->y, first.x - start_m->x)};
    out.goal_m = *goal_m;
  } else {
    Rng rng(seed);
    const Result<StartAndGoal> sg = choose_start_and_goal(world, clearance_m, route_length_m, rng);
    if (!sg) return sg.error();
    out.start = sg->start;
    out.goal_m = sg->goal_m;
  }
  return out;
}

namespace {

// The point at arc length s_m along a polyline and the unit normal (left) of its segment there.
std::pair<Vec2, Vec2> point_and_normal_at(const std::vector<Vec2>& line, double s_m) {
  for (std::size_t i = 1; i < line.size(); ++i) {
    const Vec2 d = line[i] - line[i - 1];
    const double len = d.norm();
    if (len <= 0.0) continue;
    if (s_m <= len || i + 1 == line.size()) {
      const Vec2 u = d * (1.0 / len);
      return {line[i - 1] + u * std::min(s_m, len), Vec2{-u.y, u.x}};
    }
    s_m -= len;
  }
  return {line.front(), Vec2{0.0, 1.0}};
}

// `world` with the cells the box [lo_m, hi_m] overlaps made solid (the overlap rule of
// World::any_solid_in, grid/cell_region.hpp).
World with_box(const World& world, Vec2 lo_m, Vec2 hi_m) {
  const GridGeometry& g = world.geometry();
  std::vector<std::uint8_t> solid(world.solid_cells().begin(), world.solid_cells().end());
  const CellRange r = cells_overlapping(g, lo_m, hi_m);
  for (int y = std::max(r.y0, 0); y < std::min(r.y1, g.height()); ++y) {
    for (int x = std::max(r.x0, 0); x < std::min(r.x1, g.width()); ++x) {
      solid[g.index_of({x, y})] = 1;
    }
  }
  return World(g, std::move(solid), world.name());
}

}  // namespace

Result<RouteObstacles> place_route_obstacles(const World& world, const std::vector<Vec2>& route_m,
                                             int count, double side_m, double min_end_distance_m,
                                             double clearance_m, double free_around_m, Rng& rng) {
  RouteObstacles out{world, {}};
  if (count <= 0 || route_m.size() < 2) return out;
  const double length = polyline_length_m(route_m);
  const double usable = length - 2.0 * min_end_distance_m;
  if (usable < count * side_m) {
    return input_error("obstacles: the route (" + std::to_string(length) + " m) is too short for " +
                       std::to_string(count) + " boxes at least " +
                       std::to_string(min_end_distance_m) + " m from its ends");
  }
  const double share = usable / count;
  for (int k = 0; k < count; ++k) {
    const double lo_s = min_end_distance_m + k * share;
    const double first = rng.uniform(lo_s, lo_s + share);
    const double offset = rng.uniform(-0.25, 0.25) * side_m;
    bool placed = false;
    // Try the drawn place first, then 5 cm steps alternately after and before it, anywhere on the
    // usable part of the route.
    for (int step = 0; !placed && step <= static_cast<int>(2.0 * usable / 0.05) + 1; ++step) {
      const double s = first + ((step % 2 == 1) ? 1.0 : -1.0) * 0.05 * ((step + 1) / 2);
      if (s < min_end_distance_m || s > length - min_end_distance_m) continue;
      const auto [p, n] = point_and_normal_at(route_m, s);
      const Vec2 c = p + n * offset;
      const Vec2 lo{c.x - 0.5 * side_m, c.y - 0.5 * side_m};
      const Vec2 hi{c.x + 0.5 * side_m, c.y + 0.5 * side_m};
      // Open floor: no wall (or earlier box) within free_around_m of the box, so the robot can
      // pass it on either side.
      const Vec2 margin{free_around_m, free_around_m};
      if (out.world.any_solid_in(lo - margin, hi + margin)) continue;
      World next = with_box(out.world, lo, hi);
      if (!plan_route(next, route_m.front(), route_m.back(), clearance_m)) continue;
      out.world = std::move(next);
      out.boxes_m.emplace_back(lo, hi);
      placed = true;
    }
    if (!placed) {
      return input_error("obstacles: no place for box " + std::to_string(k + 1) +
                         " on the route with " + std::to_string(free_around_m) +
                         " m of open floor round it and a way past it");
    }
  }
  return out;
}

Result<std::vector<Vec2>> there_and_back_waypoints(const World& world, Vec2 start_m, Vec2 goal_m,
                                                   double clearance_m) {
  const Result<std::vector<Vec2>> route = plan_route(world, start_m, goal_m, clearance_m);
  if (!route) return route.error();
  std::vector<Vec2> waypoints(route->begin() + 1, route->end());
  waypoints.insert(waypoints.end(), route->rbegin() + 1, route->rend());
  return waypoints;
}

}  // namespace tessera
