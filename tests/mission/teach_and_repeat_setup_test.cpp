// The teach-and-repeat scenario (mission/teach_and_repeat_setup.hpp): the taught route keeps its
// clearance on every leg, unreachable goals are input errors, the scenario takes both ends or
// neither, and the mapping run drives the route there and back.
#include "tessera/mission/teach_and_repeat_setup.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

TEST(TeachAndRepeatSetup, RouteKeepsClearanceAndEndsAtTheGoal) {
  const World world = builtin_world("office", 0.05);
  Rng rng(5);
  const Result<StartAndGoal> sg = choose_start_and_goal(world, 0.3, 6.0, rng);
  ASSERT_TRUE(sg) << sg.error().message;
  const Result<std::vector<Vec2>> route =
      plan_route(world, {sg->start.x, sg->start.y}, sg->goal_m, 0.3);
  ASSERT_TRUE(route) << route.error().message;
  ASSERT_GE(route->size(), 2u);
  EXPECT_DOUBLE_EQ(route->front().x, sg->start.x);
  EXPECT_DOUBLE_EQ(route->back().y, sg->goal_m.y);
  // Every point of every leg keeps 0.3 m from walls (nav/route_planner.hpp checks legs exactly;
  // sampled here every 2 cm, 16 rays).
  for (std::size_t i = 1; i < route->size(); ++i) {
    const Vec2 a = (*route)[i - 1], b = (*route)[i];
    const double len = std::hypot(b.x - a.x, b.y - a.y);
    for (double s = 0.0; s <= len; s += 0.02) {
      const Vec2 p{a.x + (b.x - a.x) * s / len, a.y + (b.y - a.y) * s / len};
      for (int k = 0; k < 16; ++k) {
        EXPECT_GE(world.cast_ray(p, k * std::numbers::pi / 8, 1.0), 0.3 - 1e-9) << "leg " << i;
      }
    }
  }
}

TEST(TeachAndRepeatSetup, GoalBehindAWallThatLeavesNoRoomIsAnInputError) {
  const World world = builtin_world("office", 0.05);
  Rng rng(5);
  const Result<StartAndGoal> sg = choose_start_and_goal(world, 0.3, 6.0, rng);
  ASSERT_TRUE(sg);
  const Result<std::vector<Vec2>> route =
      plan_route(world, {sg->start.x, sg->start.y}, {-5.0, -5.0}, 0.3);
  ASSERT_FALSE(route);
  EXPECT_EQ(route.error().kind, ErrorKind::kInput);
  EXPECT_NE(route.error().message.find("goal"), std::string::npos);
}

TEST(TeachAndRepeatSetup, TheScenarioTakesBothEndsOrNeitherAndTheMappingRunDrivesThereAndBack) {
  const World world = builtin_world("office", 0.05);
  const std::vector<WallTexture> no_textures;
  const Result<TeachAndRepeatScenario> one_end =
      set_up_teach_and_repeat(world, no_textures, Vec2{2.0, 2.0}, std::nullopt, 0.3, 6.0, 1);
  ASSERT_FALSE(one_end);
  EXPECT_EQ(one_end.error().kind, ErrorKind::kUsage);
  const Result<TeachAndRepeatScenario> chosen =
      set_up_teach_and_repeat(world, no_textures, std::nullopt, std::nullopt, 0.3, 6.0, 1);
  ASSERT_TRUE(chosen) << chosen.error().message;
  Rng rng(1);
  const Result<StartAndGoal> sg = choose_start_and_goal(world, 0.3, 6.0, rng);
  ASSERT_TRUE(sg);
  EXPECT_EQ(chosen->start.x, sg->start.x);
  EXPECT_EQ(chosen->goal_m, sg->goal_m);
  const Result<std::vector<Vec2>> route =
      plan_route(world, {sg->start.x, sg->start.y}, sg->goal_m, 0.3);
  const Result<std::vector<Vec2>> waypoints =
      there_and_back_waypoints(world, {sg->start.x, sg->start.y}, sg->goal_m, 0.3);
  ASSERT_TRUE(route);
  ASSERT_TRUE(waypoints);
  ASSERT_EQ(waypoints->size(), 2 * (route->size() - 1));
  EXPECT_EQ(waypoints->at(route->size() - 2), sg->goal_m);
  EXPECT_EQ(waypoints->back(), route->front());
}

