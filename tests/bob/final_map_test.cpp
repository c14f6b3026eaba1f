#include "tessera/bob/final_map.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera::bob {
namespace {

// Section 4: the 11 x 14 grid takes "28 bytes ... for map representation": 11 bits per row padded
// to 2 bytes, 14 rows.
TEST(FinalMap, ElevenByFourteenGridTakesTwentyEightBytes) {
  EXPECT_EQ(FinalMap::bytes_per_row(11), 2u);
  EXPECT_EQ(FinalMap::bytes_needed(11, 14), 28u);
  std::vector<std::uint8_t> buf(28);
  FinalMap map;
  ASSERT_EQ(map.init(buf.data(), buf.size(), 11, 14), Status::kOk);
  EXPECT_EQ(map.memory_bytes(), 28u);
  EXPECT_EQ(map.init(buf.data(), 27, 11, 14), Status::kBufferTooSmall);
}

TEST(FinalMap, OccupiedAndUnsensedBecomeOneFreeAndVisitedBecomeZero) {
  std::vector<std::uint8_t> mbuf(PackedMap::bytes_needed(11, 2));
  PackedMap mapping;
  ASSERT_EQ(mapping.init(mbuf.data(), mbuf.size(), 11, 2), Status::kOk);
  for (int x = 0; x < 11; ++x) mapping.set_state({x, 0}, CellState::kFree);
  mapping.set_state({9, 0}, CellState::kOccupied);
  mapping.set_visited({0, 0}, Direction::kNorth);
  // Row 1 stays unsensed except one free cell.
  mapping.set_state({10, 1}, CellState::kFree);

  std::vector<std::uint8_t> fbuf(FinalMap::bytes_needed(11, 2), 0xAA);
  FinalMap final_map;
  ASSERT_EQ(final_map.init(fbuf.data(), fbuf.size(), 11, 2), Status::kOk);
  ASSERT_EQ(final_map.assign_from(mapping), Status::kOk);
  EXPECT_FALSE(final_map.occupied({0, 0}));
  EXPECT_TRUE(final_map.occupied({9, 0}));
  EXPECT_FALSE(final_map.occupied({10, 0}));
  EXPECT_TRUE(final_map.occupied({0, 1}));
  EXPECT_FALSE(final_map.occupied({10, 1}));
  // Bit x % 8 of byte y * 2 + x / 8; padding bits stay zero.
  EXPECT_EQ(fbuf[0], 0x00);
  EXPECT_EQ(fbuf[1], 0x02);  // x = 9 occupied
  EXPECT_EQ(fbuf[2], 0xFF);
  EXPECT_EQ(fbuf[3], 0x03);  // x = 8, 9 unsensed; x = 10 free

  FinalMap other;
  std::vector<std::uint8_t> obuf(FinalMap::bytes_needed(10, 2));
  ASSERT_EQ(other.init(obuf.data(), obuf.size(), 10, 2), Status::kOk);
  EXPECT_EQ(other.assign_from(mapping), Status::kBadSize);
}

}  // namespace
}  // namespace tessera::bob
