#pragma once
// The BOBMapping explorer (section 3.1, section 3.4, Code 1 and Code 2) as a step machine with no
// I/O: the caller (simulator or firmware) reports sensor readings of cells and asks for the next
// one-cell move. Freestanding: no heap, no exceptions, no RTTI, no standard library beyond
// <cstdint>/<cstddef>; every buffer comes from the caller.

#include <cstddef>
#include <cstdint>

#include "tessera/bob/direction.hpp"
#include "tessera/bob/explorer_options.hpp"
#include "tessera/bob/final_map.hpp"
#include "tessera/bob/packed_map.hpp"
#include "tessera/bob/status.hpp"

namespace tessera::bob {

/// Why the explorer stopped (section 3.4).
enum class StopReason : std::uint8_t {
  kNone,               // still exploring
  kBackAtStart,        // (i) back at the initial cell with no explorable neighbour (kTrail)
  kAllSensed,          // (ii) every cell of the grid is sensed
  kNoReachableTarget,  // kShortestKnownPath: no explorable cell reachable through known space
};

/// Tremaux exploration with the optimisation of BOBMapping Code 2.
///
/// A cell is *explorable* when it is known free (sensed empty or visited), has never been stood
/// in, and has an unsensed orthogonal neighbour inside the grid. Each next_move():
///  1. stops if every cell is sensed (condition ii);
///  2. Code 2: moves to the first explorable neighbour in clockwise order from North;
///  3. otherwise backtracks: kTrail moves one cell opposite to the stored "reached by" direction,
///     or stops at the start cell (condition i); kShortestKnownPath takes the first step of a
///     shortest path through known-free cells to the nearest explorable cell, or stops when there
///     is none. Tie-break: the first move in N, E, S, W order that starts a shortest path to
///     any of the nearest targets (the same move as a breadth-first search from the robot that
///     expands neighbours N, E, S, W and stops at its first target).
/// The move is committed at once: position(), heading() and the map assume the robot has done
/// it. The caller then reports what its sensors saw on the way with sense(), and asks again.
///
/// Visited cells are never forward candidates although Code 2 would allow one with unsensed
/// neighbours: arriving in a cell senses all its neighbours (section 3.2: the three around the
/// next cell; the fourth is where the robot came from), so only the start cell, whose back
/// neighbour the sensors cannot see at rest, can be such a cell, and re-entering it would
/// overwrite its stored direction and close a loop in the trail. Returning to the start senses
/// that neighbour anyway. This also bounds a run: every forward move enters a new cell. kTrail
/// returns there by construction; kShortestKnownPath therefore also takes the start cell as a
/// target while it has an unsensed neighbour and the robot has not been back in it since starting
/// (once only, so a sensor that never reports that neighbour cannot trap the robot).
///
/// Re-sensing (section 3.4): a later reading overrides an earlier one, except that a reading of
/// "occupied" in a visited cell does not make it occupied: the robot has stood there, so the cell
/// stays traversable for the explorer (backtracking goes through it). Such a reading, and a bump
/// on the way into a visited cell (blocked()), are kept in the final map instead, which marks the
/// cell 1, "not fully free": a body that fits in the cell with 3 cm to spare can stand beside an
/// obstacle that lies inside it (decision 0008). Once recorded, it stays (errors fall on the safe
/// side, as section 3.2 wants): later "free" readings of the cell do not clear it.
///
/// The final map (section 3.4, 1 bit per cell, FinalMap) is kept current while mapping, in a
/// second caller buffer: bit 1 for an unsensed cell, a cell sensed occupied, and a visited cell
/// with an obstacle recorded inside; 0 for the rest. For a visited cell it is the only record of
/// such an obstacle (the fifth bit of the cell, which the 4-bit layout has no room for), so the
/// mapping memory is PackedMap::bytes_needed + FinalMap::bytes_needed (memory_bytes(): 84 + 28 =
/// 112 bytes for 11 x 14), and the final map costs nothing more at the end.
///
/// Protocol: init(); sense() what the sensors see at the start pose; start(); then loop
/// { next_move(); move the robot; sense() on the way } until next_move() returns kFinished.
///
/// The kShortestKnownPath search runs in place, in the two direction bits of the packed map that
/// only kTrail reads (decision 0004): a wavefront from all targets at once marks each known-free
/// cell with 1 + (its distance to the nearest target) mod 3 until it reaches a neighbour of the
/// robot, then clears the marks. It needs no memory beyond the map, but a kShortestKnownPath
/// explorer records no "reached by" directions: map().came_from() is meaningful with kTrail only.
///
/// Cost: sense() is O(1); next_move() is O(1) with kTrail and when a neighbour qualifies, and
/// O(cells x (K + 1)) when kShortestKnownPath backtracks, K the distance to the nearest target.
/// Memory: the packed map and the final map (memory_bytes()) for either variant; no scratch.
class Explorer {
 public:
  /// Bytes of the two caller buffers together: PackedMap::bytes_needed (the 4-bit mapping
  /// layout) + FinalMap::bytes_needed (the final map, which also holds the fifth bit of visited
  /// cells). 11 x 14 -> 84 + 28 = 112.
  [[nodiscard]] static constexpr std::size_t memory_bytes(int width_cells, int height_cells) {
    return PackedMap::bytes_needed(width_cells, height_cells) +
           FinalMap::bytes_needed(width_cells, height_cells);
  }

