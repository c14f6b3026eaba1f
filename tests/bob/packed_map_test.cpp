#include "tessera/bob/packed_map.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera::bob {
namespace {

// Section 4: "if rows have 11 cells, 44 bits (5.5 bytes) are required ... but six bytes are used.
// In the experiments, a grid map of 11x14 cells has been used, so 84 bytes have been used during
// the mapping process". Rows are 11 cells wide; there are 14 rows.
TEST(PackedMap, ElevenByFourteenGridTakesEightyFourBytesWithRowsPaddedToWholeBytes) {
  EXPECT_EQ(PackedMap::bytes_per_row(11), 6u);
  EXPECT_EQ(PackedMap::bytes_needed(11, 14), 84u);
  std::vector<std::uint8_t> buf(84);
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 11, 14), Status::kOk);
  EXPECT_EQ(map.memory_bytes(), 84u);
}

TEST(PackedMap, InitRejectsBadSizesAndShortBuffers) {
  std::vector<std::uint8_t> buf(84);
  PackedMap map;
  EXPECT_EQ(map.init(buf.data(), buf.size(), 0, 14), Status::kBadSize);
  EXPECT_EQ(map.init(buf.data(), buf.size(), 11, -1), Status::kBadSize);
  EXPECT_EQ(map.init(buf.data(), 83, 11, 14), Status::kBufferTooSmall);
  EXPECT_EQ(map.init(nullptr, 84, 11, 14), Status::kBufferTooSmall);
  std::vector<std::uint8_t> big(PackedMap::bytes_needed(200, 200));
  EXPECT_EQ(map.init(big.data(), big.size(), 200, 200), Status::kBadSize);  // > 16384 cells
}

TEST(PackedMap, InitClearsEveryCellToUnsensed) {
  std::vector<std::uint8_t> buf(84, 0xFF);
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 11, 14), Status::kOk);
  for (int y = 0; y < 14; ++y) {
    for (int x = 0; x < 11; ++x) EXPECT_EQ(map.state({x, y}), CellState::kUnsensed);
  }
}

TEST(PackedMap, EachCellKeepsItsOwnStateAndDirectionWithoutTouchingItsNeighbours) {
  std::vector<std::uint8_t> buf(PackedMap::bytes_needed(5, 3));
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 5, 3), Status::kOk);
  map.set_state({0, 0}, CellState::kOccupied);
  map.set_state({1, 0}, CellState::kFree);
  map.set_visited({2, 0}, Direction::kWest);
  map.set_visited({4, 2}, Direction::kSouth);
  map.set_visited({3, 2}, Direction::kEast);
  EXPECT_EQ(map.state({0, 0}), CellState::kOccupied);
  EXPECT_EQ(map.state({1, 0}), CellState::kFree);
  EXPECT_EQ(map.state({2, 0}), CellState::kVisited);
  EXPECT_EQ(map.came_from({2, 0}), Direction::kWest);
  EXPECT_EQ(map.state({3, 0}), CellState::kUnsensed);
  EXPECT_EQ(map.came_from({4, 2}), Direction::kSouth);
  EXPECT_EQ(map.came_from({3, 2}), Direction::kEast);
  EXPECT_EQ(map.state({4, 1}), CellState::kUnsensed);
}

// The map-aware search keeps its marks in the two direction bits (decision 0004).
TEST(PackedMap, DirectionBitsAreWrittenWithoutTouchingTheState) {
  std::vector<std::uint8_t> buf(PackedMap::bytes_needed(3, 1));
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 3, 1), Status::kOk);
  map.set_state({0, 0}, CellState::kFree);
  map.set_visited({1, 0}, Direction::kSouth);
  map.set_direction_bits({0, 0}, 3);
  map.set_direction_bits({1, 0}, 1);
  EXPECT_EQ(map.state({0, 0}), CellState::kFree);
  EXPECT_EQ(map.direction_bits({0, 0}), 3u);
  EXPECT_EQ(map.state({1, 0}), CellState::kVisited);
  EXPECT_EQ(map.came_from({1, 0}), Direction::kEast);
  EXPECT_EQ(map.state({2, 0}), CellState::kUnsensed);
  EXPECT_EQ(map.direction_bits({2, 0}), 0u);
  map.set_direction_bits({0, 0}, 0);
  EXPECT_EQ(buf[0], 0x52);  // (1, 0): 0b0101, visited reached East; (0, 0): 0b0010, free
}

// The layout of section 3.4 with "visited" in the code the paper leaves unused (not sensed,
// occupancy bit set): cell (x, y) is nibble x % 2 of byte y * 3 + x / 2 for a 5-wide grid.
TEST(PackedMap, NibblesFollowTheDocumentedBitLayout) {
  std::vector<std::uint8_t> buf(PackedMap::bytes_needed(5, 2));
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 5, 2), Status::kOk);
  map.set_state({0, 0}, CellState::kFree);      // sensed bit only: 0b0010
  map.set_state({1, 0}, CellState::kOccupied);  // sensed + occupied: 0b0011
  map.set_visited({4, 1}, Direction::kWest);    // direction 3 << 2 | occupancy bit: 0b1101
  EXPECT_EQ(buf[0], 0x32);
  EXPECT_EQ(buf[5], 0x0D);  // row 1 starts at byte 3; x = 4 is the low nibble of byte 3 + 2
  EXPECT_EQ(buf[2], 0x00);  // the padding nibble of row 0 is never written
}

TEST(PackedMap, UnsensedNeighboursIgnoreCellsOutsideTheGrid) {
  std::vector<std::uint8_t> buf(PackedMap::bytes_needed(2, 1));
  PackedMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 2, 1), Status::kOk);
  EXPECT_TRUE(map.has_unsensed_neighbor({0, 0}));
  map.set_state({1, 0}, CellState::kFree);
  EXPECT_FALSE(map.has_unsensed_neighbor({0, 0}));
  EXPECT_FALSE(map.is_sensed({-1, 0}));
  EXPECT_FALSE(map.is_known_free({2, 0}));
  EXPECT_TRUE(map.is_known_free({1, 0}));
}

}  // namespace
}  // namespace tessera::bob
