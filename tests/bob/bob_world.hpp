#pragma once
// Test helpers for bob/: worlds and explorer knowledge drawn as text, and a loop that runs the
// explorer against a world with an exact cell sensor. Host only (std::vector, std::string).

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "tessera/bob/direction.hpp"
#include "tessera/bob/explorer.hpp"

namespace tessera::bob::bobtest {

/// A grid drawn as text, top row first (the highest y), so it reads like a map: '#' solid,
/// anything else free. Other characters mark cells for the test ('R' robot, '?' unsensed, ...).
class TextGrid {
 public:
  explicit TextGrid(std::vector<std::string> rows_top_first) : rows_(std::move(rows_top_first)) {}

  [[nodiscard]] int width() const { return static_cast<int>(rows_.front().size()); }
  [[nodiscard]] int height() const { return static_cast<int>(rows_.size()); }
  [[nodiscard]] bool contains(GridCell c) const {
    return 0 <= c.x && c.x < width() && 0 <= c.y && c.y < height();
  }
  /// Precondition: contains(c).
  [[nodiscard]] char at(GridCell c) const {
    return rows_[static_cast<std::size_t>(height() - 1 - c.y)][static_cast<std::size_t>(c.x)];
  }
  /// Solid where drawn '#' and everywhere outside the grid.
  [[nodiscard]] bool solid(GridCell c) const { return !contains(c) || at(c) == '#'; }
  /// The first cell drawn as `mark`, scanning from the top row; {-1, -1} if none.
  [[nodiscard]] GridCell find(char mark) const {
    for (int y = height() - 1; y >= 0; --y) {
      for (int x = 0; x < width(); ++x) {
        if (at({x, y}) == mark) return {x, y};
      }
    }
    return {-1, -1};
  }
  /// Free cells 4-connected to `start`: the space the robot can reach.
  [[nodiscard]] std::vector<std::uint8_t> reachable_from(GridCell start) const {
    std::vector<std::uint8_t> seen(static_cast<std::size_t>(width() * height()), 0);
    std::vector<GridCell> stack{start};
    seen[index(start)] = 1;
    while (!stack.empty()) {
      const GridCell c = stack.back();
      stack.pop_back();
      for (const Direction d : kClockwiseFromNorth) {
        const GridCell n = step(c, d);
        if (!solid(n) && seen[index(n)] == 0) {
          seen[index(n)] = 1;
          stack.push_back(n);
        }
      }
    }
    return seen;
  }
  [[nodiscard]] std::size_t index(GridCell c) const {
    return static_cast<std::size_t>(c.y * width() + c.x);
  }

 private:
  std::vector<std::string> rows_;
};

/// Which cells the exact sensor reports after each move.
enum class SensorLayout {
  /// The four neighbours of the cell the robot stands in, at the start and after every move.
  kFourNeighbors,
  /// Section 3.2, Figure 3: after moving into a cell, the three neighbours of that cell ahead and
  /// to the sides (lateral sensors i, j and the "snowplow" beams k, l, m); at the start, at rest,
  /// the front and the two sides of the start cell. The cell behind the start stays unsensed.
  kSnowplow,
};

/// Reports exact readings of the cells `layout` covers with the robot in `at` facing `heading`.
inline void sense_exact(Explorer& explorer, const TextGrid& world, GridCell at, Direction heading,
                        SensorLayout layout) {
  const Direction dirs[4] = {heading, clockwise(heading), counter_clockwise(heading),
                             opposite(heading)};
  const int count = layout == SensorLayout::kFourNeighbors ? 4 : 3;
  for (int i = 0; i < count; ++i) {
    const GridCell c = step(at, dirs[i]);
    (void)explorer.sense(c, world.solid(c));  // kOutOfBounds past the grid's edge: ignored
  }
}

/// One exploration of `world` from the cell drawn 'R', facing `heading`.
struct ExplorationRun {
  Status start_status = Status::kOk;
  Status last_status = Status::kOk;
  StopReason stop_reason = StopReason::kNone;
  std::uint32_t moves = 0;
  std::uint32_t turns = 0;
  std::vector<GridCell> path;         // cells entered, in order
  bool hit_wall = false;              // a move into a solid cell (must never happen)
  std::vector<std::uint8_t> mapping;  // the packed 4-bit map at the end
  std::vector<std::uint8_t> final_map;  // the explorer's final-map buffer
  Explorer explorer;  // holds pointers into `mapping` and `final_map`: valid while this
                      // ExplorationRun lives, not copied
};

/// Runs the explorer to the end (or `max_moves`). The ExplorationRun owns every buffer.
inline void explore(const TextGrid& world, Direction heading, Backtrack backtrack,
                    SensorLayout layout, ExplorationRun& run, std::uint32_t max_moves = 100000) {
  const int w = world.width();
  const int h = world.height();
  run.mapping.assign(PackedMap::bytes_needed(w, h), 0);
  run.final_map.assign(FinalMap::bytes_needed(w, h), 0xFF);
  Explorer& ex = run.explorer;
  run.start_status = ex.init(ExplorerOptions{backtrack}, run.mapping.data(), run.mapping.size(),
                             run.final_map.data(), run.final_map.size(), w, h);
  if (run.start_status != Status::kOk) return;
  GridCell pos = world.find('R');
  sense_exact(ex, world, pos, heading, layout);
  run.start_status = ex.start(pos, heading);
  if (run.start_status != Status::kOk) return;
  Direction move = heading;
  while (run.moves < max_moves) {
    run.last_status = ex.next_move(move);
    if (run.last_status != Status::kOk) break;
    pos = step(pos, move);
    if (world.solid(pos)) run.hit_wall = true;
    run.path.push_back(pos);
    ++run.moves;
    sense_exact(ex, world, pos, move, layout);
  }
  run.stop_reason = ex.stop_reason();
  run.turns = ex.turns();
}

}  // namespace tessera::bob::bobtest
