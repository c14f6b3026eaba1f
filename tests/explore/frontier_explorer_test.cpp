#include "tessera/explore/frontier_explorer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "explore/ascii_map.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

FrontierExplorerOptions with(FrontierStrategy strategy, int spread_radius_cells = 4) {
  FrontierExplorerOptions o;
  o.strategy = strategy;
  o.spread_radius_cells = spread_radius_cells;
  return o;
}

TEST(FrontierExplorer, LabyrinthNearestPicksTheCellOneStepAway) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  const FrontierSet frontier(map);
  FrontierExplorer explorer(with(FrontierStrategy::kNearest), 1);
  const auto plan = explorer.plan(map, frontier, 0, {3, 3});
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->target, (Cell{3, 2}));
  EXPECT_EQ(plan->distance_cells, 1);
  EXPECT_EQ(plan->unknown_neighbors, 1);
  EXPECT_DOUBLE_EQ(plan->priority, 1.0);  // p(3,2) = 1/1
  EXPECT_THAT(plan->path, ElementsAre(Cell{3, 3}, Cell{3, 2}));
}

TEST(FrontierExplorer, LabyrinthPriorityPicksTheCellWithThreeUnknownNeighbours) {
  // lecture: p(3,2) = 1/1 = 1, p(2,2) = 2/2 = 1, p(1,3) = 3/2 = 1.5 -> start from (1,3).
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  const FrontierSet frontier(map);
  FrontierExplorer explorer(with(FrontierStrategy::kPriority), 1);
  const auto plan = explorer.plan(map, frontier, 0, {3, 3});
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->target, (Cell{1, 3}));
  EXPECT_EQ(plan->distance_cells, 2);
  EXPECT_EQ(plan->unknown_neighbors, 3);
  EXPECT_DOUBLE_EQ(plan->priority, 1.5);
  EXPECT_THAT(plan->path, ElementsAre(Cell{3, 3}, Cell{2, 3}, Cell{1, 3}));
  EXPECT_EQ(explorer.claim(0), (Cell{1, 3}));
}

TEST(FrontierExplorer, RobotStandingOnAFrontierCellCountsDistanceAsOne) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  const FrontierSet frontier(map);
  FrontierExplorer explorer(with(FrontierStrategy::kPriority), 1);
  const auto plan = explorer.plan(map, frontier, 0, {1, 3});  // d = 0, a = 3
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->target, (Cell{1, 3}));
  EXPECT_EQ(plan->distance_cells, 0);
  EXPECT_DOUBLE_EQ(plan->priority, 3.0);
  EXPECT_THAT(plan->path, ElementsAre(Cell{1, 3}));
}

TEST(FrontierExplorer, BlacklistedTargetIsNeverChosenAgain) {
  const OccupancyGrid map = test::ascii_map(test::labyrinth_rows());
  const FrontierSet frontier(map);
  FrontierExplorer explorer(with(FrontierStrategy::kNearest), 1);
  explorer.blacklist({3, 2});
  EXPECT_TRUE(explorer.blacklisted({3, 2}));
  const auto plan = explorer.plan(map, frontier, 0, {3, 3});
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->target, (Cell{2, 2}));  // d = 2, found before (1,3) in BFS order
  explorer.blacklist({2, 2});
  explorer.blacklist({1, 3});
  EXPECT_FALSE(explorer.plan(map, frontier, 0, {3, 3}).has_value());
  EXPECT_THAT(explorer.blacklisted_cells(), ElementsAre(Cell{3, 2}, Cell{2, 2}, Cell{1, 3}));
  EXPECT_THAT(explorer.unreachable(), IsEmpty());  // blacklisted cells are not "unreachable"
}

TEST(FrontierExplorer, SeveralRobotsGetDistinctTargets) {
  // Both robots are closest to (1,1); robot 0 plans first and claims it, robot 1 takes (9,1).
  const std::vector<std::string> rows{
      "###########",
      "?.AB......?",
      "###########",
  };
  const OccupancyGrid map = test::ascii_map(rows);
  const FrontierSet frontier(map);
  for (const FrontierStrategy s : {FrontierStrategy::kNearest, FrontierStrategy::kPriority}) {
    FrontierExplorer explorer(with(s), 2);
    const std::vector<Cell> robots{test::find_char(rows, 'A'), test::find_char(rows, 'B')};
    const auto plans = explorer.plan_all(map, frontier, robots);
    ASSERT_EQ(plans.size(), 2u);
    ASSERT_TRUE(plans[0].has_value() && plans[1].has_value()) << to_string(s);
    EXPECT_EQ(plans[0]->target, (Cell{1, 1})) << to_string(s);
    EXPECT_EQ(plans[1]->target, (Cell{9, 1})) << to_string(s);
    EXPECT_EQ(plans[1]->distance_cells, 6);
  }
}

TEST(FrontierExplorer, RobotsSpreadAwayFromEachOthersTargets) {
  // A long frontier row; the robots stand side by side under it.
  const std::vector<std::string> rows{
      "????????????",
      "............",
      "####AB######",
  };
  const OccupancyGrid map = test::ascii_map(rows);
  const FrontierSet frontier(map);
  const std::vector<Cell> robots{test::find_char(rows, 'A'), test::find_char(rows, 'B')};
  {
    FrontierExplorer explorer(with(FrontierStrategy::kNearest, /*spread_radius_cells=*/4), 2);
    const auto plans = explorer.plan_all(map, frontier, robots);
    ASSERT_TRUE(plans[0].has_value() && plans[1].has_value());
    EXPECT_EQ(plans[0]->target, (Cell{4, 1}));
    EXPECT_EQ(plans[1]->target, (Cell{9, 1}));  // first cell more than 4 columns from (4,1)
  }
  {
    FrontierExplorer explorer(with(FrontierStrategy::kNearest, /*spread_radius_cells=*/0), 2);
    const auto plans = explorer.plan_all(map, frontier, robots);
    ASSERT_TRUE(plans[0].has_value() && plans[1].has_value());
    EXPECT_EQ(plans[1]->target, (Cell{5, 1}));  // only the claimed cell itself is excluded
  }
}

