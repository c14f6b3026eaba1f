#pragma once
// Limits and buffer checks shared by the bob/ sources. Private header.

#include <cstddef>
#include <cstdint>

#include "tessera/bob/status.hpp"

namespace tessera::bob::internal {

/// Most cells a grid may have (status.hpp, kBadSize). The map-aware search costs O(cells x
/// distance) per step, so the bound also keeps a step's worst case in hand.
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

/// The checks and the clearing that PackedMap::init and FinalMap::init share, for a layout whose
/// grid takes `bytes_needed(width, height)` bytes: kBadSize unless valid_grid_size(),
/// kBufferTooSmall when `buffer` is null or shorter than the grid; otherwise zeroes the grid's
/// bytes and returns kOk.
[[nodiscard]] inline Status clear_grid_buffer(std::uint8_t* buffer, std::size_t buffer_bytes,
                                              int width_cells, int height_cells,
                                              std::size_t (*bytes_needed)(int, int)) {
  if (!valid_grid_size(width_cells, height_cells)) return Status::kBadSize;
  const std::size_t bytes = bytes_needed(width_cells, height_cells);
  if (buffer == nullptr || buffer_bytes < bytes) return Status::kBufferTooSmall;
  zero_bytes(buffer, bytes);
  return Status::kOk;
}

}  // namespace tessera::bob::internal
