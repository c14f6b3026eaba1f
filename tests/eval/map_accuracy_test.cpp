#include "tessera/eval/map_accuracy.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera {
namespace {

// 4 x 1 truth: free, solid, free, solid.
World four_cells() {
  return World(GridGeometry({0.0, 0.0}, 0.5, 4, 1), std::vector<std::uint8_t>{0, 1, 0, 1});
}

TEST(MapAccuracy, CountsTheTwoKindsOfErrorOverKnownCellsOnly) {
  const World truth = four_cells();
  OccupancyGrid map(truth.geometry());
  map.set_probability({0, 0}, 0.1);  // free as free: correct
  map.set_probability({1, 0}, 0.2);  // solid sensed as empty
  map.set_probability({2, 0}, 0.8);  // free sensed as occupied
  // (3,0) unknown: not compared
  const MapAccuracy a = compare_to_truth(map, truth);
  EXPECT_EQ(a.cells_compared, 3u);
  EXPECT_EQ(a.correct, 1u);
  EXPECT_EQ(a.occupied_as_empty, 1u);
  EXPECT_EQ(a.empty_as_occupied, 1u);
  EXPECT_DOUBLE_EQ(a.success_rate, 1.0 / 3.0);
}

TEST(MapAccuracy, ThresholdDecidesWhatCountsAsOccupied) {
  const World truth = four_cells();
  OccupancyGrid map(truth.geometry());
  map.set_probability({1, 0}, 0.6);
  EXPECT_EQ(compare_to_truth(map, truth, 0.5).correct, 1u);
  EXPECT_EQ(compare_to_truth(map, truth, 0.7).occupied_as_empty, 1u);  // objects look smaller
  map.set_probability({1, 0}, 0.5);  // p == threshold counts as occupied
  EXPECT_EQ(compare_to_truth(map, truth, 0.5).correct, 1u);
}

TEST(MapAccuracy, EmptyMapComparesNothing) {
  const World truth = four_cells();
  const MapAccuracy a = compare_to_truth(OccupancyGrid(truth.geometry()), truth);
  EXPECT_EQ(a.cells_compared, 0u);
  EXPECT_DOUBLE_EQ(a.success_rate, 0.0);
}

TEST(MapAccuracy, PerfectMapOfTheTruthScoresOne) {
  const World truth = four_cells();
  OccupancyGrid map(truth.geometry());
  for (int x = 0; x < 4; ++x) map.set_probability({x, 0}, truth.solid({x, 0}) ? 0.97 : 0.12);
  const MapAccuracy a = compare_to_truth(map, truth);
  EXPECT_EQ(a.correct, 4u);
  EXPECT_DOUBLE_EQ(a.success_rate, 1.0);
}

}  // namespace
}  // namespace tessera
