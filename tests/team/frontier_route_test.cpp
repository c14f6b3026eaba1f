#include "tessera/team/frontier_route.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tessera::team {
namespace {

// A 4 m x 2 m map of 0.05 m cells: known free inside a wall all round, except an unknown
// strip at each end (x < 0.5 m and x >= 3.5 m): two frontiers, left and right.
OccupancyGrid corridor() {
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 0.05, 80, 40));
  for (int y = 0; y < 40; ++y) {
    for (int x = 10; x < 70; ++x) {
      const bool wall = y == 0 || y == 39;
      map.set_probability({x, y}, wall ? 0.9 : 0.1);
    }
  }
  return map;
}

TEST(DrivableMap, KeepsTheRobotClearOfWallsAndSkipsLoneHoles) {
  OccupancyGrid map = corridor();
  map.set_unknown({40, 20});  // a lone hole in the middle
  const DrivableMap d = drivable_map(map, {.clearance_m = 0.25});
  const auto drivable = [&](double x, double y) {
    return d.drivable[d.geometry.index_of(*d.geometry.cell_at({x, y}))] != 0;
  };
  EXPECT_TRUE(drivable(2.5, 1.0));
  EXPECT_FALSE(drivable(2.0, 0.2));  // 0.15 m from the wall's cell
  EXPECT_TRUE(drivable(2.0, 0.4));   // 0.35 m from it
  EXPECT_FALSE(drivable(0.2, 1.0));  // unknown
  const auto frontier = [&](Cell c) { return d.frontier[d.geometry.index_of(c)] != 0; };
  EXPECT_TRUE(frontier({10, 20}));   // beside the unknown strip
  EXPECT_FALSE(frontier({41, 20}));  // beside the lone hole only
  EXPECT_FALSE(frontier({39, 20}));
}

TEST(FrontierRoute, GoesToTheNearestFrontierAlongDrivableLegs) {
  const DrivableMap d = drivable_map(corridor(), {});
  const std::optional<FrontierRoute> r = plan_frontier_route(d, {1.2, 1.0}, {}, {}, {}, {});
  ASSERT_TRUE(r.has_value());
  EXPECT_LT(r->target_m.x, 1.0);  // the left end is nearer
  EXPECT_NEAR(r->waypoints_m.front().x, 1.2, 1e-9);
  EXPECT_EQ(r->waypoints_m.back().x, r->target_m.x);
  EXPECT_TRUE(route_still_drivable(d, r->waypoints_m, 0));
  EXPECT_GT(r->length_m, 0.5);
}

TEST(FrontierRoute, ATeammateNearerToAFrontierOrItsClaimSendsTheRobotElsewhere) {
  const DrivableMap d = drivable_map(corridor(), {});
  const Vec2 robot{1.2, 1.0};
  const std::vector<Vec2> teammate{{0.8, 1.0}};  // nearer to the left end
  std::optional<FrontierRoute> r = plan_frontier_route(d, robot, teammate, {}, {}, {});
  ASSERT_TRUE(r.has_value());
  EXPECT_GT(r->target_m.x, 3.0);
  const std::vector<Vec2> claim{{0.55, 1.0}};  // the left end claimed
  r = plan_frontier_route(d, robot, {}, claim, {}, {});
  ASSERT_TRUE(r.has_value());
  EXPECT_GT(r->target_m.x, 3.0);
  // Both ends claimed: a claimed cell rather than nothing.
  const std::vector<Vec2> both{{0.55, 1.0}, {3.45, 1.0}};
  r = plan_frontier_route(d, robot, {}, both, {}, {.claim_radius_m = 1.5});
  ASSERT_TRUE(r.has_value());
  EXPECT_LT(r->target_m.x, 1.0);
}

TEST(FrontierRoute, GivenUpTargetsAreNeverChosenAndNoFrontierGivesNone) {
  const DrivableMap d = drivable_map(corridor(), {});
  const std::vector<Vec2> given_up{{0.55, 1.0}};
  const std::optional<FrontierRoute> r =
      plan_frontier_route(d, {1.2, 1.0}, {}, {}, given_up, {.give_up_radius_m = 1.5});
  ASSERT_TRUE(r.has_value());
  EXPECT_GT(r->target_m.x, 3.0);
  OccupancyGrid closed = corridor();
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 80; ++x) {
      if (!closed.known({x, y})) closed.set_probability({x, y}, 0.9);
    }
  }
  EXPECT_FALSE(plan_frontier_route(drivable_map(closed, {}), {1.2, 1.0}, {}, {}, {}, {}));
}

TEST(FrontierRoute, ARouteHomeAndARouteThatANewWallBlocks) {
  OccupancyGrid map = corridor();
  const DrivableMap d = drivable_map(map, {});
  const std::optional<std::vector<Vec2>> home = plan_drivable_route(d, {3.0, 1.0}, {1.0, 1.0});
  ASSERT_TRUE(home.has_value());
  EXPECT_NEAR(home->back().x, 1.0, 0.05);
  for (int y = 0; y < 40; ++y) map.set_probability({40, y}, 0.9);  // a wall across at x = 2 m
  const DrivableMap blocked = drivable_map(map, {});
  EXPECT_FALSE(route_still_drivable(blocked, *home, 0));
  EXPECT_FALSE(plan_drivable_route(blocked, {3.0, 1.0}, {1.0, 1.0}).has_value());
  EXPECT_TRUE(frontier_near(d, {0.6, 1.0}, 0.2));
  EXPECT_FALSE(frontier_near(d, {2.0, 1.0}, 0.2));
}

}  // namespace
}  // namespace tessera::team
