#include "tessera/nav/wavefront.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include "taught_corridor.hpp"
#include "tessera/fusion/hex_cell_map.hpp"

namespace tessera {
namespace {

using ::testing::ElementsAre;

// A chain 0-1-2-3 plus a branch 1-4 and an isolated cell 5.
CellGraph small_graph() {
  CellGraph g;
  g.centres_m = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {1, 1}, {9, 9}};
  g.adjacent = {{1}, {0, 2, 4}, {1, 3}, {2}, {1}, {}};
  return g;
}

TEST(Wavefront, GoalGetsTheCellCountAndEachStepAwayOneLessUnreachableStaysMinusOne) {
  const CellGraph g = small_graph();
  const WavefrontField f = wavefront(g, 3);
  // Thesis 4.3.5: goal = number of cells stored (6), decremented per adjacency step, -1 elsewhere.
  EXPECT_THAT(f.value, ElementsAre(3, 4, 5, 6, 3, kNoWavefrontValue));
  EXPECT_EQ(f.goal, 3u);
}

TEST(Wavefront, PathClimbsTheValuesToTheGoal) {
  const CellGraph g = small_graph();
  const WavefrontField f = wavefront(g, 3);
  EXPECT_THAT(wavefront_path(g, f, 4), ElementsAre(4u, 1u, 2u, 3u));
  EXPECT_THAT(wavefront_path(g, f, 3), ElementsAre(3u));
  EXPECT_TRUE(wavefront_path(g, f, 5).empty());
  EXPECT_EQ(wavefront_next(g, f, 5), 5u);
  EXPECT_DOUBLE_EQ(cell_path_length_m(g, {4, 1, 2, 3}), 3.0);
}

TEST(Wavefront, TiesGoToTheNeighbourNearerTheGoalThenToTheLowerId) {
  // A diamond 0 -> {1, 2} -> 3: 1 and 2 tie on value.
  CellGraph g;
  g.centres_m = {{0, 0}, {1, 1}, {1, -0.5}, {2, 0}};
  g.adjacent = {{1, 2}, {0, 3}, {0, 3}, {1, 2}};
  WavefrontField f = wavefront(g, 3);
  EXPECT_EQ(f.value[1], f.value[2]);
  EXPECT_EQ(wavefront_next(g, f, 0), 2u);  // (1, -0.5) is nearer (2, 0) than (1, 1)
  g.centres_m[2] = {1, -1};                // now equally near: the lower id
  f = wavefront(g, 3);
  EXPECT_EQ(wavefront_next(g, f, 0), 1u);
}

TEST(Wavefront, OnTheThesisMapItUsesOnlyTraversedAdjacency) {
  // Out along y = +0.03 and back along y = -0.03: traversed adjacency reaches every cell, and the
  // path from the start to the far end is a shortest one in traversed steps.
  const fusion::HexCellMap map = nav_test::taught_corridor(nav_test::corridor_length_m());
  const CellGraph g = map.graph(fusion::CellAdjacency::kTraversed);
  const std::size_t goal = *map.find(map.lattice().cell_at({nav_test::corridor_length_m(), 0.0}));
  const WavefrontField f = wavefront(g, goal);
  for (std::size_t i = 0; i < g.size(); ++i) EXPECT_NE(f.value[i], kNoWavefrontValue) << i;
  const std::vector<std::size_t> path = wavefront_path(g, f, 0);
  ASSERT_FALSE(path.empty());
  EXPECT_EQ(path.back(), goal);
  for (std::size_t i = 1; i < path.size(); ++i) {
    EXPECT_EQ(f.value[path[i]], f.value[path[i - 1]] + 1);
    const auto& adj = g.adjacent[path[i - 1]];
    EXPECT_NE(std::find(adj.begin(), adj.end(), path[i]), adj.end());
  }
  // Each step advances one column: as few steps as the lattice allows.
  EXPECT_EQ(static_cast<int>(path.size()) - 1,
            hex_distance(map.cell(0).coord, map.cell(goal).coord));
  EXPECT_EQ(static_cast<int>(path.size()) - 1, f.value[goal] - f.value[0]);
}

}  // namespace
}  // namespace tessera