// A corridor of 0.1 m cells, 30 x 9, walled all round: free x in [0.1, 2.9] m, y in [0.1, 0.8] m.
// Its middle row (y = 0.45 m) is 0.35 m from the side walls.
World corridor() {
  const GridGeometry g({0.0, 0.0}, 0.1, 30, 9);
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (x == 0 || y == 0 || x == g.width() - 1 || y == g.height() - 1)
        solid[g.index_of({x, y})] = 1;
    }
  }
  return World(g, std::move(solid), "corridor");
}

constexpr Vec2 kWest{0.45, 0.45};
constexpr Vec2 kEast{2.55, 0.45};

TEST(TeachAndRepeatSetup, RouteAlongAStraightCorridorIsOneLeg) {
  const Result<std::vector<Vec2>> route = plan_route(corridor(), kWest, kEast, 0.2);
  ASSERT_TRUE(route) << route.error().message;
  EXPECT_EQ(*route, (std::vector<Vec2>{kWest, kEast}));
}

TEST(TeachAndRepeatSetup, EndsWithoutRoomAreInputErrorsNamingTheEnd) {
  const World w = corridor();
  // 0.05 m from the north wall's face (y = 0.8): less than the clearance.
  const Result<std::vector<Vec2>> bad_goal = plan_route(w, kWest, {1.5, 0.75}, 0.2);
  ASSERT_FALSE(bad_goal);
  EXPECT_EQ(bad_goal.error().kind, ErrorKind::kInput);
  EXPECT_NE(bad_goal.error().message.find("route: goal"), std::string::npos)
      << bad_goal.error().message;
  const Result<std::vector<Vec2>> outside = plan_route(w, {-1.0, 0.45}, kEast, 0.2);
  ASSERT_FALSE(outside);
  EXPECT_EQ(outside.error().kind, ErrorKind::kInput);
  EXPECT_NE(outside.error().message.find("route: start"), std::string::npos)
      << outside.error().message;
  // The corridor is 0.7 m wide: no cell keeps 0.4 m from both walls.
  const Result<std::vector<Vec2>> too_wide = plan_route(w, kWest, kEast, 0.4);
  ASSERT_FALSE(too_wide);
  EXPECT_EQ(too_wide.error().kind, ErrorKind::kInput);
}

TEST(TeachAndRepeatSetup, GivenStartFacesTheFirstLeg) {
  const World w = corridor();
  const std::vector<WallTexture> no_textures;
  const Result<TeachAndRepeatScenario> east =
      set_up_teach_and_repeat(w, no_textures, kWest, kEast, 0.2, 6.0, 1);
  ASSERT_TRUE(east) << east.error().message;
  EXPECT_EQ(east->start.x, kWest.x);
  EXPECT_EQ(east->start.y, kWest.y);
  EXPECT_EQ(east->start.theta, 0.0);  // the goal is due east
  EXPECT_EQ(east->goal_m, kEast);
  const Result<TeachAndRepeatScenario> west =
      set_up_teach_and_repeat(w, no_textures, kEast, kWest, 0.2, 6.0, 1);
  ASSERT_TRUE(west) << west.error().message;
  // Due west. atan2 gives +pi here, which lies outside Pose2's [-pi, pi) (reported to the lead);
  // either end of the circle faces the same way.
  EXPECT_EQ(std::abs(west->start.theta), std::numbers::pi);
  EXPECT_EQ(west->goal_m, kWest);
}

TEST(TeachAndRepeatSetup, OnlyOneEndGivenIsAUsageError) {
  const std::vector<WallTexture> no_textures;
  const Result<TeachAndRepeatScenario> r =
      set_up_teach_and_repeat(corridor(), no_textures, std::nullopt, kEast, 0.2, 6.0, 1);
  ASSERT_FALSE(r);
  EXPECT_EQ(r.error().kind, ErrorKind::kUsage);
}

