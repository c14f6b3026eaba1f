#include "tessera/eval/map_accuracy.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera {
namespace {

// 4 x 1 truth: free, solid, free, solid.
const std::vector<std::uint8_t> kFourCells{0, 1, 0, 1};
TruthGrid four_cells() { return TruthGrid(GridGeometry({0.0, 0.0}, 0.5, 4, 1), kFourCells); }

TEST(MapAccuracy, CountsTheTwoKindsOfErrorOverKnownCellsOnly) {
  const TruthGrid truth = four_cells();
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
  const TruthGrid truth = four_cells();
  OccupancyGrid map(truth.geometry());
  map.set_probability({1, 0}, 0.6);
  EXPECT_EQ(compare_to_truth(map, truth, 0.5).correct, 1u);
  EXPECT_EQ(compare_to_truth(map, truth, 0.7).occupied_as_empty, 1u);  // objects look smaller
  map.set_probability({1, 0}, 0.5);  // p == threshold counts as occupied
  EXPECT_EQ(compare_to_truth(map, truth, 0.5).correct, 1u);
}

TEST(MapAccuracy, AsShownCellsBetweenTheThresholdsAreGreyAndNotCompared) {
  const TruthGrid truth = four_cells();
  OccupancyGrid map(truth.geometry());
  map.set_probability({0, 0}, 0.1);   // shown free: correct
  map.set_probability({1, 0}, 0.4);   // a wall cell the map is unsure of: grey, not compared
  map.set_probability({2, 0}, 0.8);   // free shown occupied
  map.set_probability({3, 0}, 0.25);  // solid shown free (p == free_at_most is free)
  const MapAccuracy a = compare_to_truth_as_shown(map, truth, 0.25, 0.65);
  EXPECT_EQ(a.cells_compared, 3u);
  EXPECT_EQ(a.correct, 1u);
  EXPECT_EQ(a.empty_as_occupied, 1u);
  EXPECT_EQ(a.occupied_as_empty, 1u);
  EXPECT_EQ(a.occupied_compared, 1u);
  // The threshold view counts the unsure wall cell as shown free.
  EXPECT_EQ(compare_to_truth(map, truth).occupied_as_empty, 2u);
}

TEST(MapAccuracy, EmptyMapComparesNothing) {
  const TruthGrid truth = four_cells();
  const MapAccuracy a = compare_to_truth(OccupancyGrid(truth.geometry()), truth);
  EXPECT_EQ(a.cells_compared, 0u);
  EXPECT_DOUBLE_EQ(a.success_rate, 0.0);
}

TEST(MapAccuracy, PerfectMapOfTheTruthScoresOne) {
  const TruthGrid truth = four_cells();
  OccupancyGrid map(truth.geometry());
  for (int x = 0; x < 4; ++x) map.set_probability({x, 0}, truth.solid({x, 0}) ? 0.97 : 0.12);
  const MapAccuracy a = compare_to_truth(map, truth);
  EXPECT_EQ(a.correct, 4u);
  EXPECT_DOUBLE_EQ(a.success_rate, 1.0);
}

TEST(MapAccuracy, CountsTheOccupiedCellsComparedForTheShare) {
  const TruthGrid truth = four_cells();
  OccupancyGrid map(truth.geometry());
  map.set_probability({1, 0}, 0.2);  // solid sensed as empty
  map.set_probability({3, 0}, 0.9);  // solid sensed as occupied
  map.set_probability({0, 0}, 0.1);
  const MapAccuracy a = compare_to_truth(map, truth);
  EXPECT_EQ(a.occupied_compared, 2u);
  EXPECT_DOUBLE_EQ(a.occupied_as_empty_share(), 0.5);
}

// A SLAM map lives on its own grid: here cells of 0.25 m shifted by 0.1 m against the truth's
// 0.5 m cells. Each map cell takes the truth of the world cell under its centre.
TEST(MapAccuracy, AtCentresComparesAMapOnAnotherGrid) {
  const TruthGrid truth = four_cells();  // x in [0, 0.5) free, [0.5, 1) solid, [1, 1.5) free, ...
  OccupancyGrid map(GridGeometry({0.1, 0.0}, 0.25, 4, 1));
  // Centres at 0.225 (free), 0.475 (free), 0.725 (solid), 0.975 (solid).
  map.set_probability({0, 0}, 0.1);
  map.set_probability({1, 0}, 0.9);  // free sensed as occupied
  map.set_probability({2, 0}, 0.9);
  map.set_probability({3, 0}, 0.2);  // solid sensed as empty
  const MapAccuracy a = compare_to_truth_at_centres(map, truth);
  EXPECT_EQ(a.cells_compared, 4u);
  EXPECT_EQ(a.correct, 2u);
  EXPECT_EQ(a.empty_as_occupied, 1u);
  EXPECT_EQ(a.occupied_as_empty, 1u);
  EXPECT_EQ(a.occupied_compared, 2u);
}

TEST(MapAccuracy, AtCentresTreatsSpaceOutsideTheWorldAsSolid) {
  const TruthGrid truth = four_cells();
  OccupancyGrid map(GridGeometry({-1.0, 0.0}, 0.5, 1, 1));  // entirely left of the world
  map.set_probability({0, 0}, 0.1);
  EXPECT_EQ(compare_to_truth_at_centres(map, truth).occupied_as_empty, 1u);
}

}  // namespace
}  // namespace tessera
