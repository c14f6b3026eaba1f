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

// A wall's face on a cell line (y = 0, solid below) seen at 7 degrees from 4 m: the returns land
// 1 cm inside the wall, so each ray runs 8 cm through the row of the wall's face before its
// return. The band without misses is measured across the surface its neighbours show, so those
// face cells stay as they were; a return with no neighbour keeps the band along its ray (the old
// rule, which clears the face cell), and a return seen head-on keeps its 3 cm.
TEST(RangeInserter, AShallowRayDoesNotClearTheFaceOfTheWallItMeets) {
  RangeInsertOptions o;
  o.miss_margin_m = 0.03;
  const Pose2 T_grid_robot{0.0, 0.5, 0.0};
  const auto face_cell_known = [&](std::vector<Vec2> returns_m, std::vector<int> beams) {
    ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.05, 120, 40));
    ScanPoints points;
    for (Vec2& p : returns_m) p = T_grid_robot.inverse() * p;
    points.returns_m = std::move(returns_m);
    points.return_beams = std::move(beams);
    RangeInserter(o).insert(grid, T_grid_robot, points);
    const GridGeometry& g = grid.geometry();
    EXPECT_GT(grid.probability(g.cell_at_unchecked({4.0, -0.01})), 0.5);  // the return's cell
    return grid.known(g.cell_at_unchecked({3.925, -0.025}));  // the ray enters it at x = 3.92
  };
  EXPECT_FALSE(face_cell_known({{4.0, -0.01}, {4.4, -0.01}}, {0, 1}));
  EXPECT_TRUE(face_cell_known({{4.0, -0.01}, {4.4, -0.01}}, {0, 2})) << "not neighbours";

  ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.05, 120, 40));
  ScanPoints head_on;  // a wall across the ray at x = 2.01: the band stays 3 cm along the ray
  head_on.returns_m = {{2.01, -0.2}, {2.01, 0.025}, {2.01, 0.25}};
  head_on.return_beams = {0, 1, 2};
  RangeInserter(o).insert(grid, Pose2{}, head_on);
  const GridGeometry& g = grid.geometry();
  EXPECT_LT(grid.probability(g.cell_at_unchecked({1.975, 0.025})), 0.5);  // entered at 1.95 m
}

// A ray that runs 2 mm inside a row of cells, along its edge (a wall face on a cell line, passed by
// a ray a pose error of a few millimetres away), leaves them as they were once miss_inset_m says
// so; a ray through their middle clears them either way.
TEST(RangeInserter, ARayAlongACellsEdgeLeavesTheCellWithAnInset) {
  const auto row_known = [](double ray_y_m, double inset_m) {
    ProbabilityGrid grid(GridGeometry({-1.0, -1.0}, 0.05, 80, 40));
    ScanPoints points;
    points.origin_m = {0.0, ray_y_m};
    points.misses_m = {{2.0, ray_y_m}};
    RangeInsertOptions o;
    o.miss_inset_m = inset_m;
    RangeInserter(o).insert(grid, Pose2{}, points);
    return grid.known(grid.geometry().cell_at_unchecked({1.0, 0.025}));
  };
  EXPECT_TRUE(row_known(0.002, 0.0));
  EXPECT_FALSE(row_known(0.002, 0.005));
  EXPECT_TRUE(row_known(0.025, 0.005));
  EXPECT_TRUE(row_known(0.048, 0.0));
  EXPECT_FALSE(row_known(0.048, 0.005));
}

TEST(RangeInsertOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(RangeInsertOptions{}).has_value());
  RangeInsertOptions o;
  o.miss_probability = 0.6;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("miss_probability"));
  EXPECT_THAT(validate(RangeInsertOptions{.miss_inset_m = -0.001}).value_or(""),
              ::testing::HasSubstr("miss_inset_m"));
}

}  // namespace
}  // namespace tessera::slam