  constexpr Explorer() = default;

  /// Sets up a width x height grid of unsensed cells in `map_buffer` (PackedMap::bytes_needed
  /// bytes) and its final map, every cell 1, in `final_map_buffer` (FinalMap::bytes_needed
  /// bytes). The explorer uses both until it is initialised again. kBadSize, kBufferTooSmall on
  /// a bad size or a short or null buffer; the explorer is then unusable.
  [[nodiscard]] Status init(const ExplorerOptions& options, std::uint8_t* map_buffer,
                            std::size_t map_buffer_bytes, std::uint8_t* final_map_buffer,
                            std::size_t final_map_buffer_bytes, int width_cells, int height_cells);

  /// Records a reading: `occupied` for any detection inside cell c. kOutOfBounds for a cell
  /// outside the grid (ignore it: the robot's sensors see past the grid's edge), kNotStarted
  /// before init(). A reading of "occupied" in a visited cell leaves the cell visited and marks
  /// it 1 in the final map (kOk).
  Status sense(GridCell c, bool occupied);

  /// One cell a step's beams swept (section 3.2: B2, C3 or D2 of Figure 3), read free or occupied.
  /// A "free" reading goes to sense(); an "occupied" one too, unless the robot has stood in the
  /// cell: the three targets are read occupied whenever a reflector *may* lie in them (the IR
  /// noise and the pose uncertainty), which is the safe side for a cell the robot has not been in
  /// but weaker evidence than having stood there, so a visited cell takes only detections placed
  /// inside it (report_detection). Same statuses as sense().
  Status report_target(GridCell c, bool occupied);
  /// A reading placed its reflector inside cell c, which the step's beams do not sweep as a whole
  /// (B1, C2's far neighbours...): a detection only, never "free". Recorded as an "occupied"
  /// reading of c when c is sensed already (an unsensed cell waits for a full sweep); in a
  /// visited cell it marks the final map (decision 0008). Same statuses as sense().
  Status report_detection(GridCell c);

  /// Places the robot in `cell` facing `heading` and marks the cell visited. Section 3.4 requires
  /// the front neighbour to be unoccupied: kFrontBlocked if it is outside the grid or was sensed
  /// occupied (the explorer then stays unstarted); an unsensed front cell is taken as free, as
  /// that requirement says. kOutOfBounds, kNotStarted (before init), kAlreadyStarted.
  [[nodiscard]] Status start(GridCell cell, Direction heading);

  /// The next one-cell move into `move` (kOk), or kFinished (see stop_reason()), or kNotStarted.
  [[nodiscard]] Status next_move(Direction& move);

  [[nodiscard]] bool started() const { return started_; }
  [[nodiscard]] bool finished() const { return stop_reason_ != StopReason::kNone; }
  [[nodiscard]] StopReason stop_reason() const { return stop_reason_; }
  [[nodiscard]] GridCell position() const { return position_; }
  [[nodiscard]] GridCell start_cell() const { return start_; }
  [[nodiscard]] Direction heading() const { return heading_; }
  [[nodiscard]] const ExplorerOptions& options() const { return options_; }
  [[nodiscard]] const PackedMap& map() const { return map_; }
  /// The final map as it stands (see above): valid from init() on, complete once finished().
  [[nodiscard]] const FinalMap& final_map() const { return final_map_; }
  /// True when c is a visited cell with an obstacle recorded inside it (a reading or a bump):
  /// traversable for the explorer, 1 in the final map. Precondition: map().contains(c).
  [[nodiscard]] bool obstacle_in_visited(GridCell c) const {
    return map_.state(c) == CellState::kVisited && final_map_.occupied(c);
  }

