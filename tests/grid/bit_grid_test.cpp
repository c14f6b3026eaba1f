#include "tessera/grid/bit_grid.hpp"

#include <gtest/gtest.h>

#include <array>
#include <vector>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

// BOBMapping 4: "if rows have 11 cells, 44 bits (5.5 bytes) are required to store the row during
// the mapping process, but six bytes are used. [...] a grid map of 11x14 cells has been used, so 84
// bytes have been used during the mapping process and 28 bytes have been used for map
// representation." So a row is 11 cells wide and there are 14 rows: 14 * 6 = 84 and 14 * 2 = 28.
TEST(BitGrid, BobMappingsElevenByFourteenGridTakes84BytesMappingAnd28Final) {
  static_assert(BitGrid::bytes_per_row(11, 4) == 6);
  static_assert(BitGrid::bytes_needed(11, 14, 4) == 84);
  static_assert(BitGrid::bytes_per_row(11, 1) == 2);
  static_assert(BitGrid::bytes_needed(11, 14, 1) == 28);
  // Rows of 14 cells (the other reading of "11 x 14") would not give the paper's figures.
  EXPECT_EQ(BitGrid::bytes_needed(14, 11, 4), 77u);
  EXPECT_EQ(BitGrid::bytes_needed(14, 11, 1), 22u);
  std::array<std::uint8_t, 84> buffer{};
  const BitGrid mapping(buffer, 11, 14, 4);
  EXPECT_EQ(mapping.memory_bytes(), 84u);
  EXPECT_EQ(mapping.max_value(), 15);
}

TEST(BitGrid, RowsStartOnWholeBytesAndCellsPackFromTheLowBit) {
  std::array<std::uint8_t, 84> buffer{};
  BitGrid grid(buffer, 11, 14, 4);
  grid.set({0, 0}, 0x3);
  grid.set({1, 0}, 0xA);
  grid.set({10, 0}, 0xF);  // the last cell of row 0: low nibble of byte 5, high nibble is padding
  grid.set({0, 1}, 0x5);   // row 1 starts at byte 6
  EXPECT_EQ(buffer[0], 0xA3);
  EXPECT_EQ(buffer[5], 0x0F);
  EXPECT_EQ(buffer[6], 0x05);
  EXPECT_EQ(grid.get({1, 0}), 0xA);
  EXPECT_EQ(grid.bytes().size(), 84u);
}

TEST(BitGrid, SetThenGetRoundTripsForEveryWidthFromOneToEightBits) {
  Rng rng(5);
  for (int bits = 1; bits <= 8; ++bits) {
    const int width = 13, height = 7;  // odd width: 3, 5, 6 and 7-bit cells straddle bytes
    std::vector<std::uint8_t> buffer(BitGrid::bytes_needed(width, height, bits));
    BitGrid grid(buffer, width, height, bits);
    grid.clear();
    std::vector<std::uint8_t> truth(static_cast<std::size_t>(width * height), 0);
    for (int k = 0; k < 2000; ++k) {
      const Cell c{rng.uniform_int(0, width - 1), rng.uniform_int(0, height - 1)};
      const auto value = static_cast<std::uint8_t>(rng.uniform_int(0, grid.max_value()));
      grid.set(c, value);
      truth[static_cast<std::size_t>(c.y * width + c.x)] = value;
    }
    for (int y = 0; y < height; ++y) {
      for (int x = 0; x < width; ++x) {
        ASSERT_EQ(grid.get({x, y}), truth[static_cast<std::size_t>(y * width + x)])
            << bits << " bits, cell (" << x << ", " << y << ")";
      }
    }
  }
}

TEST(BitGrid, NeverWritesPaddingBitsOrBytesBeyondTheGrid) {
  // 11 cells at 1 bit: byte 1 of each row holds 3 cells and 5 padding bits. A sentinel byte
  // follows the grid.
  std::array<std::uint8_t, 29> buffer{};
  buffer.fill(0xFF);
  BitGrid grid(std::span<std::uint8_t>(buffer).first(28), 11, 14, 1);
  grid.fill(0);
  for (int y = 0; y < 14; ++y) EXPECT_EQ(buffer[static_cast<std::size_t>(2 * y + 1)], 0xF8) << y;
  EXPECT_EQ(buffer[28], 0xFF);
  grid.clear();
  EXPECT_EQ(buffer[1], 0x00);
  EXPECT_EQ(buffer[28], 0xFF);
}

TEST(BitGrid, WorksWithoutHeapInAConstantExpression) {
  constexpr auto packed = [] {
    std::array<std::uint8_t, BitGrid::bytes_needed(5, 3, 3)> buffer{};
    BitGrid grid(buffer, 5, 3, 3);
    grid.set({2, 1}, 7);  // bits 6..8 of row 1: straddles two bytes
    grid.set({4, 2}, 5);
    return grid.get({2, 1}) * 10 + grid.get({4, 2});
  }();
  static_assert(packed == 75);
  EXPECT_EQ(packed, 75);
}

TEST(BitGrid, ReattachingABufferKeepsItsContents) {
  std::array<std::uint8_t, 28> buffer{};
  {
    BitGrid grid(buffer, 11, 14, 1);
    grid.set({7, 9}, 1);
  }
  const BitGrid again(buffer, 11, 14, 1);
  EXPECT_EQ(again.get({7, 9}), 1);
  EXPECT_EQ(again.get({6, 9}), 0);
}

}  // namespace
}  // namespace tessera
