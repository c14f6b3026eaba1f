#include "tessera/mission/teach_and_repeat_setup.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace tessera {
namespace {

// A corridor of 0.1 m cells, 30 x 9, walled all round: free x in [0.1, 2.9] m, y in [0.1, 0.8] m.
// Its middle row (y = 0.45 m) is 0.35 m from the side walls.
World corridor() {
  const GridGeometry g({0.0, 0.0}, 0.1, 30, 9);
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (x == 0 || y == 0 || x == g.width() - 1 || y == g.height() - 1) solid[g.index_of({x, y})] = 1;
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
