#pragma once
// The scenario of the teach-and-repeat experiment (mission/teach_and_repeat.hpp) and of the fusion
// mapping run in a simulated world: the taught route, the start and goal, and the posters on the
// walls. The route is nav/route_planner.hpp's, over sim/tour.hpp's room for the robot.
// Deterministic for a seed. No I/O.
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sim/poster.hpp"
#include "tessera/sim/wall_faces.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// A drivable route in `world` from `from_m` to `to_m`: nav/route_planner.hpp's plan_mask_route
/// over the cells at least clearance_m from every wall (sim/tour.hpp room_for_robot), so every leg
/// keeps clearance_m (exact segment checks). Starts with from_m and ends with to_m. Input error
/// when either end has no room or they are not connected. Cost: one Dijkstra search over the grid.
[[nodiscard]] Result<std::vector<Vec2>> plan_route(const World& world, Vec2 from_m, Vec2 to_m,
                                                   double clearance_m);

/// A start and goal for the experiment: the start a random room cell of the largest component, the
/// goal the room cell whose route length from the start is nearest route_length_m (the thesis'
/// route: about 7.4 m + 2.3 m). The start heading faces the route's first leg.
struct StartAndGoal {
  Pose2 start;
  Vec2 goal_m;
  double route_length_m = 0.0;
};
[[nodiscard]] Result<StartAndGoal> choose_start_and_goal(const World& world, double clearance_m,
                                                         double route_length_m, Rng& rng);

/// Posters for the experiment's world: `layers` passes of sim/poster.hpp's place_posters (seeds
/// seed, seed + 1, ...), a poster of a later pass kept only where it does not overlap (with
/// margin_m) one already on its face. One pass hangs at most one poster per wall face, which leaves
/// long walls mostly blank; the thesis' robot drove past desks and cabinets. Deterministic.
[[nodiscard]] std::vector<Poster> place_poster_layers(const std::vector<WallFace>& faces,
                                                      const std::vector<WallTexture>& textures,
                                                      const PosterPlacementOptions& options,
                                                      std::uint64_t seed, int layers);

/// The experiment's world as `tessera fusion --world / --teach-and-repeat` sets it up: posters
/// placed by the seed (three layers, probability 0.9 per face) and one start and goal for every
/// run (the thesis repeated one route); runs then differ only in their own seed.
struct TeachAndRepeatScenario {
  std::vector<Poster> posters;
  Pose2 start;
  Vec2 goal_m;
};

/// Places the posters and takes the start and goal: the given ones (start heading along the
/// route's first leg) or, when both are empty, choose_start_and_goal with Rng(seed). Usage error
/// when only one of start and goal is given; input errors of plan_route and choose_start_and_goal.
[[nodiscard]] Result<TeachAndRepeatScenario> set_up_teach_and_repeat(
    const World& world, const std::vector<WallTexture>& textures, std::optional<Vec2> start_m,
    std::optional<Vec2> goal_m, double clearance_m, double route_length_m, std::uint64_t seed);

/// Boxes put on a taught route (the obstacle course of thesis chapter 5, Figure 5.1): `world`
/// with the boxes' cells solid, and each box as its lo and hi corners.
struct RouteObstacles {
  World world;
  std::vector<std::pair<Vec2, Vec2>> boxes_m;
};

/// `count` square boxes of side side_m centred on `route` (start to goal), spread over the part of
/// it at least min_end_distance_m (along the route) from either end: box k at a random place in
/// the k-th of `count` equal shares, with a random sideways offset of up to a quarter of its side.
/// A box stands on open floor: no wall or earlier box within free_around_m of it, so the robot
/// can pass it on either side (a reactive avoidance cannot know which side leads on: a box beside
/// a door would be a trap, decision 0028), and a route keeping clearance_m from everything must
/// still join the ends. Where the drawn place fails, the box
/// moves along the route in 5 cm steps, alternately after and before it, anywhere on that part.
/// Input error when the route is too short for the boxes or a box has no such place.
/// Deterministic for the Rng. Cost: one route search per place tried.
[[nodiscard]] Result<RouteObstacles> place_route_obstacles(
    const World& world, const std::vector<Vec2>& route_m, int count, double side_m,
    double min_end_distance_m, double clearance_m, double free_around_m, Rng& rng);

/// The fusion mapping run's waypoints (tessera fusion --world, decision 0010): plan_route from the
/// start to the goal and back, without the start itself (sim/rgbd_run.hpp's RgbdRunOptions
/// waypoints_m, driven with tour.clearance_m = clearance_m: every leg keeps it). Input error when
/// no route joins them.
[[nodiscard]] Result<std::vector<Vec2>> there_and_back_waypoints(const World& world, Vec2 start_m,
                                                                 Vec2 goal_m, double clearance_m);

}  // namespace tessera
