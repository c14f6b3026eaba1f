#pragma once
// Bit-packed grid in a caller-supplied fixed buffer: BOBMapping's map layout (BOBMapping 3.4 and 4:
// 4 bits per cell while mapping -- occupancy, sensed, two bits of backtracking direction -- and
// 1 bit per cell in the final map; "each row of the grid requires an integer number of bytes").
// No heap, no exceptions, no I/O: the bob/ microcontroller build uses it freestanding.

#include <cstddef>
#include <cstdint>
#include <span>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"

namespace tessera {

/// A width x height grid of `bits_per_cell`-bit unsigned values (1..8) over a buffer the caller
/// owns.
///
/// Layout: same grid convention as GridGeometry (cell (0,0) lower-left, x column, y row,
/// row-major). Row y starts at byte y * bytes_per_row(); rows are padded to whole bytes, so a row
/// of 11 cells at 4 bits takes 6 bytes, not 5.5 (BOBMapping 4: an 11 x 14 grid is 84 bytes while
/// mapping and 28 bytes as the final 1-bit map). Within a row, cell x occupies bits [x*b, x*b + b)
/// counted from the least significant bit of the row's first byte; with b in {3, 5, 6, 7} a cell
/// may straddle two bytes. Padding bits are never read or written by get/set.
class BitGrid {
 public:
  /// Bytes one row takes: ceil(width * bits / 8).
  [[nodiscard]] static constexpr std::size_t bytes_per_row(int width_cells, int bits_per_cell) {
    return (static_cast<std::size_t>(width_cells) * static_cast<std::size_t>(bits_per_cell) + 7) /
           8;
  }
  /// Bytes the whole grid takes, rows padded to whole bytes. Use it to size the buffer.
  [[nodiscard]] static constexpr std::size_t bytes_needed(int width_cells, int height_cells,
                                                          int bits_per_cell) {
    return bytes_per_row(width_cells, bits_per_cell) * static_cast<std::size_t>(height_cells);
  }

  /// An empty 0 x 0 grid.
  constexpr BitGrid() = default;
  /// Views `buffer` as the grid, leaving its bytes as they are (so a map kept in flash or RAM can
  /// be re-attached); call clear() for a fresh grid. Preconditions: width, height >= 0, 1 <=
  /// bits_per_cell <= 8, buffer.size() >= bytes_needed(width, height, bits_per_cell).
  constexpr BitGrid(std::span<std::uint8_t> buffer, int width_cells, int height_cells,
                    int bits_per_cell)
      : buffer_(buffer),
        width_(width_cells),
        height_(height_cells),
        bits_(bits_per_cell),
        row_bytes_(bytes_per_row(width_cells, bits_per_cell)),
        mask_(static_cast<unsigned>((1u << bits_per_cell) - 1u)) {
    TESSERA_ASSERT(width_cells >= 0 && height_cells >= 0);
    TESSERA_ASSERT(bits_per_cell >= 1 && bits_per_cell <= 8);
    TESSERA_ASSERT(buffer.size() >= bytes_needed(width_cells, height_cells, bits_per_cell));
  }

  [[nodiscard]] constexpr int width() const { return width_; }
  [[nodiscard]] constexpr int height() const { return height_; }
  [[nodiscard]] constexpr int bits_per_cell() const { return bits_; }
  /// Largest storable value, 2^bits - 1.
  [[nodiscard]] constexpr std::uint8_t max_value() const {
    return static_cast<std::uint8_t>(mask_);
  }
  [[nodiscard]] constexpr std::size_t bytes_per_row() const { return row_bytes_; }
  /// Bytes of the buffer the grid uses (bytes_needed of its size).
  [[nodiscard]] constexpr std::size_t memory_bytes() const {
    return row_bytes_ * static_cast<std::size_t>(height_);
  }
  /// The used part of the buffer, e.g. to send the packed map.
  [[nodiscard]] constexpr std::span<const std::uint8_t> bytes() const {
    return buffer_.first(memory_bytes());
  }
  [[nodiscard]] constexpr bool contains(Cell c) const {
    return 0 <= c.x && c.x < width_ && 0 <= c.y && c.y < height_;
  }

  /// Value of cell c. Precondition: contains(c). O(1).
  [[nodiscard]] constexpr std::uint8_t get(Cell c) const {
    TESSERA_ASSERT(contains(c));
    const std::size_t bit = static_cast<std::size_t>(c.x) * static_cast<std::size_t>(bits_);
    const std::size_t byte = static_cast<std::size_t>(c.y) * row_bytes_ + bit / 8;
    const unsigned shift = static_cast<unsigned>(bit % 8);
    unsigned word = buffer_[byte];
    if (shift + static_cast<unsigned>(bits_) > 8u)
      word |= static_cast<unsigned>(buffer_[byte + 1]) << 8;
    return static_cast<std::uint8_t>((word >> shift) & mask_);
  }

  /// Sets cell c to value. Preconditions: contains(c), value <= max_value(). O(1).
  constexpr void set(Cell c, std::uint8_t value) {
    TESSERA_ASSERT(contains(c));
    TESSERA_ASSERT(value <= mask_);
    const std::size_t bit = static_cast<std::size_t>(c.x) * static_cast<std::size_t>(bits_);
    const std::size_t byte = static_cast<std::size_t>(c.y) * row_bytes_ + bit / 8;
    const unsigned shift = static_cast<unsigned>(bit % 8);
    const unsigned clear = ~(mask_ << shift);
    const unsigned put = static_cast<unsigned>(value) << shift;
    buffer_[byte] = static_cast<std::uint8_t>((buffer_[byte] & clear) | put);
    if (shift + static_cast<unsigned>(bits_) > 8u) {
      buffer_[byte + 1] =
          static_cast<std::uint8_t>((buffer_[byte + 1] & (clear >> 8)) | (put >> 8));
    }
  }

  /// Sets every cell to value; padding bits keep theirs. Precondition: value <= max_value().
  constexpr void fill(std::uint8_t value) {
    TESSERA_ASSERT(value <= mask_);
    for (int y = 0; y < height_; ++y) {
      for (int x = 0; x < width_; ++x) set({x, y}, value);
    }
  }
  /// Sets every used byte, padding included, to zero.
  constexpr void clear() {
    for (std::size_t i = 0; i < memory_bytes(); ++i) buffer_[i] = 0;
  }

 private:
  std::span<std::uint8_t> buffer_{};
  int width_ = 0;
  int height_ = 0;
  int bits_ = 1;
  std::size_t row_bytes_ = 0;
  unsigned mask_ = 1;
};

}  // namespace tessera
