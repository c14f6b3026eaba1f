#include "tessera/explore/frontier.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "explore/ascii_map.hpp"

namespace tessera {
namespace {

using ::testing::ElementsAre;

TEST(Frontier, LabyrinthHasTheLecturesThreeFrontierCellsInRowMajorOrder) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  EXPECT_THAT(compute_frontier(map), ElementsAre(Cell{2, 2}, Cell{3, 2}, Cell{1, 3}));
}

TEST(Frontier, UnknownNeighborsCountsTheLecturesA) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  EXPECT_EQ(unknown_neighbors(map, {3, 2}), 1);
  EXPECT_EQ(unknown_neighbors(map, {2, 2}), 2);
  EXPECT_EQ(unknown_neighbors(map, {1, 3}), 3);
  EXPECT_EQ(unknown_neighbors(map, {3, 3}), 0);
  EXPECT_EQ(unknown_neighbors(map, {0, 0}), 2);  // (0,0) itself unknown; outside cells don't count
}

TEST(Frontier, DiagonalUnknownNeighbourDoesNotMakeAFrontierCell) {
  const OccupancyGrid map = test::ascii_map({
      "?#",
      "..",
  });
  // (1,0): unknown only diagonally at (0,1); (0,0) has it straight above.
  EXPECT_FALSE(is_frontier(map, {1, 0}));
  EXPECT_TRUE(is_frontier(map, {0, 0}));
  EXPECT_THAT(compute_frontier(map), ElementsAre(Cell{0, 0}));
}

TEST(Frontier, CellsOutsideTheMapAreNotUnknown) {
  const OccupancyGrid map = test::ascii_map({
      "...",
      "...",
  });
  EXPECT_TRUE(compute_frontier(map).empty());
  EXPECT_EQ(unknown_neighbors(map, {0, 0}), 0);
}

TEST(Frontier, ObstacleAndUnknownCellsAreNeverFrontierCells) {
  const OccupancyGrid map = test::ascii_map({
      "???",
      "#.?",
  });
  EXPECT_FALSE(is_frontier(map, {0, 0}));
  EXPECT_TRUE(is_frontier(map, {1, 0}));
  EXPECT_FALSE(is_frontier(map, {2, 0}));
}

TEST(Frontier, OpenMeansStrictlyBelowLow) {
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, 2, 1));
  map.set_probability({0, 0}, 0.3);
  EXPECT_TRUE(is_frontier(map, {0, 0}, 0.5));
  EXPECT_FALSE(is_frontier(map, {0, 0}, 0.2));
  map.set_probability({0, 0}, 0.5);
  EXPECT_FALSE(is_frontier(map, {0, 0}, 0.5));
}

TEST(Frontier, EmptyAndAllUnknownMapsHaveNoFrontier) {
  EXPECT_TRUE(compute_frontier(OccupancyGrid(GridGeometry({0.0, 0.0}, 1.0, 0, 0))).empty());
  EXPECT_TRUE(compute_frontier(OccupancyGrid(GridGeometry({0.0, 0.0}, 0.1, 30, 20))).empty());
}

}  // namespace
}  // namespace tessera