TEST(TeachAndRepeatSetup, ThereAndBackDropsTheStartAndEndsOnIt) {
  const Result<std::vector<Vec2>> w = there_and_back_waypoints(corridor(), kWest, kEast, 0.2);
  ASSERT_TRUE(w) << w.error().message;
  EXPECT_EQ(*w, (std::vector<Vec2>{kEast, kWest}));
  const Result<std::vector<Vec2>> none = there_and_back_waypoints(corridor(), kWest, kEast, 0.4);
  ASSERT_FALSE(none);
  EXPECT_EQ(none.error().kind, ErrorKind::kInput);
}

}  // namespace
}  // namespace tessera

namespace tessera {
namespace {

// The obstacle course's boxes (issue 18 item 9).
TEST(TeachAndRepeatSetup, BoxesSitOnTheRouteAwayFromItsEndsAndLeaveAWayRound) {
  const World world = builtin_world("office", 0.05);
  Rng pick(5);
  const Result<StartAndGoal> sg = choose_start_and_goal(world, 0.3, 7.0, pick);
  ASSERT_TRUE(sg) << sg.error().message;
  const Result<std::vector<Vec2>> route =
      plan_route(world, {sg->start.x, sg->start.y}, sg->goal_m, 0.3);
  ASSERT_TRUE(route) << route.error().message;
  Rng rng(9);
  const Result<RouteObstacles> boxes =
      place_route_obstacles(world, *route, 2, 0.3, 1.5, 0.3, 0.6, rng);
  ASSERT_TRUE(boxes) << boxes.error().message;
  ASSERT_EQ(boxes->boxes_m.size(), 2u);
  for (const auto& [lo, hi] : boxes->boxes_m) {
    EXPECT_NEAR(hi.x - lo.x, 0.3, 1e-12);
    EXPECT_FALSE(world.any_solid_in(lo, hi));        // placed in free space
    EXPECT_TRUE(boxes->world.any_solid_in(lo, hi));  // and solid in the new world
    const Vec2 c{0.5 * (lo.x + hi.x), 0.5 * (lo.y + hi.y)};
    // On the route: its centre within a quarter side of some leg.
    double off = 1e9;
    for (std::size_t i = 1; i < route->size(); ++i) {
      off = std::min(off, distance_to_segment(c, (*route)[i - 1], (*route)[i]));
    }
    EXPECT_LE(off, 0.25 * 0.3 + 1e-9);
    EXPECT_GE((c - route->front()).norm(), 1.0);  // 1.5 m along the route, at least 1 m away
    EXPECT_GE((c - route->back()).norm(), 1.0);
  }
  EXPECT_TRUE(plan_route(boxes->world, route->front(), route->back(), 0.3));  // a way round
  Rng again(9);
  const Result<RouteObstacles> same =
      place_route_obstacles(world, *route, 2, 0.3, 1.5, 0.3, 0.6, again);
  ASSERT_TRUE(same);
  EXPECT_EQ(same->boxes_m, boxes->boxes_m);
}

TEST(TeachAndRepeatSetup, ABoxWithNoWayRoundOrNoRoomOnTheRouteIsAnInputError) {
  const World w = corridor();  // 0.7 m wide: a box in it blocks any route keeping 0.2 m
  const Result<std::vector<Vec2>> route = plan_route(w, kWest, kEast, 0.2);
  ASSERT_TRUE(route);
  Rng rng(1);
  const Result<RouteObstacles> blocked =
      place_route_obstacles(w, *route, 1, 0.3, 0.5, 0.2, 0.4, rng);
  ASSERT_FALSE(blocked);
  EXPECT_EQ(blocked.error().kind, ErrorKind::kInput);
  EXPECT_NE(blocked.error().message.find("no place for box 1"), std::string::npos)
      << blocked.error().message;
  const Result<RouteObstacles> short_route =
      place_route_obstacles(w, *route, 3, 0.3, 1.0, 0.2, 0.4, rng);
  ASSERT_FALSE(short_route);
  EXPECT_NE(short_route.error().message.find("too short"), std::string::npos)
      << short_route.error().message;
}

}  // namespace
}  // namespace tessera
