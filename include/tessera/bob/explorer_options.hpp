#pragma once
// Options of the BOBMapping explorer (explorer.hpp). Freestanding: <cstdint> only.

#include <cstdint>

namespace tessera::bob {

/// How the robot returns to unexplored space when no neighbour qualifies (BOBMapping Code 1,
/// line 13).
enum class Backtrack : std::uint8_t {
  /// The paper's Tremaux backtracking: one cell back along the stored "reached by" directions per
  /// step; stops back at the start cell with no explorable neighbour (section 3.4, condition i).
  kTrail,
  /// Uses the map already built: the shortest known-free path to the nearest explorable cell,
  /// found in place in the map's direction bits (no scratch memory, decision 0004); stops when
  /// none is reachable.
  kShortestKnownPath,
};

struct ExplorerOptions {
  Backtrack backtrack = Backtrack::kTrail;
  /// BOBMapping 3.4 re-sensing: a later reading of a sensed cell changes it (a visited cell never
  /// becomes occupied; an obstacle read inside it goes into the final map, decision 0008). Off:
  /// the first reading of a cell is final and later readings of sensed cells are ignored (the
  /// paper's ablation, "20 errors arose while mapping, but using the re-sensing process, the
  /// errors dropped to six"). Bumps (Explorer::blocked) are not readings and act either way.
  bool resense = true;
};

}  // namespace tessera::bob
