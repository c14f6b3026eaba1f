#include "tessera/nav/detour_planner.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/nav/cell_polyline.hpp"

namespace tessera {
namespace {

// Echoes from the points `where`: each is seen three times, straight on, by a sonar 0.8 m away
// in direction `from_rad` (so that each point's cell is occupied and the cone before it free).
// The direction must not run along a line of points, or each cone clears the points before it.
SonarGrid grid_with(const std::vector<Vec2>& where, double from_rad = -std::numbers::pi / 2) {
  SonarGrid grid;
  for (const Vec2 p : where) {
    const Pose2 T{p.x + std::cos(from_rad), p.y + std::sin(from_rad), from_rad + std::numbers::pi};
    for (int i = 0; i < 3; ++i) grid.insert(T, {{0.0, 0.8}});
  }
  return grid;
}

// A 0.3 m box centred on c, as echo points every 5 cm along its edges.
std::vector<Vec2> box(Vec2 c) {
  std::vector<Vec2> out;
  for (double t = -0.15; t <= 0.15 + 1e-9; t += 0.05) {
    out.push_back({c.x + t, c.y - 0.15});
    out.push_back({c.x + t, c.y + 0.15});
    out.push_back({c.x - 0.15, c.y + t});
    out.push_back({c.x + 0.15, c.y + t});
  }
  return out;
}

// The smallest distance from the legs of `path` (sampled every 1 cm) to the occupied cells.
double clearance_m(const std::vector<Vec2>& path, const SonarGrid& grid) {
  double best = 1e9;
  const std::vector<Vec2> cells = grid.occupied_within({0.0, 0.0}, 100.0);
  for (std::size_t i = 1; i < path.size(); ++i) {
    const double len = (path[i] - path[i - 1]).norm();
    for (double s = 0.0; s <= len; s += 0.01) {
      const Vec2 p = path[i - 1] + (path[i] - path[i - 1]) * (len > 0.0 ? s / len : 0.0);
      for (const Vec2 c : cells) best = std::min(best, (c - p).norm());
    }
  }
  return best;
}

const std::vector<Vec2> kStraight = {{0.0, 0.0}, {6.0, 0.0}};

TEST(DetourPlanner, ABoxOnThePathBlocksItAndTheDetourKeepsClearOfItToTheEnd) {
  const SonarGrid grid = grid_with(box({2.0, 0.0}));
  const DetourOptions options;
  const std::optional<PathBlockage> blockage = find_blockage(kStraight, 0.5, grid, options);
  ASSERT_TRUE(blockage);
  EXPECT_NEAR(blockage->first_m, 2.0 - 0.15 - options.block_radius_m, 0.1);
  EXPECT_NEAR(blockage->last_m, 2.0 + 0.15 + options.block_radius_m, 0.1);
  const std::optional<Detour> detour = plan_detour(kStraight, {0.5, 0.0}, *blockage, grid, options);
  ASSERT_TRUE(detour);
  EXPECT_LE((detour->path.front() - Vec2{0.5, 0.0}).norm(), 1e-9);
  EXPECT_EQ(detour->path.back(), kStraight.back());
  EXPECT_GE(clearance_m(detour->path, grid), options.clearances_m.back() - 0.05);
  // It rejoins the old path past the box and goes on along it.
  EXPECT_GE(detour->rejoin_on_old_path_m, blockage->last_m + options.rejoin_after_m - 1e-9);
  EXPECT_NEAR(polyline_point_at(detour->path, detour->rejoin_m).y, 0.0, 1e-6);
  // The follow-up check on the detour finds it clear.
  EXPECT_FALSE(find_blockage(detour->path, 0.0, grid, options));
}

TEST(DetourPlanner, ABoxBesideAWallIsPassedOnItsOpenSide) {
  // A wall along y = 0.75 (0.6 m above the box's top edge); open floor below the box.
  std::vector<Vec2> echoes = box({2.0, 0.0});
  for (double x = 0.0; x <= 6.0; x += 0.05) echoes.push_back({x, 0.75});
  const SonarGrid grid = grid_with(echoes);
  const DetourOptions options;
  const std::optional<PathBlockage> blockage = find_blockage(kStraight, 0.0, grid, options);
  ASSERT_TRUE(blockage);
  const std::optional<Detour> detour = plan_detour(kStraight, {0.5, 0.0}, *blockage, grid, options);
  ASSERT_TRUE(detour);
  double lowest_y = 0.0, highest_y = 0.0;
  for (const Vec2 p : detour->path) {
    lowest_y = std::min(lowest_y, p.y);
    highest_y = std::max(highest_y, p.y);
  }
  EXPECT_LT(lowest_y, -0.4);   // round the box below it
  EXPECT_LT(highest_y, 0.05);  // never between the box and the wall
}

TEST(DetourPlanner, WhatTheCallerDoesNotCountAndWhatIsBesideTheRobotBlockNothing) {
  const SonarGrid grid = grid_with(box({2.0, 0.0}));
  const DetourOptions options;
  EXPECT_FALSE(find_blockage(kStraight, 0.0, grid, options, [](Vec2 c) { return c.x > 4.0; }));
  // Within skip_m of the robot: left to the avoidance and the bumpers.
  EXPECT_FALSE(find_blockage(kStraight, 2.3, grid, options));
  // Beyond look_ahead_m: not yet.
  EXPECT_FALSE(find_blockage({{-3.0, 0.0}, {6.0, 0.0}}, -3.0, grid, options));
}

TEST(DetourPlanner, AWallAcrossTheCorridorLeavesNoDetour) {
  std::vector<Vec2> echoes;
  for (double y = -1.5; y <= 1.5; y += 0.05) echoes.push_back({2.0, y});
  const SonarGrid grid = grid_with(echoes, std::numbers::pi);  // seen from the robot's side
  DetourOptions options;
  options.corridor_m = 0.9;  // the wall is wider than the corridor round the path
  const std::optional<PathBlockage> blockage = find_blockage(kStraight, 0.5, grid, options);
  ASSERT_TRUE(blockage);
  EXPECT_FALSE(plan_detour(kStraight, {0.5, 0.0}, *blockage, grid, options));
}

TEST(DetourPlanner, ARouteDrivenBeforeWidensTheCorridorAlongItOnly) {
  // A wall across the path whose ends lie beyond the corridor round it (0.8 m off, plus the
  // clearance): no detour, unless a route driven before passes round an end (y = 1.3 m), where
  // the sonars have swept; the detour then keeps within the corridor round one of the two.
  std::vector<Vec2> echoes;
  for (double y = -0.8; y <= 0.8 + 1e-9; y += 0.05) echoes.push_back({2.0, y});
  const SonarGrid grid = grid_with(echoes, std::numbers::pi);
  const DetourOptions options;
  const std::optional<PathBlockage> blockage = find_blockage(kStraight, 0.5, grid, options);
  ASSERT_TRUE(blockage);
  EXPECT_FALSE(plan_detour(kStraight, {0.5, 0.0}, *blockage, grid, options));
  const std::vector<Vec2> driven = {{0.5, 0.0}, {1.0, 1.3}, {3.0, 1.3}, {3.5, 0.0}};
  const std::optional<Detour> detour =
      plan_detour(kStraight, {0.5, 0.0}, *blockage, grid, options, driven);
  ASSERT_TRUE(detour);
  EXPECT_GE(clearance_m(detour->path, grid), options.clearances_m.back() - 0.05);
  for (const Vec2 p : detour->path) {
    EXPECT_LE(std::min(distance_to_polyline(p, kStraight), distance_to_polyline(p, driven)),
              options.corridor_m + 0.05);
  }
}

TEST(DetourPlanner, ValidateNamesTheBadField) {
  DetourOptions o;
  EXPECT_FALSE(validate(o));
  o.give_up_after_s = 0.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("give_up_after_s"), std::string::npos);
  o = {};
  o.clearances_m.clear();
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("clearances_m"), std::string::npos);
  o = {};
  o.corridor_m = 0.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("corridor_m"), std::string::npos);
}

}  // namespace
}  // namespace tessera
