#include "tessera/nav/route_planner.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tessera {
namespace {

using ::testing::HasSubstr;

/// 10 x 10 cells of 1 m, all in the mask except the given cells.
std::vector<std::uint8_t> mask_without(const GridGeometry& g, const std::vector<Cell>& blocked) {
  std::vector<std::uint8_t> mask(g.size(), 1);
  for (const Cell c : blocked) mask[g.index_of(c)] = 0;
  return mask;
}

TEST(RoutePlanner, AnOpenFloorIsCrossedInOneStraightLeg) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  const std::vector<std::uint8_t> mask = mask_without(g, {});
  const Result<std::vector<Vec2>> route = plan_mask_route(g, mask, {0.5, 0.5}, {8.5, 3.5});
  ASSERT_TRUE(route) << route.error().message;
  ASSERT_EQ(route->size(), 2u);
  EXPECT_EQ(route->front(), (Vec2{0.5, 0.5}));
  EXPECT_EQ(route->back(), (Vec2{8.5, 3.5}));
}

TEST(RoutePlanner, AWallIsPassedAtItsGapAndNoLegCrossesAnOutsideCell) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  std::vector<Cell> wall;
  for (int y = 0; y < 9; ++y) wall.push_back({5, y});  // the gap is at the top row
  const std::vector<std::uint8_t> mask = mask_without(g, wall);
  const Result<std::vector<Vec2>> route = plan_mask_route(g, mask, {1.5, 1.5}, {8.5, 1.5});
  ASSERT_TRUE(route) << route.error().message;
  ASSERT_GE(route->size(), 3u);
  for (std::size_t i = 0; i + 1 < route->size(); ++i) {
    EXPECT_TRUE(segment_in_mask(g, mask, (*route)[i], (*route)[i + 1])) << "leg " << i;
  }
  bool through_gap = false;
  for (const Vec2 p : *route) through_gap = through_gap || p.y > 9.0;
  EXPECT_TRUE(through_gap);
}

TEST(RoutePlanner, TheSegmentCheckCountsASliverOfACellAndACornerTouch) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  const std::vector<std::uint8_t> mask = mask_without(g, {{5, 5}});
  // Crosses x = 5 at y = 5.995: a sliver 0.005 m high of cell (5, 5).
  EXPECT_FALSE(segment_in_mask(g, mask, {4.0, 4.99}, {6.0, 7.0}));
  // Through the cell's corner (5, 6) exactly.
  EXPECT_FALSE(segment_in_mask(g, mask, {4.0, 5.0}, {6.0, 7.0}));
  // Crosses x = 5 at y = 6.005: misses it.
  EXPECT_TRUE(segment_in_mask(g, mask, {4.0, 5.01}, {6.0, 7.0}));
}

TEST(RoutePlanner, StringPullingKeepsTheEndsAndDropsRepeatedPoints) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  const std::vector<std::uint8_t> mask = mask_without(g, {});
  const std::vector<Vec2> pulled =
      string_pull(g, mask, {{0.5, 0.5}, {1.5, 0.5}, {2.5, 0.5}, {2.5, 0.5}});
  EXPECT_EQ(pulled, (std::vector<Vec2>{{0.5, 0.5}, {2.5, 0.5}}));
}

TEST(RoutePlanner, EndsWithoutRoomAndUnconnectedEndsAreInputErrors) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  std::vector<Cell> wall;
  for (int y = 0; y < 10; ++y) wall.push_back({5, y});
  const std::vector<std::uint8_t> mask = mask_without(g, wall);
  const Result<std::vector<Vec2>> blocked = plan_mask_route(g, mask, {5.5, 1.5}, {8.5, 1.5});
  ASSERT_FALSE(blocked);
  EXPECT_THAT(blocked.error().message, HasSubstr("start (5.5, 1.5) m has no room"));
  const Result<std::vector<Vec2>> outside = plan_mask_route(g, mask, {1.5, 1.5}, {18.5, 1.5});
  ASSERT_FALSE(outside);
  EXPECT_THAT(outside.error().message, HasSubstr("goal (18.5, 1.5) m"));
  const Result<std::vector<Vec2>> cut = plan_mask_route(g, mask, {1.5, 1.5}, {8.5, 1.5});
  ASSERT_FALSE(cut);
  EXPECT_THAT(cut.error().message, HasSubstr("no path"));
}

TEST(RoutePlanner, DijkstraGivesPathLengthsInCellsAndInfinityWhereItDidNotReach) {
  const GridGeometry g({0.0, 0.0}, 1.0, 10, 10);
  std::vector<Cell> wall;
  for (int y = 0; y < 10; ++y) wall.push_back({5, y});
  const std::vector<std::uint8_t> mask = mask_without(g, wall);
  MaskDijkstra d(g, mask);
  EXPECT_FALSE(d.search({0, 0}, [](Cell) { return false; }));
  EXPECT_DOUBLE_EQ(d.cost_cells({3, 0}), 3.0);
  EXPECT_NEAR(d.cost_cells({2, 2}), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(std::isinf(d.cost_cells({7, 0})));
  const std::optional<Cell> found = d.search({0, 0}, [](Cell c) { return c == Cell{4, 1}; });
  ASSERT_TRUE(found);
  const std::vector<Cell> path = d.path_to(*found);
  EXPECT_EQ(path.front(), (Cell{0, 0}));
  EXPECT_EQ(path.back(), (Cell{4, 1}));
  EXPECT_EQ(path.size(), 5u);
}

}  // namespace
}  // namespace tessera
