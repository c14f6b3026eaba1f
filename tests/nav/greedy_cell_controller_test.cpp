#include "tessera/nav/greedy_cell_controller.hpp"

#include <gtest/gtest.h>

#include "unicycle.hpp"

namespace tessera {
namespace {

// Four cells in a row, 1 m apart, and one cell (4) that nothing is adjacent to.
CellGraph row() {
  CellGraph g;
  g.centres_m = {{0, 0}, {1, 0}, {2, 0}, {3, 0}, {0, 3}};
  g.adjacent = {{1}, {0, 2}, {1, 3}, {2}, {}};
  return g;
}

TEST(GreedyCellController, HeadsForTheBestNeighbourOfTheNearestCellAndArrivesAtTheGoalCentre) {
  GreedyCellController c(row(), 3);
  // In cell 0 facing +y: the target is cell 1's centre, to the right -> turn clockwise.
  const VelocityCommand first = c.command({0.1, 0.0, 1.5707963});
  EXPECT_LT(first.omega_rad_per_s, 0.0);
  const nav_test::DriveResult r = nav_test::drive(c, {0.0, 0.0, 0.0}, 0.1, 60.0);
  ASSERT_TRUE(r.arrived);
  EXPECT_LT((r.poses.back().translation() - Vec2{3, 0}).norm(), 0.05);
  EXPECT_EQ(c.target_changes(), 2);  // 1 -> 2 -> 3, one decision per border
}

TEST(GreedyCellController, StopsWhenTheCurrentCellCannotReachTheGoal) {
  GreedyCellController c(row(), 3);
  const VelocityCommand cmd = c.command({0.0, 2.9, 0.0});  // nearest cell: 4, not connected
  EXPECT_TRUE(c.stuck());
  EXPECT_FALSE(c.arrived());
  EXPECT_EQ(cmd.v_m_per_s, 0.0);
  EXPECT_EQ(cmd.omega_rad_per_s, 0.0);
  EXPECT_EQ(c.field().value[4], kNoWavefrontValue);
}

}  // namespace
}  // namespace tessera
