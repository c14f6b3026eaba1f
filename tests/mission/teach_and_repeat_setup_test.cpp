// The teach-and-repeat scenario (mission/teach_and_repeat_setup.hpp): the taught route keeps its
// clearance on every leg, unreachable goals are input errors, the scenario takes both ends or
// neither, and the mapping run drives the route there and back.
#include "tessera/mission/teach_and_repeat_setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
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

}  // namespace
}  // namespace tessera
