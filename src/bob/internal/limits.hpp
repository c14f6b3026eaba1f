#pragma once
// Limits shared by the bob/ sources. Private header.

#include <cstddef>
#include <cstdint>

namespace tessera::bob::internal {

/// Most cells a grid may have: the breadth-first queue packs a cell index in 14 bits.
inline constexpr int kMaxCells = 1 << 14;

/// True when a width x height grid has at least one cell and at most kMaxCells.
[[nodiscard]] constexpr bool valid_grid_size(int width_cells, int height_cells) {
  return width_cells >= 1 && height_cells >= 1 && width_cells <= kMaxCells &&
         height_cells <= kMaxCells / width_cells;
}

/// Zeroes `bytes` bytes (the freestanding core has no memset).
inline void zero_bytes(std::uint8_t* buffer, std::size_t bytes) {
  for (std::size_t i = 0; i < bytes; ++i) buffer[i] = 0;
}

}  // namespace tessera::bob::internal
