#include "tessera/bob/explorer.hpp"

namespace tessera::bob {
namespace {

// The marks of the in-place search (decision 0004), in the direction bits of known-free cells:
// 0 = not reached, otherwise 1 + (distance to the nearest target) mod 3. Between searches every
// direction bit of a kShortestKnownPath map is 0, and during one only known-free cells are marked.
constexpr unsigned mark_of(unsigned distance) { return 1u + distance % 3u; }

// The first neighbour of c, in N, E, S, W order, that carries `mark`, into `dir`; false if none.
bool find_marked_neighbor(const PackedMap& map, GridCell c, unsigned mark, Direction& dir) {
  for (const Direction d : kClockwiseFromNorth) {
    const GridCell n = step(c, d);
    if (map.contains(n) && map.direction_bits(n) == mark) {
      dir = d;
      return true;
    }
  }
  return false;
}

// Level `distance` + 1 of the wavefront: marks every unmarked known-free cell next to a cell marked
// mark_of(distance). False when there was none. O(cells).
bool grow_wavefront(PackedMap& map, unsigned distance) {
  bool grew = false;
  Direction unused = Direction::kNorth;
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      const GridCell c{x, y};
      if (map.is_known_free(c) && map.direction_bits(c) == 0 &&
          find_marked_neighbor(map, c, mark_of(distance), unused)) {
        map.set_direction_bits(c, mark_of(distance + 1));
        grew = true;
      }
    }
  }
  return grew;
}

void clear_marks(PackedMap& map) {
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      if (map.is_known_free({x, y})) map.set_direction_bits({x, y}, 0);
    }
  }
}

}  // namespace

Status Explorer::init(const ExplorerOptions& options, std::uint8_t* map_buffer,
                      std::size_t map_buffer_bytes, std::uint8_t* final_map_buffer,
                      std::size_t final_map_buffer_bytes, int width_cells, int height_cells) {
  *this = Explorer{};
  Status s = map_.init(map_buffer, map_buffer_bytes, width_cells, height_cells);
  if (s == Status::kOk) {
    s = final_map_.init(final_map_buffer, final_map_buffer_bytes, width_cells, height_cells);
  }
  if (s != Status::kOk) {
    map_ = PackedMap{};
    return s;
  }
  (void)final_map_.assign_from(map_);  // every cell unsensed: 1
  options_ = options;
  unsensed_ = map_.cell_count();
  initialised_ = true;
  return Status::kOk;
}

void Explorer::set_sensed(GridCell c, CellState s) {
  map_.set_state(c, s);
  final_map_.set_occupied(c, s != CellState::kFree);
}

Status Explorer::sense(GridCell c, bool occupied) {
  if (!initialised_) return Status::kNotStarted;
  if (!map_.contains(c)) return Status::kOutOfBounds;
  const CellState reading = occupied ? CellState::kOccupied : CellState::kFree;
  if (!options_.resense && map_.state(c) != CellState::kUnsensed) {
    ++ignored_;  // re-sensing off: the first reading stays
    return Status::kOk;
  }
  switch (map_.state(c)) {
    case CellState::kUnsensed:
      --unsensed_;
      set_sensed(c, reading);
      break;
    case CellState::kFree:  // section 3.4: a later reading changes a sensed cell
    case CellState::kOccupied:
      if (map_.state(c) != reading) {
        set_sensed(c, reading);
        ++resensed_;
      }
      break;
    case CellState::kVisited:
      // Section 3.4: a cell the robot stood in never becomes occupied, so the explorer may still
      // drive through it; the obstacle inside it goes into the final map (decision 0008).
      if (occupied) {
        ++discarded_;
        final_map_.set_occupied(c, true);
      }
      break;
  }
  return Status::kOk;
}

Status Explorer::report_target(GridCell c, bool occupied) {
  if (!initialised_) return Status::kNotStarted;
  if (!map_.contains(c)) return Status::kOutOfBounds;
  if (occupied && map_.state(c) == CellState::kVisited) return Status::kOk;
  return sense(c, occupied);
}

Status Explorer::report_detection(GridCell c) {
  if (!initialised_) return Status::kNotStarted;
  if (!map_.contains(c)) return Status::kOutOfBounds;
  if (map_.state(c) == CellState::kUnsensed) return Status::kOk;
  return sense(c, true);
}

Status Explorer::start(GridCell cell, Direction heading) {
  if (!initialised_) return Status::kNotStarted;
  if (started_) return Status::kAlreadyStarted;
  if (!map_.contains(cell)) return Status::kOutOfBounds;
  // Section 3.4: "the sensor structure requires the robot to be initially positioned in a cell
  // whose frontal neighbor is unoccupied".
  const GridCell front = step(cell, heading);
  if (!map_.contains(front) || map_.state(front) == CellState::kOccupied) {
    return Status::kFrontBlocked;
  }
  const CellState before = map_.state(cell);
  if (before == CellState::kUnsensed) --unsensed_;
  map_.set_visited(cell, recorded(heading));
  // A detection inside the start cell before the start is an obstacle inside a visited cell.
  final_map_.set_occupied(cell, before == CellState::kOccupied);
  if (map_.state(front) == CellState::kUnsensed) {
    --unsensed_;
    set_sensed(front, CellState::kFree);
  }
  start_ = position_ = cell;
  heading_ = heading;
  started_ = true;
  return Status::kOk;
}

bool Explorer::explorable(GridCell c) const {
  return map_.contains(c) && map_.state(c) == CellState::kFree && map_.has_unsensed_neighbor(c);
}

