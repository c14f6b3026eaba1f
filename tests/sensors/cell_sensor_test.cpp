#include "tessera/sensors/cell_sensor.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <ostream>
#include <vector>

#include "support/cell_print.hpp"

namespace tessera {

namespace {

using ::testing::UnorderedElementsAre;

const GridGeometry kCellGeometry({0.0, 0.0}, 1.0, 5, 5);

CellReading reading_at(Cell center, std::vector<int> occupied_k) {
  CellReading r;
  r.center = center;
  for (std::size_t k = 0; k < 8; ++k)
    r.inside_map[k] = kCellGeometry.contains(center + kNeighbors8[k]);
  for (const int k : occupied_k) r.occupied[static_cast<std::size_t>(k)] = true;
  return r;
}

TEST(InsertCellReading, CentreAndOpenNeighboursGetPFreeAndObstaclesPOccupied) {
  OccupancyGrid map(kCellGeometry);
  // North (k = 0) and South-West (k = 5) hold obstacles.
  insert_cell_reading(map, reading_at({2, 2}, {0, 5}), {}, nullptr);
  EXPECT_EQ(map.known_count(), 9u);
  EXPECT_NEAR(*map.probability_at({2, 2}), 0.1, 1e-6);
  EXPECT_NEAR(*map.probability_at({2, 3}), 0.9, 1e-6);
  EXPECT_NEAR(*map.probability_at({1, 1}), 0.9, 1e-6);
  EXPECT_NEAR(*map.probability_at({3, 3}), 0.1, 1e-6);
  EXPECT_EQ(map.state({0, 0}), CellState::kUnknown);
}

TEST(InsertCellReading, NeighboursBeyondTheMapEdgeAreNotWritten) {
  OccupancyGrid map(kCellGeometry);
  std::vector<Cell> touched;
  insert_cell_reading(map, reading_at({0, 0}, {}), {}, &touched);
  EXPECT_THAT(touched, UnorderedElementsAre(Cell{0, 0}, Cell{0, 1}, Cell{1, 1}, Cell{1, 0}));
  EXPECT_EQ(map.known_count(), 4u);
}

TEST(InsertCellReading, NeighbourMarkedOutsideTheMapIsSkippedEvenIfTheGridHasIt) {
  OccupancyGrid map(kCellGeometry);
  CellReading r = reading_at({2, 2}, {2});
  r.inside_map[2] = false;  // East not reported
  insert_cell_reading(map, r, {}, nullptr);
  EXPECT_EQ(map.state({3, 2}), CellState::kUnknown);
  EXPECT_EQ(map.known_count(), 8u);
}

TEST(InsertCellReading, TouchedListsOnlyCellsThatChangedOrBecameKnown) {
  OccupancyGrid map(kCellGeometry);
  std::vector<Cell> touched;
  insert_cell_reading(map, reading_at({2, 2}, {0}), {}, &touched);
  EXPECT_EQ(touched.size(), 9u);
  touched.clear();
  insert_cell_reading(map, reading_at({2, 2}, {0}), {}, &touched);
  EXPECT_TRUE(touched.empty());
  // The robot moves East: (2,1), (3,1), (2,2) and (3,2) keep their values.
  insert_cell_reading(map, reading_at({3, 2}, {0}), {}, &touched);
  EXPECT_THAT(touched, UnorderedElementsAre(Cell{3, 3},  // NE of (2,2): was open, now obstacle
                                            Cell{2, 3},  // N of (2,2): was obstacle, now open
                                            Cell{4, 3}, Cell{4, 2}, Cell{4, 1}));
}

TEST(InsertCellReading, UsesTheConfiguredProbabilities) {
  OccupancyGrid map(kCellGeometry);
  CellSensorOptions options;
  options.p_free = 0.2;
  options.p_occupied = 0.8;
  insert_cell_reading(map, reading_at({2, 2}, {1}), options, nullptr);
  EXPECT_NEAR(*map.probability_at({2, 2}), 0.2, 1e-6);
  EXPECT_NEAR(*map.probability_at({3, 3}), 0.8, 1e-6);
}

}  // namespace
}  // namespace tessera