TEST(FrontierExplorer, CellsNearAClaimAreAFallbackWhenNothingElseIsReachable) {
  const std::vector<std::string> rows{
      "####??####",
      "####..####",
      "####AB####",
  };
  const OccupancyGrid map = test::ascii_map(rows);
  const FrontierSet frontier(map);
  FrontierExplorer explorer(with(FrontierStrategy::kNearest, 4), 2);
  const std::vector<Cell> robots{test::find_char(rows, 'A'), test::find_char(rows, 'B')};
  const auto plans = explorer.plan_all(map, frontier, robots);
  ASSERT_TRUE(plans[0].has_value() && plans[1].has_value());
  EXPECT_EQ(plans[0]->target, (Cell{4, 1}));
  EXPECT_EQ(plans[1]->target, (Cell{5, 1}));
}

TEST(FrontierExplorer, UnreachableFrontierIsRememberedAndRetriedWhenTheMapChanges) {
  // The robot's room is fully known; through a window it saw the open row y = 3, whose frontier it
  // cannot reach through known free cells.
  OccupancyGrid map = test::ascii_map({
      "??????",
      "#....#",
      "######",
      "#R...#",
      "######",
  });
  FrontierSet frontier(map);
  ASSERT_EQ(frontier.size(), 4u);
  FrontierExplorer explorer(with(FrontierStrategy::kNearest), 1);
  EXPECT_FALSE(explorer.plan(map, frontier, 0, {1, 1}).has_value());
  ASSERT_EQ(explorer.unreachable().size(), 4u);
  EXPECT_EQ(explorer.unreachable()[0].cell, (Cell{1, 3}));
  EXPECT_EQ(explorer.unreachable()[0].revision, frontier.revision());
  // Asked again with nothing changed: the same answer.
  EXPECT_FALSE(explorer.plan(map, frontier, 0, {1, 1}).has_value());
  // The door at (2,2) turns out to be open: the frontier is reachable now.
  map.set_probability({2, 2}, 0.1);
  const std::vector<Cell> touched{{2, 2}};
  frontier.update(map, touched);
  const auto plan = explorer.plan(map, frontier, 0, {1, 1});
  ASSERT_TRUE(plan.has_value());
  EXPECT_EQ(plan->target, (Cell{2, 3}));
  EXPECT_EQ(plan->distance_cells, 3);
}

TEST(FrontierExplorer, ChoicesMatchBruteForceOnRandomMaps) {
  // Property: the nearest plan has the minimum path distance over reachable frontier cells, and the
  // pruned priority search finds the maximum a / max(d, 1).
  Rng rng(99);
  for (int trial = 0; trial < 200; ++trial) {
    const int w = rng.uniform_int(3, 24), h = rng.uniform_int(3, 24);
    OccupancyGrid map(GridGeometry({0.0, 0.0}, 0.5, w, h));
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        const double u = rng.uniform(0.0, 1.0);
        if (u < 0.55)
          map.set_probability({x, y}, 0.1);
        else if (u < 0.75)
          map.set_probability({x, y}, 0.9);
      }
    }
    const Cell robot{rng.uniform_int(0, w - 1), rng.uniform_int(0, h - 1)};
    const FrontierSet frontier(map);
    const std::vector<int> d = free_space_distances(map, robot);
    int best_d = -1;
    double best_p = -1.0;
    for (const Cell c : frontier.cells()) {
      const int dc = d[map.geometry().index_of(c)];
      if (dc < 0) continue;
      if (best_d < 0 || dc < best_d) best_d = dc;
      best_p = std::max(best_p, unknown_neighbors(map, c) / static_cast<double>(std::max(dc, 1)));
    }
    FrontierExplorer nearest(with(FrontierStrategy::kNearest), 1);
    FrontierExplorer priority(with(FrontierStrategy::kPriority), 1);
    const auto n = nearest.plan(map, frontier, 0, robot);
    const auto p = priority.plan(map, frontier, 0, robot);
    ASSERT_EQ(n.has_value(), best_d >= 0) << "trial " << trial;
    ASSERT_EQ(p.has_value(), best_d >= 0) << "trial " << trial;
    if (best_d < 0) continue;
    EXPECT_EQ(n->distance_cells, best_d) << "trial " << trial;
    EXPECT_DOUBLE_EQ(p->priority, best_p) << "trial " << trial;
    EXPECT_TRUE(frontier.contains(p->target));
    EXPECT_EQ(static_cast<int>(p->path.size()) - 1, d[map.geometry().index_of(p->target)]);
  }
}

TEST(FrontierExplorer, OptionsAreValidated) {
  EXPECT_FALSE(validate(FrontierExplorerOptions{}).has_value());
  FrontierExplorerOptions o;
  o.low = 1.0;
  EXPECT_TRUE(validate(o).has_value());
  o = {};
  o.spread_radius_cells = -1;
  EXPECT_TRUE(validate(o).has_value());
}

}  // namespace
}  // namespace tessera
