#pragma once
// The BOBMapping final map (section 3.4: "the final map will only record the occupancy information
// of each cell, requiring just one bit per cell"), each row padded to whole bytes (section 4): an
// 11 x 14 grid takes 2 * 14 = 28 bytes. Freestanding: no heap, no exceptions, no standard library
// beyond <cstdint>/<cstddef>.

#include <cstddef>
#include <cstdint>

#include "tessera/bob/direction.hpp"
#include "tessera/bob/packed_map.hpp"
#include "tessera/bob/status.hpp"

namespace tessera::bob {

/// A 1-bit-per-cell map over a caller buffer: bit 1 = not known to be wholly free (sensed
/// occupied, never sensed, or -- in an Explorer's final map -- a cell the robot stood in with an
/// obstacle detected inside it, decision 0008), 0 = known empty. Cell (x, y) is bit x % 8 (least
/// significant first) of byte y * bytes_per_row() + x / 8; padding bits are zero. Same grid
/// convention as PackedMap.
class FinalMap {
 public:
  /// ceil(width / 8).
  [[nodiscard]] static constexpr std::size_t bytes_per_row(int width_cells) {
    return (static_cast<std::size_t>(width_cells) + 7u) / 8u;
  }
  /// 11 x 14 -> 28.
  [[nodiscard]] static constexpr std::size_t bytes_needed(int width_cells, int height_cells) {
    return bytes_per_row(width_cells) * static_cast<std::size_t>(height_cells);
  }

  constexpr FinalMap() = default;

  /// Views `buffer` as a width x height map with every cell 0. kBadSize, kBufferTooSmall as
  /// PackedMap::init.
  [[nodiscard]] Status init(std::uint8_t* buffer, std::size_t buffer_bytes, int width_cells,
                            int height_cells);
  /// Fills this map from the 4-bit mapping layout alone: occupied or unsensed -> 1, free or
  /// visited -> 0. The layout has no room for an obstacle inside a visited cell, so this is not
  /// an Explorer's final map (Explorer::final_map(), which keeps those). kBadSize when the sizes
  /// differ.
  [[nodiscard]] Status assign_from(const PackedMap& mapping);

  [[nodiscard]] constexpr int width() const { return width_; }
  [[nodiscard]] constexpr int height() const { return height_; }
  [[nodiscard]] constexpr std::size_t memory_bytes() const { return bytes_needed(width_, height_); }
  [[nodiscard]] constexpr const std::uint8_t* data() const { return buffer_; }
  [[nodiscard]] constexpr bool contains(GridCell c) const {
    return 0 <= c.x && c.x < width_ && 0 <= c.y && c.y < height_;
  }
  /// Precondition: contains(c).
  [[nodiscard]] bool occupied(GridCell c) const;
  /// Precondition: contains(c).
  void set_occupied(GridCell c, bool occupied);

 private:
  std::uint8_t* buffer_ = nullptr;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace tessera::bob
