#include "tessera/grid/occupancy_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

namespace tessera {
namespace {

const GridGeometry kGeometry({0.0, 0.0}, 1.0, 8, 8);

TEST(OccupancyGrid, NewGridIsUnknownEverywhere) {
  const OccupancyGrid map(kGeometry);
  EXPECT_EQ(map.known_count(), 0u);
  for (std::size_t i = 0; i < kGeometry.size(); ++i) {
    const Cell c = kGeometry.cell_of(i);
    EXPECT_FALSE(map.known(c));
    EXPECT_FALSE(map.probability_at(c).has_value());
    EXPECT_EQ(map.state(c), CellState::kUnknown);
    EXPECT_EQ(map.state(c, 0.7), CellState::kUnknown);
  }
}

TEST(OccupancyGrid, UnknownIsItsOwnStateNotProbabilityOneHalf) {
  OccupancyGrid map(kGeometry);
  map.set_probability({1, 1}, 0.5);
  EXPECT_EQ(map.log_odds_at({1, 1}), map.log_odds_at({2, 2}));  // both log-odds 0 ...
  EXPECT_EQ(map.state({2, 2}), CellState::kUnknown);            // ... but only one was seen
  EXPECT_EQ(map.state({1, 1}), CellState::kOccupied);           // p >= 0.5 at threshold 0.5
  EXPECT_DOUBLE_EQ(*map.probability_at({1, 1}), 0.5);
  EXPECT_FALSE(map.probability_at({2, 2}).has_value());
  map.set_unknown({1, 1});
  EXPECT_EQ(map.state({1, 1}), CellState::kUnknown);
  EXPECT_EQ(map.known_count(), 0u);
}

TEST(OccupancyGrid, ProbabilityViewReturnsWhatWasSet) {
  OccupancyGrid map(kGeometry);
  for (const double p : {0.1, 0.3, 0.5, 0.7, 0.9}) {
    map.set_probability({3, 3}, p);
    EXPECT_NEAR(*map.probability_at({3, 3}), p, 1e-6);
  }
}

TEST(OccupancyGrid, SetProbabilityClampsCertaintyToKeepLogOddsFinite) {
  OccupancyGrid map(kGeometry);
  map.set_probability({0, 0}, 0.0);
  map.set_probability({1, 0}, 1.0);
  EXPECT_TRUE(std::isfinite(map.log_odds_at({0, 0})));
  EXPECT_TRUE(std::isfinite(map.log_odds_at({1, 0})));
  EXPECT_NEAR(*map.probability_at({0, 0}), 1e-4, 1e-7);
  EXPECT_NEAR(*map.probability_at({1, 0}), 1.0 - 1e-4, 1e-7);
}

// The lecture ("The content of the cells"): the cells the triangle covers hold at least 0.7; a
// threshold of 0.5 counts more cells as occupied and makes the object bigger than it is, 0.7 gives
// the better approximation. The slide's figure is not in the text, so the numbers of the two cells
// the triangle only grazes, (4,4) and (3,5), are ours: 0.6 and 0.5.
TEST(OccupancyGrid, ThresholdHalfMakesTheLecturesTriangleBiggerThanThresholdSevenTenths) {
  OccupancyGrid map(kGeometry);
  for (std::size_t i = 0; i < kGeometry.size(); ++i) map.set_probability(kGeometry.cell_of(i), 0.1);
  const std::vector<Cell> object = {{5, 3}, {5, 4}, {5, 5}, {4, 5}, {5, 6}, {4, 6}, {3, 6}};
  const std::vector<double> p_object = {0.7, 0.9, 1.0, 0.8, 1.0, 1.0, 0.7};
  for (std::size_t k = 0; k < object.size(); ++k) map.set_probability(object[k], p_object[k]);
  map.set_probability({4, 4}, 0.6);
  map.set_probability({3, 5}, 0.5);
  const auto count = [&](double threshold) {
    int n = 0;
    for (std::size_t i = 0; i < kGeometry.size(); ++i) {
      n += map.state(kGeometry.cell_of(i), threshold) == CellState::kOccupied ? 1 : 0;
    }
    return n;
  };
  EXPECT_EQ(count(0.5), 9);
  EXPECT_EQ(count(0.7), 7);
  for (const Cell c : object) EXPECT_EQ(map.state(c, 0.7), CellState::kOccupied);
  EXPECT_EQ(map.state({4, 4}, 0.7), CellState::kFree);
  EXPECT_EQ(map.state({4, 4}, 0.5), CellState::kOccupied);
}

TEST(OccupancyGrid, HitAndMissAddTheModelsLogOddsToAnUnknownCell) {
  OccupancyGrid map(kGeometry);
  const SensorModelOptions model;
  map.apply_hit({1, 1}, model);
  map.apply_miss({2, 2}, model);
  EXPECT_FLOAT_EQ(map.log_odds_at({1, 1}), log_odds(0.7));
  EXPECT_NEAR(*map.probability_at({1, 1}), 0.7, 1e-6);
  EXPECT_NEAR(*map.probability_at({2, 2}), 0.4, 1e-6);
  EXPECT_EQ(map.state({2, 2}), CellState::kFree);
  EXPECT_EQ(map.known_count(), 2u);
}

TEST(OccupancyGrid, ClampingLetsAWallThatMovedAwayBecomeFreeAfterNineMisses) {
  // OctoMap's clamping: however many hits, the cell stays within [0.1192, 0.971], so a few misses
  // can change its mind. log-odds(0.971) = 3.51 and a miss adds log-odds(0.4) = -0.405.
  OccupancyGrid map(kGeometry);
  const SensorModelOptions model;
  for (int i = 0; i < 100; ++i) map.apply_hit({4, 4}, model);
  EXPECT_FLOAT_EQ(map.log_odds_at({4, 4}), log_odds(model.p_clamp_max));
  for (int i = 0; i < 8; ++i) map.apply_miss({4, 4}, model);
  EXPECT_EQ(map.state({4, 4}), CellState::kOccupied);
  map.apply_miss({4, 4}, model);
  EXPECT_EQ(map.state({4, 4}), CellState::kFree);
  for (int i = 0; i < 100; ++i) map.apply_miss({4, 4}, model);
  EXPECT_FLOAT_EQ(map.log_odds_at({4, 4}), log_odds(model.p_clamp_min));
}

TEST(OccupancyGrid, AddLogOddsClampsToTheGivenRange) {
  OccupancyGrid map(kGeometry);
  map.add_log_odds({0, 0}, 10.0f, -2.0f, 2.0f);
  EXPECT_FLOAT_EQ(map.log_odds_at({0, 0}), 2.0f);
  map.add_log_odds({0, 0}, -10.0f, -2.0f, 2.0f);
  EXPECT_FLOAT_EQ(map.log_odds_at({0, 0}), -2.0f);
  EXPECT_TRUE(map.known({0, 0}));
}

TEST(OccupancyGrid, IsFreeBelowIsFalseForUnknownCells) {
  OccupancyGrid map(kGeometry);
  EXPECT_FALSE(map.is_free_below({0, 0}, log_odds(0.5)));
  map.set_probability({0, 0}, 0.2);
  EXPECT_TRUE(map.is_free_below({0, 0}, log_odds(0.5)));
  EXPECT_FALSE(map.is_free_below({0, 0}, log_odds(0.1)));
}

TEST(OccupancyGrid, MemoryIsFiveBytesPerCell) {
  EXPECT_EQ(OccupancyGrid(kGeometry).memory_bytes(), 64u * 5u);
  EXPECT_EQ(OccupancyGrid(GridGeometry({0.0, 0.0}, 0.05, 11, 14)).memory_bytes(), 154u * 5u);
}

TEST(SensorModelOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(SensorModelOptions{}).has_value());
  SensorModelOptions o;
  o.p_hit = 0.4;
  ASSERT_TRUE(validate(o).has_value());
  EXPECT_NE(validate(o)->find("p_hit"), std::string::npos);
  o = {};
  o.p_miss = 0.6;
  EXPECT_NE(validate(o)->find("p_miss"), std::string::npos);
  o = {};
  o.p_clamp_min = 0.99;
  EXPECT_NE(validate(o)->find("p_clamp_min"), std::string::npos);
}

TEST(OccupancyGrid, CountStatesFollowsTheThresholdView) {
  OccupancyGrid g(GridGeometry({0.0, 0.0}, 1.0, 4, 1));
  g.set_probability({0, 0}, 0.2);
  g.set_probability({1, 0}, 0.6);
  g.set_probability({2, 0}, 0.9);
  const CellCounts at_half = g.count_states();
  EXPECT_EQ(at_half.free, 1u);
  EXPECT_EQ(at_half.occupied, 2u);
  EXPECT_EQ(at_half.unknown, 1u);
  const CellCounts at_07 = g.count_states(0.7);  // the lecture's higher threshold
  EXPECT_EQ(at_07.free, 2u);
  EXPECT_EQ(at_07.occupied, 1u);
}

// What a robot sends of its map: the smallest box that holds every known cell.
TEST(OccupancyGrid, KnownBoxHoldsEveryKnownCell) {
  OccupancyGrid g(GridGeometry({-1.0, 2.0}, 0.5, 10, 8));
  g.set_probability({3, 2}, 0.2);
  g.set_probability({6, 5}, 0.9);
  const auto same = [](const std::optional<CellBox>& b, Cell min, Cell max) {
    return b && b->min == min && b->max == max;
  };
  EXPECT_TRUE(same(known_box(g), {3, 2}, {6, 5}));
  EXPECT_FALSE(known_box(OccupancyGrid(GridGeometry({0.0, 0.0}, 1.0, 3, 3))).has_value());
  // The box's sides come from different rows: the leftmost and rightmost known cells of any row.
  g.set_probability({1, 4}, 0.5);
  g.set_probability({9, 4}, 0.5);
  EXPECT_TRUE(same(known_box(g), {1, 2}, {9, 5}));
  g.set_unknown({6, 5});
  EXPECT_TRUE(same(known_box(g), {1, 2}, {9, 4}));
}

// The known box as a grid of its own, each cell where it was in space.
TEST(OccupancyGrid, KnownPartIsTheBoxOfTheKnownCellsInPlace) {
  OccupancyGrid g(GridGeometry({-1.0, 2.0}, 0.5, 10, 8));
  g.set_probability({3, 2}, 0.2);
  g.set_probability({6, 5}, 0.9);
  const OccupancyGrid part = known_part(g);
  EXPECT_EQ(part.geometry(), GridGeometry({0.5, 3.0}, 0.5, 4, 4));
  EXPECT_NEAR(*part.probability_at({0, 0}), 0.2, 1e-6);
  EXPECT_NEAR(*part.probability_at({3, 3}), 0.9, 1e-6);
  EXPECT_FALSE(part.known({1, 1}));
  EXPECT_EQ(part.known_count(), 2u);
  EXPECT_EQ(known_part(OccupancyGrid(GridGeometry({0.0, 0.0}, 1.0, 3, 3))).geometry().size(), 0u);
}

}  // namespace
}  // namespace tessera
