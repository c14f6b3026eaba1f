#pragma once
// The BOBMapping map while mapping (section 3.4 and section 4): 4 bits per cell -- occupancy,
// sensed, and two bits for the direction the robot took to reach the cell -- over a buffer the
// caller owns, each row padded to whole bytes: an 11 x 14 grid takes 6 * 14 = 84 bytes.
// Freestanding: no heap, no exceptions, no standard library beyond <cstdint>/<cstddef>.

#include <cstddef>
#include <cstdint>

#include "tessera/bob/direction.hpp"
#include "tessera/bob/status.hpp"

namespace tessera::bob {

/// What the robot knows about one cell.
enum class CellState : std::uint8_t {
  kUnsensed,  // no reading yet
  kFree,      // sensed empty, never stood in
  kOccupied,  // sensed occupied (any detection inside the cell, section 3.2)
  kVisited,   // the robot has stood in it: empty for good (section 3.4 re-sensing rule)
};

/// The 4-bit mapping layout. Bit 0 is "occupied", bit 1 "sensed", bits 2-3 the Direction the robot
/// moved in to reach the cell (section 3.4: "the direction ... that the robot took to reach that
/// cell"), so backtracking moves the opposite way.
///
/// Visited in 4 bits: the paper stores occupied, sensed and a direction, but the re-sensing rule
/// also needs "the robot has stood here", and all four direction codes are valid, so a set
/// direction cannot mean visited. The paper ignores the occupancy bit of an unsensed cell, which
/// leaves the code (occupied = 1, sensed = 0) unused; that code means visited:
///   sensed occupied  state
///      0      0      kUnsensed   (direction ignored)
///      1      0      kFree       (direction ignored)
///      1      1      kOccupied   (direction ignored)
///      0      1      kVisited    (direction = the move that reached it; at the start cell it is
///                                 the start heading and is never used: backtracking ends there)
/// A visited cell counts as sensed and empty here (is_sensed, is_known_free, FinalMap::assign_from).
/// An obstacle detected inside a visited cell has no bit in this layout: the Explorer records it
/// in its final map (explorer.hpp, decision 0008).
///
/// Only the paper's trail backtracking (Backtrack::kTrail) reads the direction of a visited cell.
/// The map-aware explorer (Backtrack::kShortestKnownPath) stores none and uses the two bits of
/// every known-free cell as the marks of its in-place path search instead (explorer.hpp,
/// decision 0004); they are zero between its calls. direction_bits() gives raw access to them.
///
/// Layout: cell (x, y) is the nibble x % 2 (low nibble for even x) of byte y * bytes_per_row() +
/// x / 2. Cell (0,0) is the lower-left cell, x the column, y the row (docs/conventions.md).
class PackedMap {
 public:
  static constexpr int kBitsPerCell = 4;

  /// Bytes one row takes: ceil(width / 2).
  [[nodiscard]] static constexpr std::size_t bytes_per_row(int width_cells) {
    return (static_cast<std::size_t>(width_cells) + 1u) / 2u;
  }
  /// Bytes the whole grid takes; size the buffer with this. 11 x 14 -> 84.
  [[nodiscard]] static constexpr std::size_t bytes_needed(int width_cells, int height_cells) {
    return bytes_per_row(width_cells) * static_cast<std::size_t>(height_cells);
  }

  /// An unusable 0 x 0 map until init().
  constexpr PackedMap() = default;

  /// Views `buffer` (at least bytes_needed(width, height) bytes) as a width x height map with
  /// every cell unsensed. kBadSize for width or height < 1 or above 16384 cells in all;
  /// kBufferTooSmall otherwise if the buffer is short. O(bytes).
  [[nodiscard]] Status init(std::uint8_t* buffer, std::size_t buffer_bytes, int width_cells,
                            int height_cells);

  [[nodiscard]] constexpr int width() const { return width_; }
  [[nodiscard]] constexpr int height() const { return height_; }
  [[nodiscard]] constexpr int cell_count() const { return width_ * height_; }
  /// Bytes of the buffer the map uses.
  [[nodiscard]] constexpr std::size_t memory_bytes() const { return bytes_needed(width_, height_); }
  [[nodiscard]] constexpr const std::uint8_t* data() const { return buffer_; }

  [[nodiscard]] constexpr bool contains(GridCell c) const {
    return 0 <= c.x && c.x < width_ && 0 <= c.y && c.y < height_;
  }
  /// Row-major index y * width + x. Precondition: contains(c).
  [[nodiscard]] constexpr int index_of(GridCell c) const { return c.y * width_ + c.x; }
  [[nodiscard]] constexpr GridCell cell_of(int index) const {
    return {index % width_, index / width_};
  }

  /// State of c. Precondition: contains(c).
  [[nodiscard]] CellState state(GridCell c) const;
  /// The move that reached c. Meaningful only for kVisited cells of a kTrail explorer.
  /// Precondition: contains(c).
  [[nodiscard]] Direction came_from(GridCell c) const;
  /// The two direction bits of c as a number 0-3, whatever the state (came_from() of a visited
  /// cell). Precondition: contains(c).
  [[nodiscard]] unsigned direction_bits(GridCell c) const;
  /// Writes the two direction bits of c (bits 0-1 of `bits`), keeping the state.
  /// Precondition: contains(c).
  void set_direction_bits(GridCell c, unsigned bits);

  /// Precondition: contains(c). Writes the state, keeping the direction bits.
  void set_state(GridCell c, CellState s);
  /// Marks c visited, reached by moving `reached_by`. Precondition: contains(c).
  void set_visited(GridCell c, Direction reached_by);

  /// Sensed or visited. Cells outside the grid are neither sensed nor unsensed: false.
  [[nodiscard]] bool is_sensed(GridCell c) const {
    return contains(c) && state(c) != CellState::kUnsensed;
  }
  /// Inside the grid and sensed free or visited: a cell the robot may drive into.
  [[nodiscard]] bool is_known_free(GridCell c) const {
    if (!contains(c)) return false;
    const CellState s = state(c);
    return s == CellState::kFree || s == CellState::kVisited;
  }
  /// True when an orthogonal neighbour of c inside the grid is still unsensed ("uncharted
  /// neighbours", section 3.1). Cells outside the grid do not count. O(1).
  [[nodiscard]] bool has_unsensed_neighbor(GridCell c) const;

 private:
  [[nodiscard]] std::uint8_t nibble(GridCell c) const;
  void set_nibble(GridCell c, std::uint8_t v);

  std::uint8_t* buffer_ = nullptr;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace tessera::bob