  /// One-cell moves so far (Table 1 "length path").
  [[nodiscard]] std::uint32_t moves() const { return moves_; }
  /// Heading changes so far, each one turn in place whatever its angle (Table 1 "turns").
  [[nodiscard]] std::uint32_t turns() const { return turns_; }
  /// The same in 90-degree units: a reversal counts two.
  [[nodiscard]] std::uint32_t quarter_turns() const { return quarter_turns_; }
  /// Readings that changed an already sensed cell (Table 1 "re-sensed cells", counted per change).
  [[nodiscard]] std::uint32_t resensed() const { return resensed_; }
  /// "Occupied" readings of visited cells: kept out of the mapping state, recorded in the final
  /// map only.
  [[nodiscard]] std::uint32_t discarded_readings() const { return discarded_; }
  /// Readings of already sensed cells ignored because re-sensing is off (ExplorerOptions).
  [[nodiscard]] std::uint32_t ignored_readings() const { return ignored_; }
  /// Cells of the grid not sensed yet.
  [[nodiscard]] int unsensed_cells() const { return unsensed_; }

  /// The move just returned by next_move() could not be made: the robot met an obstacle on the
  /// way (a bump or a stalled motor) and drove back to the cell it left. That cell becomes the
  /// position again and the cell it tried to enter is marked occupied -- unless the robot had
  /// stood in it before (section 3.4: a visited cell never becomes occupied), when it stays
  /// visited and is marked 1 in the final map only (an obstacle inside it, decision 0008). Not in
  /// the paper, whose robot has no bumper: without it a robot that misread a cell drives into it.
  /// kNotStarted when there is no move to take back (before the first move, or twice in a row).
  /// The move is not counted in moves().
  [[nodiscard]] Status blocked();
  /// Moves taken back with blocked().
  [[nodiscard]] std::uint32_t blocked_moves() const { return blocked_moves_; }

  /// Copies the final 1-bit map (final_map(), FinalMap layout) into `buffer`
  /// (FinalMap::bytes_needed bytes; the explorer's own final-map buffer is fine too).
  /// kBufferTooSmall, kNotStarted before init().
  [[nodiscard]] Status write_final_map(std::uint8_t* buffer, std::size_t buffer_bytes) const;

 private:
  /// Code 2: first explorable neighbour clockwise from North; false when there is none.
  [[nodiscard]] bool check_neighbors(Direction& dir) const;
  [[nodiscard]] bool explorable(GridCell c) const;
  /// A cell kShortestKnownPath heads for: explorable, or the start cell by the rule above.
  /// Precondition: map_.contains(c).
  [[nodiscard]] bool is_target(GridCell c) const;
  /// First step of a shortest known-free path to the nearest target; false when none is reachable.
  [[nodiscard]] bool first_step_to_nearest_explorable(Direction& dir);
  /// The "reached by" direction to store in a newly visited cell: `reached_by` with kTrail,
  /// kNorth (bits 0) with kShortestKnownPath, whose search owns those bits.
  [[nodiscard]] Direction recorded(Direction reached_by) const;
  void commit_move(Direction dir);
  /// Sets c, not visited, to kFree or kOccupied, and its final-map bit to match.
  void set_sensed(GridCell c, CellState s);

  ExplorerOptions options_{};
  PackedMap map_{};
  FinalMap final_map_{};
  GridCell start_{};
  GridCell position_{};
  Direction heading_ = Direction::kNorth;
  StopReason stop_reason_ = StopReason::kNone;
  bool initialised_ = false;
  bool started_ = false;
  bool start_reentered_ = false;
  int unsensed_ = 0;
  std::uint32_t moves_ = 0;
  std::uint32_t turns_ = 0;
  std::uint32_t quarter_turns_ = 0;
  std::uint32_t resensed_ = 0;
  std::uint32_t discarded_ = 0;
  std::uint32_t ignored_ = 0;
  std::uint32_t blocked_moves_ = 0;
  // What blocked() needs to take the last move back (kUndo* bits).
  std::uint8_t undo_ = 0;
};

}  // namespace tessera::bob
