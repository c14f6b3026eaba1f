#include "tessera/core/cell.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <unordered_set>

namespace tessera {
namespace {

TEST(Cell, AddsSubtractsAndCompares) {
  EXPECT_EQ((Cell{2, -3} + Cell{-5, 7}), (Cell{-3, 4}));
  EXPECT_EQ((Cell{2, -3} - Cell{-5, 7}), (Cell{7, -10}));
  EXPECT_NE((Cell{1, 2}), (Cell{2, 1}));
  EXPECT_EQ(Cell{}, (Cell{0, 0}));
}

TEST(Cell, FourNeighboursAreNorthEastSouthWest) {
  // BOBMapping's order, y up (docs/conventions.md).
  ASSERT_EQ(kNeighbors4.size(), 4u);
  EXPECT_EQ(kNeighbors4[0], (Cell{0, 1}));
  EXPECT_EQ(kNeighbors4[1], (Cell{1, 0}));
  EXPECT_EQ(kNeighbors4[2], (Cell{0, -1}));
  EXPECT_EQ(kNeighbors4[3], (Cell{-1, 0}));
}

TEST(Cell, EightNeighboursGoClockwiseFromNorth) {
  ASSERT_EQ(kNeighbors8.size(), 8u);
  EXPECT_EQ(kNeighbors8[0], (Cell{0, 1}));
  for (std::size_t i = 0; i < kNeighbors8.size(); ++i) {
    const Cell a = kNeighbors8[i];
    const Cell b = kNeighbors8[(i + 1) % kNeighbors8.size()];
    // Clockwise with y up: the next offset is to the right of this one (cross product < 0).
    EXPECT_LT(a.x * b.y - a.y * b.x, 0) << "at " << i;
    // Every offset touches the cell: Chebyshev distance 1.
    EXPECT_EQ(std::max(std::abs(a.x), std::abs(a.y)), 1) << "at " << i;
  }
  // The four neighbours sit at the even positions, in the same order.
  for (std::size_t i = 0; i < kNeighbors4.size(); ++i) EXPECT_EQ(kNeighbors8[2 * i], kNeighbors4[i]);
}

TEST(Cell, ManhattanDistance) {
  EXPECT_EQ(manhattan({1, 2}, {4, -2}), 7);
  EXPECT_EQ(manhattan({4, -2}, {1, 2}), 7);
  EXPECT_EQ(manhattan({-3, -3}, {-3, -3}), 0);
  EXPECT_EQ(manhattan({0, 0}, {-5, 0}), 5);
  static_assert(manhattan({0, 0}, {2, 3}) == 5);
}

TEST(Cell, ToStringForMessages) {
  EXPECT_EQ(to_string(Cell{3, -4}), "(3, -4)");
  EXPECT_EQ(to_string(Cell{}), "(0, 0)");
}

TEST(Cell, HashSeparatesNearbyCellsIncludingNegatives) {
  // x and y are packed into one 64-bit key, so no two cells of a window share a hash; a hash that
  // mixed x and y (x ^ y, x + y) or dropped the sign would collide here.
  const CellHash hash;
  std::unordered_set<std::size_t> hashes;
  int cells = 0;
  for (int y = -20; y <= 20; ++y) {
    for (int x = -20; x <= 20; ++x) {
      hashes.insert(hash(Cell{x, y}));
      ++cells;
    }
  }
  EXPECT_EQ(hashes.size(), static_cast<std::size_t>(cells));
  EXPECT_EQ(hash(Cell{5, -7}), hash(Cell{5, -7}));
}

}  // namespace
}  // namespace tessera
