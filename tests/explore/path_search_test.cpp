#include "tessera/explore/path_search.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <vector>

#include "explore/ascii_map.hpp"
#include "tessera/explore/frontier_set.hpp"

namespace tessera {
namespace {

using ::testing::ElementsAre;

// The open row y = 3 is frontier all along (unknown above it), and its cell (1,3) is two cells
// straight above the robot, but the wall at y = 2 only opens at x = 8.
const std::vector<std::string> kWallRows{
    "?????????#", ".........#", "########.#", "#R.......#", "##########",
};

void expect_valid_path(const OccupancyGrid& map, const std::vector<Cell>& path) {
  for (std::size_t k = 1; k < path.size(); ++k) {
    EXPECT_EQ(manhattan(path[k - 1], path[k]), 1) << "step " << k;
    EXPECT_EQ(map.state(path[k]), CellState::kFree) << "step " << k;
  }
}

TEST(PathSearch, NearestFrontierIsMeasuredAlongThePathAroundObstaclesNotStraightLine) {
  const OccupancyGrid map = test::ascii_map(kWallRows);
  const FrontierSet frontier(map);
  ASSERT_TRUE(frontier.contains({1, 3}));  // the straight-line closest frontier cell
  FreeSpaceBfs bfs;
  const std::optional<FrontierPath> nearest = nearest_frontier(bfs, map, frontier, {1, 1});
  ASSERT_TRUE(nearest.has_value());
  EXPECT_EQ(nearest->target, (Cell{8, 3}));
  EXPECT_EQ(nearest->distance_cells, 9);
  ASSERT_EQ(nearest->path.size(), 10u);
  EXPECT_EQ(nearest->path.front(), (Cell{1, 1}));
  EXPECT_EQ(nearest->path.back(), (Cell{8, 3}));
  expect_valid_path(map, nearest->path);
}

TEST(PathSearch, DistancesFollowTheFreeCells) {
  const OccupancyGrid map = test::ascii_map(kWallRows);
  const std::vector<int> d = free_space_distances(map, {1, 1});
  const auto at = [&](Cell c) { return d[map.geometry().index_of(c)]; };
  EXPECT_EQ(at({1, 1}), 0);
  EXPECT_EQ(at({8, 1}), 7);
  EXPECT_EQ(at({1, 3}), 16);  // 9 to (8,3), then 7 back along the row
  EXPECT_EQ(at({0, 3}), 17);
  EXPECT_EQ(at({0, 0}), -1);  // obstacle
  EXPECT_EQ(at({3, 4}), -1);  // unknown cells are never entered
}

TEST(PathSearch, ShortestPathUsesOnlyKnownFreeCells) {
  const OccupancyGrid map = test::ascii_map(kWallRows);
  const std::vector<Cell> path = shortest_free_path(map, {1, 1}, {0, 3});
  ASSERT_EQ(path.size(), 18u);
  expect_valid_path(map, path);
  EXPECT_TRUE(shortest_free_path(map, {1, 1}, {3, 4}).empty());  // unknown goal
  EXPECT_THAT(shortest_free_path(map, {1, 1}, {1, 1}), ElementsAre(Cell{1, 1}));
}

TEST(PathSearch, TiesGoNorthFirstThenEastSouthWest) {
  {
    // Frontier cells straight above and below the robot, both one step away: North wins.
    const OccupancyGrid map = test::ascii_map({
        "?????",
        "##.##",
        "#.R.#",
        "##.##",
        "?????",
    });
    FreeSpaceBfs bfs;
    const auto nearest = nearest_frontier(bfs, map, FrontierSet(map), {2, 2});
    ASSERT_TRUE(nearest.has_value());
    EXPECT_EQ(nearest->target, (Cell{2, 3}));
  }
  {
    // East and West, one step each: East wins.
    const OccupancyGrid map = test::ascii_map({
        "#####",
        "?.R.?",
        "#####",
    });
    FreeSpaceBfs bfs;
    const auto nearest = nearest_frontier(bfs, map, FrontierSet(map), {2, 1});
    ASSERT_TRUE(nearest.has_value());
    EXPECT_EQ(nearest->target, (Cell{3, 1}));
  }
}

TEST(PathSearch, BfsVisitsCellsInOrderOfDistance) {
  const OccupancyGrid map = test::ascii_map({
      ".....",
      ".#.#.",
      ".....",
  });
  FreeSpaceBfs bfs;
  bfs.start(map, {2, 1});
  int last = 0;
  std::size_t count = 0;
  while (const std::optional<Cell> c = bfs.next()) {
    EXPECT_GE(bfs.distance(*c), last);
    last = bfs.distance(*c);
    ++count;
  }
  EXPECT_EQ(count, 13u);
  EXPECT_EQ(bfs.distance({0, 1}), 4);
  EXPECT_FALSE(bfs.discovered({1, 1}));
}

TEST(PathSearch, StartCellIsExpandedWhateverTheMapSays) {
  // The robot stands in a cell the map does not know yet: it can still leave it.
  const OccupancyGrid map = test::ascii_map({"?.?"});
  FreeSpaceBfs bfs;
  bfs.start(map, {0, 0});
  EXPECT_EQ(bfs.run_to_completion(), 2u);
  EXPECT_EQ(bfs.distance({1, 0}), 1);
  EXPECT_EQ(bfs.distance({2, 0}), -1);
}

TEST(PathSearch, ReusedSearchForgetsThePreviousOneAndAdaptsToANewGeometry) {
  const OccupancyGrid a = test::ascii_map(kWallRows);
  const OccupancyGrid b = test::ascii_map({"...", "..."});
  FreeSpaceBfs bfs;
  bfs.start(a, {1, 1});
  bfs.run_to_completion();
  EXPECT_TRUE(bfs.discovered({8, 3}));
  bfs.start(a, {0, 3});
  EXPECT_FALSE(bfs.discovered({8, 3}));  // not yet: the new search has only the start
  bfs.start(b, {0, 0});
  EXPECT_EQ(bfs.run_to_completion(), 6u);
  EXPECT_EQ(bfs.distance({2, 1}), 3);
  EXPECT_THAT(bfs.path_to({2, 1}), ElementsAre(Cell{0, 0}, Cell{0, 1}, Cell{1, 1}, Cell{2, 1}));
}

}  // namespace
}  // namespace tessera
