#pragma once
// Limits shared by the bob/ sources. Private header.

namespace tessera::bob::internal {

/// Most cells a grid may have: the breadth-first queue packs a cell index in 14 bits.
inline constexpr int kMaxCells = 1 << 14;

}  // namespace tessera::bob::internal
