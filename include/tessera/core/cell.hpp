#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

namespace tessera {

/// Integer grid index: x is the column, y the row; (0,0) is the lower-left cell
/// (docs/conventions.md).
struct Cell {
  int x = 0;
  int y = 0;

  [[nodiscard]] constexpr Cell operator+(Cell o) const { return {x + o.x, y + o.y}; }
  [[nodiscard]] constexpr Cell operator-(Cell o) const { return {x - o.x, y - o.y}; }
  [[nodiscard]] constexpr bool operator==(const Cell&) const = default;
};

/// The 4-neighbourhood (the lecture's "adjacent": left, right, up, down), in the clockwise
/// order North, East, South, West that BOBMapping's explorer also uses.
inline constexpr std::array<Cell, 4> kNeighbors4{{{0, 1}, {1, 0}, {0, -1}, {-1, 0}}};

/// The 8-neighbourhood, clockwise from North.
inline constexpr std::array<Cell, 8> kNeighbors8{
    {{0, 1}, {1, 1}, {1, 0}, {1, -1}, {0, -1}, {-1, -1}, {-1, 0}, {-1, 1}}};

/// Manhattan distance in cells.
[[nodiscard]] constexpr int manhattan(Cell a, Cell b) {
  return (a.x > b.x ? a.x - b.x : b.x - a.x) + (a.y > b.y ? a.y - b.y : b.y - a.y);
}

/// "(x, y)", for messages.
[[nodiscard]] inline std::string to_string(Cell c) {
  return "(" + std::to_string(c.x) + ", " + std::to_string(c.y) + ")";
}

struct CellHash {
  [[nodiscard]] std::size_t operator()(Cell c) const noexcept {
    return std::hash<std::uint64_t>{}(
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.x)) << 32) |
        static_cast<std::uint32_t>(c.y));
  }
};

}  // namespace tessera