// BOBMapping Code 2, CheckNeighbors: the first neighbour, clockwise from North, that is empty and
// still has unsensed neighbours (visited cells excluded, see explorer.hpp).
bool Explorer::check_neighbors(Direction& dir) const {
  for (const Direction d : kClockwiseFromNorth) {
    if (explorable(step(position_, d))) {
      dir = d;
      return true;
    }
  }
  return false;
}

Direction Explorer::recorded(Direction reached_by) const {
  return options_.backtrack == Backtrack::kTrail ? reached_by : Direction::kNorth;
}

// explorable(c), or the start cell (always kVisited) by the rule in explorer.hpp; written without
// calling explorable() to keep the firmware's deepest call chain, which runs through here, short.
bool Explorer::is_target(GridCell c) const {
  const CellState s = map_.state(c);
  return (s == CellState::kFree || (c == start_ && !start_reentered_)) &&
         map_.has_unsensed_neighbor(c);
}

// A breadth-first wavefront from every target at once (a multi-source Lee expansion), marked in
// place with distances mod 3 (decision 0004). Mod 3 is enough: the cells next to a cell at distance
// d are at d - 1, d or d + 1, so when level d + 1 grows from the cells marked mark_of(d), the only
// other cells with that mark lie at d - 3, d - 6, ..., whose neighbours are all marked already. If
// the robot is K from the nearest target, its neighbours are at least K - 1 from any target; the
// first level that holds one of them is K - 1, and the ones it holds are exactly the neighbours on
// a shortest path to a nearest target. Taking the first of them in N, E, S, W order gives the same
// move as a breadth-first search from the robot that expands N, E, S, W and stops at its first
// target. The robot's own cell is never a target: the search starts where the robot stands.
bool Explorer::first_step_to_nearest_explorable(Direction& dir) {
  for (int y = 0; y < map_.height(); ++y) {
    for (int x = 0; x < map_.width(); ++x) {
      const GridCell c{x, y};
      if (map_.is_known_free(c) && !(c == position_) && is_target(c)) {
        map_.set_direction_bits(c, mark_of(0));
      }
    }
  }
  unsigned distance = 0;
  bool found = false;
  while (!(found = find_marked_neighbor(map_, position_, mark_of(distance), dir)) &&
         grow_wavefront(map_, distance)) {
    ++distance;
  }
  clear_marks(map_);
  return found;
}

// Bits of Explorer::undo_.
constexpr std::uint8_t kUndoPossible = 1u;
constexpr std::uint8_t kUndoTargetWasVisited = 2u;
constexpr std::uint8_t kUndoStartWasReentered = 4u;

void Explorer::commit_move(Direction dir) {
  const GridCell target = step(position_, dir);
  undo_ = static_cast<std::uint8_t>(
      kUndoPossible | (map_.state(target) == CellState::kVisited ? kUndoTargetWasVisited : 0u) |
      (start_reentered_ ? kUndoStartWasReentered : 0u));
  if (dir != heading_) {
    ++turns_;
    quarter_turns_ += static_cast<std::uint32_t>(bob::quarter_turns(heading_, dir));
  }
  heading_ = dir;
  position_ = step(position_, dir);
  ++moves_;
  if (position_ == start_) start_reentered_ = true;
  // BOBMapping Code 1 line 11, MarkTrack: the first arrival stores the move that reached the cell.
  // Only known-free cells are entered, so its final-map bit is 0 already.
  if (map_.state(position_) != CellState::kVisited) map_.set_visited(position_, recorded(dir));
}

// BOBMapping Code 1, one iteration of the DO ... WHILE loop.
Status Explorer::next_move(Direction& move) {
  if (!started_) return Status::kNotStarted;
  if (finished()) return Status::kFinished;
  if (unsensed_ == 0) {  // section 3.4, condition (ii)
    stop_reason_ = StopReason::kAllSensed;
    return Status::kFinished;
  }
  Direction d = Direction::kNorth;
  if (check_neighbors(d)) {
    commit_move(d);
    move = d;
    return Status::kOk;
  }
  if (options_.backtrack == Backtrack::kTrail) {
    if (position_ == start_) {  // section 3.4, condition (i)
      stop_reason_ = StopReason::kBackAtStart;
      return Status::kFinished;
    }
    d = opposite(map_.came_from(position_));  // Code 1 line 13, Backtracking
  } else if (!first_step_to_nearest_explorable(d)) {
    stop_reason_ = StopReason::kNoReachableTarget;
    return Status::kFinished;
  }
  commit_move(d);
  move = d;
  return Status::kOk;
}

Status Explorer::blocked() {
  if (!started_ || (undo_ & kUndoPossible) == 0) return Status::kNotStarted;
  if ((undo_ & kUndoTargetWasVisited) == 0) {
    set_sensed(position_, CellState::kOccupied);
  } else {
    final_map_.set_occupied(position_, true);  // stays visited; the obstacle is in the final map
  }
  start_reentered_ = (undo_ & kUndoStartWasReentered) != 0;
  position_ = step(position_, opposite(heading_));
  --moves_;
  ++blocked_moves_;
  undo_ = 0;
  stop_reason_ = StopReason::kNone;
  return Status::kOk;
}

Status Explorer::write_final_map(std::uint8_t* buffer, std::size_t buffer_bytes) const {
  if (!initialised_) return Status::kNotStarted;
  const std::size_t bytes = final_map_.memory_bytes();
  if (buffer == nullptr || buffer_bytes < bytes) return Status::kBufferTooSmall;
  const std::uint8_t* from = final_map_.data();
  for (std::size_t i = 0; i < bytes; ++i) buffer[i] = from[i];
  return Status::kOk;
}

}  // namespace tessera::bob
