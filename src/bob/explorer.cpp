#include "tessera/bob/explorer.hpp"

#include "internal/limits.hpp"

namespace tessera::bob {
namespace {

// A breadth-first queue entry: the cell index in the low 14 bits, the first move of the path that
// reached the cell in the top 2 bits (so the search needs no per-cell parent array).
constexpr unsigned kIndexBits = 14;
constexpr unsigned kIndexMask = (1u << kIndexBits) - 1u;

void put_u16(std::uint8_t* p, unsigned v) {
  p[0] = static_cast<std::uint8_t>(v & 0xFFu);
  p[1] = static_cast<std::uint8_t>(v >> 8);
}
unsigned get_u16(const std::uint8_t* p) { return static_cast<unsigned>(p[0] | (p[1] << 8)); }

}  // namespace

Status Explorer::init(const ExplorerOptions& options, std::uint8_t* map_buffer,
                      std::size_t map_buffer_bytes, int width_cells, int height_cells,
                      std::uint8_t* scratch, std::size_t scratch_buffer_bytes) {
  *this = Explorer{};
  const Status s = map_.init(map_buffer, map_buffer_bytes, width_cells, height_cells);
  if (s != Status::kOk) return s;
  if (options.backtrack == Backtrack::kShortestKnownPath &&
      (scratch == nullptr || scratch_buffer_bytes < scratch_bytes(width_cells, height_cells))) {
    map_ = PackedMap{};
    return Status::kBufferTooSmall;
  }
  options_ = options;
  scratch_ = scratch;
  unsensed_ = map_.cell_count();
  initialised_ = true;
  return Status::kOk;
}

void Explorer::mark_sensed(GridCell c, CellState s) {
  if (map_.state(c) == CellState::kUnsensed) --unsensed_;
  map_.set_state(c, s);
}

Status Explorer::sense(GridCell c, bool occupied) {
  if (!initialised_) return Status::kNotStarted;
  if (!map_.contains(c)) return Status::kOutOfBounds;
  switch (map_.state(c)) {
    case CellState::kUnsensed:
      mark_sensed(c, occupied ? CellState::kOccupied : CellState::kFree);
      break;
    case CellState::kFree:  // section 3.4: a later reading changes a sensed cell
      if (occupied) {
        map_.set_state(c, CellState::kOccupied);
        ++resensed_;
      }
      break;
    case CellState::kOccupied:
      if (!occupied) {
        map_.set_state(c, CellState::kFree);
        ++resensed_;
      }
      break;
    case CellState::kVisited:  // section 3.4: the robot passed through it without collision
      if (occupied) ++discarded_;
      break;
  }
  return Status::kOk;
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
  if (map_.state(cell) == CellState::kUnsensed) --unsensed_;
  map_.set_visited(cell, heading);
  if (map_.state(front) == CellState::kUnsensed) mark_sensed(front, CellState::kFree);
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

bool Explorer::first_step_to_nearest_explorable(Direction& dir) {
  const int n = map_.cell_count();
  std::uint8_t* const queue = scratch_;
  std::uint8_t* const seen = scratch_ + 2 * n;
  for (int i = 0; i < (n + 7) / 8; ++i) seen[i] = 0;
  const auto test_and_set = [seen](int index) {
    const auto bit = static_cast<std::uint8_t>(1u << (index % 8));
    const bool was = (seen[index / 8] & bit) != 0;
    seen[index / 8] = static_cast<std::uint8_t>(seen[index / 8] | bit);
    return was;
  };
  int head = 0;
  int tail = 0;
  (void)test_and_set(map_.index_of(position_));
  for (const Direction d : kClockwiseFromNorth) {
    const GridCell c = step(position_, d);
    if (map_.is_known_free(c) && !test_and_set(map_.index_of(c))) {
      put_u16(queue + 2 * tail++,
              static_cast<unsigned>(map_.index_of(c)) | (static_cast<unsigned>(d) << kIndexBits));
    }
  }
  while (head < tail) {
    const unsigned entry = get_u16(queue + 2 * head++);
    const GridCell c = map_.cell_of(static_cast<int>(entry & kIndexMask));
    const unsigned first = entry >> kIndexBits;
    if (explorable(c) || (c == start_ && !start_reentered_ && map_.has_unsensed_neighbor(c))) {
      dir = static_cast<Direction>(first);
      return true;
    }
    for (const Direction d : kClockwiseFromNorth) {
      const GridCell nb = step(c, d);
      if (map_.is_known_free(nb) && !test_and_set(map_.index_of(nb))) {
        put_u16(queue + 2 * tail++,
                static_cast<unsigned>(map_.index_of(nb)) | (first << kIndexBits));
      }
    }
  }
  return false;
}

void Explorer::commit_move(Direction dir) {
  if (dir != heading_) {
    ++turns_;
    quarter_turns_ += static_cast<std::uint32_t>(bob::quarter_turns(heading_, dir));
  }
  heading_ = dir;
  position_ = step(position_, dir);
  ++moves_;
  if (position_ == start_) start_reentered_ = true;
  // BOBMapping Code 1 line 11, MarkTrack: the first arrival stores the move that reached the cell.
  if (map_.state(position_) != CellState::kVisited) map_.set_visited(position_, dir);
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

Status Explorer::write_final_map(std::uint8_t* buffer, std::size_t buffer_bytes) const {
  if (!initialised_) return Status::kNotStarted;
  FinalMap final_map;
  const Status s = final_map.init(buffer, buffer_bytes, map_.width(), map_.height());
  if (s != Status::kOk) return s;
  return final_map.assign_from(map_);
}

}  // namespace tessera::bob
