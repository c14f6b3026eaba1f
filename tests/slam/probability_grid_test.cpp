#include "tessera/slam/probability_grid.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace tessera::slam {
namespace {

TEST(ProbabilityValues, RoundTripWithinOneStepAndClampToTheLimits) {
  for (double p = 0.1; p <= 0.9; p += 0.01) {
    EXPECT_NEAR(value_to_probability(probability_to_value(p)), p, 1e-4) << p;
  }
  EXPECT_EQ(probability_to_value(0.0), probability_to_value(kMinProbability));
  EXPECT_EQ(probability_to_value(1.0), kMaxCellValue);
  EXPECT_FLOAT_EQ(value_to_probability(kUnknownCellValue), static_cast<float>(kMinProbability));
}

// Bayes in odds form: two hits of 0.55 on an unknown cell give odds (0.55/0.45)^2.
TEST(UpdateTable, AppliesOddsAndTurnsUnknownIntoTheObservation) {
  ProbabilityGrid grid(GridGeometry({0.0, 0.0}, 0.1, 4, 4));
  const UpdateTable hit = make_update_table(0.55);
  EXPECT_FALSE(grid.known({1, 1}));
  EXPECT_TRUE(grid.apply({1, 1}, hit));
  EXPECT_FALSE(grid.apply({1, 1}, hit)) << "a cell is updated once per scan";
  grid.finish_update();
  EXPECT_NEAR(grid.probability({1, 1}), 0.55, 1e-4);
  EXPECT_TRUE(grid.apply({1, 1}, hit));
  grid.finish_update();
  const double odds = (0.55 / 0.45) * (0.55 / 0.45);
  EXPECT_NEAR(grid.probability({1, 1}), odds / (1.0 + odds), 1e-4);
  EXPECT_FLOAT_EQ(grid.probability({-1, 0}), static_cast<float>(kMinProbability));
}

TEST(ProbabilityGrid, GrowingKeepsEveryCellWhereItIsInSpace) {
  ProbabilityGrid grid(GridGeometry({0.0, 0.0}, 0.5, 4, 4));
  grid.set_probability({1, 2}, 0.8);
  const Vec2 where = grid.geometry().center_of({1, 2});
  grid.grow_to_include({-10.0, 7.0});
  const GridGeometry& g = grid.geometry();
  EXPECT_TRUE(g.contains(g.cell_at_unchecked({-10.0, 7.0})));
  EXPECT_DOUBLE_EQ(g.resolution_m(), 0.5);
  const Cell moved = g.cell_at_unchecked(where);
  EXPECT_NEAR(grid.probability(moved), 0.8, 1e-4);
  std::size_t known = 0;
  for (const std::uint16_t v : grid.values()) known += v != kUnknownCellValue ? 1 : 0;
  EXPECT_EQ(known, 1u);
}

// A wall 2 m ahead: its cell is hit, the cells before it are missed, nothing behind it changes.
TEST(RangeInserter, HitsTheEndCellAndMissesTheCellsBeforeIt) {
  ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.1, 40, 20));
  ScanPoints points;
  points.returns_m.push_back({2.03, 0.01});
  RangeInserter{}.insert(grid, Pose2{}, points);
  const GridGeometry& g = grid.geometry();
  EXPECT_NEAR(grid.probability(g.cell_at_unchecked({2.03, 0.01})), 0.55, 1e-4);
  EXPECT_NEAR(grid.probability(g.cell_at_unchecked({1.0, 0.01})), 0.49, 1e-4);
  EXPECT_NEAR(grid.probability(g.cell_at_unchecked({0.0, 0.01})), 0.49, 1e-4);
  EXPECT_FALSE(grid.known(g.cell_at_unchecked({2.5, 0.01})));
  EXPECT_FALSE(grid.known(g.cell_at_unchecked({1.0, 0.5})));
}

TEST(RangeInserter, GrowsTheGridForFarReturnsAndClearsAlongMisses) {
  ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.1, 20, 20));
  ScanPoints points;
  points.returns_m.push_back({5.0, 0.0});
  points.misses_m.push_back({0.0, -3.0});
  RangeInserter{}.insert(grid, Pose2{0.0, 0.0, 0.0}, points);
  const GridGeometry& g = grid.geometry();
  ASSERT_TRUE(g.contains(g.cell_at_unchecked({5.0, 0.0})));
  EXPECT_GT(grid.probability(g.cell_at_unchecked({5.0, 0.0})), 0.5);
  EXPECT_LT(grid.probability(g.cell_at_unchecked({0.05, -2.95})), 0.5);
  const OccupancyGrid occupancy = grid.to_occupancy_grid(0);
  EXPECT_GT(occupancy.known_count(), 80u);
}

// Neighbouring beams' returns are joined into a line of hit cells (no gaps along a wall for a
// matcher to snap to); returns of beams that are not neighbours, or too far apart, are not.
TEST(RangeInserter, JoinsReturnsOfNeighbouringBeams) {
  ScanPoints points;
  points.returns_m = {{2.0, -0.25}, {2.0, 0.25}, {2.0, 0.6}, {3.0, 3.0}};
  points.return_beams = {10, 11, 13, 14};
  const auto hit_cells = [&points](double join_m) {
    ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.05, 100, 100));
    RangeInsertOptions o;
    o.join_returns_within_m = join_m;
    RangeInserter(o).insert(grid, Pose2{}, points);
    int hits = 0;
    for (const std::uint16_t v : grid.values()) hits += value_to_probability(v) > 0.5f ? 1 : 0;
    return hits;
  };
  EXPECT_EQ(hit_cells(0.0), 4);
  EXPECT_EQ(hit_cells(1.0), 4 + 9);  // the 0.5 m gap between beams 10 and 11: 9 cells between
  EXPECT_EQ(hit_cells(0.4), 4);      // too far apart to be one surface
}

TEST(RangeInsertOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(RangeInsertOptions{}).has_value());
  RangeInsertOptions o;
  o.miss_probability = 0.6;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("miss_probability"));
}

}  // namespace
}  // namespace tessera::slam
