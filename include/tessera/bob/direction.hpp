#pragma once
// The four moves of the BOBMapping robot (section 3.1: orthogonal neighbours only, 90-degree turns
// and one-cell linear moves), in the clockwise priority order of BOBMapping Code 2: North first.
// Grid convention as the rest of tessera: x is the column, y the row, (0,0) the lower-left cell,
// North is +y. (The paper's matrix (i, j - 1) "north" is the same cell drawn with rows downwards.)
// Freestanding: no standard library beyond <cstdint>.

#include <cstdint>

namespace tessera::bob {

/// The numeric values are the 2-bit code stored per cell in the packed map (section 3.4).
enum class Direction : std::uint8_t { kNorth = 0, kEast = 1, kSouth = 2, kWest = 3 };

/// A cell of the robot's grid. Not tessera::Cell: core/cell.hpp needs <array>/<functional>, which
/// a freestanding build does not have. Same convention (x column, y row, (0,0) lower-left).
struct GridCell {
  int x = 0;
  int y = 0;
  [[nodiscard]] constexpr bool operator==(const GridCell&) const = default;
};

/// Directions in the order BOBMapping Code 2 tries them: clockwise from North.
inline constexpr Direction kClockwiseFromNorth[4] = {Direction::kNorth, Direction::kEast,
                                                     Direction::kSouth, Direction::kWest};

/// The neighbour of c one cell towards d.
[[nodiscard]] constexpr GridCell step(GridCell c, Direction d) {
  switch (d) {
    case Direction::kNorth:
      return {c.x, c.y + 1};
    case Direction::kEast:
      return {c.x + 1, c.y};
    case Direction::kSouth:
      return {c.x, c.y - 1};
    case Direction::kWest:
      return {c.x - 1, c.y};
  }
  return c;
}

[[nodiscard]] constexpr Direction opposite(Direction d) {
  return static_cast<Direction>((static_cast<unsigned>(d) + 2u) & 3u);
}
/// 90 degrees clockwise (North -> East).
[[nodiscard]] constexpr Direction clockwise(Direction d) {
  return static_cast<Direction>((static_cast<unsigned>(d) + 1u) & 3u);
}
/// 90 degrees counter-clockwise (North -> West).
[[nodiscard]] constexpr Direction counter_clockwise(Direction d) {
  return static_cast<Direction>((static_cast<unsigned>(d) + 3u) & 3u);
}
/// Quarter turns (0, 1 or 2) to turn in place from heading `from` to heading `to`.
[[nodiscard]] constexpr int quarter_turns(Direction from, Direction to) {
  const unsigned diff = (static_cast<unsigned>(to) - static_cast<unsigned>(from)) & 3u;
  return diff == 3u ? 1 : static_cast<int>(diff);
}

}  // namespace tessera::bob
