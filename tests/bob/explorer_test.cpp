#include "tessera/bob/explorer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "bob_world.hpp"

namespace tessera::bob {
namespace {

using bobtest::TextGrid;

// An explorer whose knowledge is drawn as text (top row first): '?' unsensed, '#' sensed occupied,
// '.' sensed free, 'R' the start cell. Every drawn cell but '?' is reported with sense(), then the
// robot starts in 'R' facing `heading`.
class Knowledge {
 public:
  Knowledge(const TextGrid& drawn, Direction heading, Backtrack backtrack = Backtrack::kTrail)
      : map_(PackedMap::bytes_needed(drawn.width(), drawn.height())),
        final_(FinalMap::bytes_needed(drawn.width(), drawn.height())) {
    EXPECT_EQ(explorer_.init(ExplorerOptions{backtrack}, map_.data(), map_.size(), final_.data(),
                             final_.size(), drawn.width(), drawn.height()),
              Status::kOk);
    for (int y = 0; y < drawn.height(); ++y) {
      for (int x = 0; x < drawn.width(); ++x) {
        const char ch = drawn.at({x, y});
        if (ch != '?' && ch != 'R') {
          EXPECT_EQ(explorer_.sense({x, y}, ch == '#'), Status::kOk);
        }
      }
    }
    EXPECT_EQ(explorer_.start(drawn.find('R'), heading), Status::kOk);
  }
  Explorer& explorer() { return explorer_; }

 private:
  std::vector<std::uint8_t> map_;
  std::vector<std::uint8_t> final_;
  Explorer explorer_;
};

Direction next(Explorer& ex) {
  Direction d = Direction::kNorth;
  EXPECT_EQ(ex.next_move(d), Status::kOk);
  return d;
}

// Figure 2a: neighbours are numbered clockwise from North, 1 = N, 2 = E, 3 = S, 4 = W. Neighbours 1
// and 2 are empty but every cell around them is already charted, so they are discarded; 3 (South)
// is the first with an uncharted neighbour (the '?' below it) and is chosen, although 4 (West,
// next to the '?' on the left) qualifies too: the priority is clockwise from North (Code 2).
TEST(Explorer, Figure2aChoosesCellThreeWhenOneAndTwoHaveNoUnchartedNeighbours) {
  const TextGrid drawn({
      "?###?",
      "#...#",
      "?.R.#",
      "?#.#?",
      "?????",
  });
  Knowledge k(drawn, Direction::kNorth);
  EXPECT_EQ(next(k.explorer()), Direction::kSouth);
  EXPECT_EQ(k.explorer().position(), (GridCell{2, 1}));
  EXPECT_EQ(k.explorer().map().came_from({2, 1}), Direction::kSouth);
  EXPECT_EQ(k.explorer().turns(), 1u);
}

// Figure 2b: neighbour 1 (North) is empty but fully charted; neighbour 2 (East) has an uncharted
// neighbour (the '?' right of it) and is chosen before 3 (South), which also has one.
TEST(Explorer, Figure2bChoosesCellTwoWhenOnlyOneIsDiscarded) {
  const TextGrid drawn({
      "?###?",
      "#...#",
      "?.R.?",
      "?#.#?",
      "?????",
  });
  Knowledge k(drawn, Direction::kNorth);
  EXPECT_EQ(next(k.explorer()), Direction::kEast);
  EXPECT_EQ(k.explorer().position(), (GridCell{3, 2}));
}

// Figure 2c: the robot reached the middle cell from the West (cell 4). Neighbours 1, 2 and 3 are
// occupied, and 4 is where it came from, the only neighbour with uncharted and accessible cells
// beyond it: the robot backtracks into 4 along its stored direction (Code 1 line 13), and from
// there Code 2 picks the empty cell further West, which still has uncharted neighbours.
TEST(Explorer, Figure2cBacktracksToCellFourWhenNoNeighbourQualifies) {
  const TextGrid drawn({
      "?###?",
      "?R.??",
      "?###?",
  });
  Knowledge k(drawn, Direction::kEast);
  Explorer& ex = k.explorer();
  ASSERT_EQ(ex.sense({0, 1}, false), Status::kOk);  // cell 4's West neighbour: empty
  EXPECT_EQ(next(ex), Direction::kEast);            // Code 2 from the start: into the middle
  ASSERT_EQ(ex.sense({3, 1}, true), Status::kOk);   // what the robot sees on arrival
  EXPECT_EQ(ex.map().came_from({2, 1}), Direction::kEast);
  EXPECT_EQ(next(ex), Direction::kWest);  // backtrack into cell 4
  EXPECT_EQ(ex.position(), (GridCell{1, 1}));
  EXPECT_EQ(next(ex), Direction::kWest);  // Code 2 from cell 4
  EXPECT_EQ(ex.position(), (GridCell{0, 1}));
  EXPECT_EQ(ex.map().state({1, 1}), CellState::kVisited);
}

TEST(Explorer, MapAwareVariantAlsoTakesCodeTwoChoicesFirst) {
  const TextGrid drawn({
      "?###?",
      "#...#",
      "?.R.?",
      "?#.#?",
      "?????",
  });
  Knowledge k(drawn, Direction::kNorth, Backtrack::kShortestKnownPath);
  EXPECT_EQ(next(k.explorer()), Direction::kEast);
}

// Every direction bit of a kShortestKnownPath map is 0 between calls (decision 0004).
void expect_no_marks(const PackedMap& map) {
  for (int y = 0; y < map.height(); ++y) {
    for (int x = 0; x < map.width(); ++x) {
      EXPECT_EQ(map.direction_bits({x, y}), 0u) << x << "," << y;
    }
  }
}

// No neighbour of the robot qualifies. The corridor North leads to a target three cells away (the
// '.' below the '?'), the one East to a target two cells away: the nearest target wins over the
// clockwise order.
TEST(Explorer, MapAwareBacktrackingHeadsForTheNearestTarget) {
  const TextGrid drawn({
      "###?###",
      "###.###",
      "###.###",
      "###.###",
      "#..R..?",
      "#######",
  });
  Knowledge k(drawn, Direction::kNorth, Backtrack::kShortestKnownPath);
  EXPECT_EQ(next(k.explorer()), Direction::kEast);
  expect_no_marks(k.explorer().map());
}

// The same with both targets two cells away: the tie goes to the first move in N, E, S, W order.
TEST(Explorer, MapAwareBacktrackingBreaksATieBetweenTargetsNorthFirst) {
  const TextGrid drawn({
      "###?###",
      "###.###",
      "###.###",
      "#..R..?",
      "#######",
  });
  Knowledge k(drawn, Direction::kNorth, Backtrack::kShortestKnownPath);
  EXPECT_EQ(next(k.explorer()), Direction::kNorth);
  expect_no_marks(k.explorer().map());
}

// One target, two shortest paths to it (North then East, East then North): North first.
TEST(Explorer, MapAwareBacktrackingBreaksATieBetweenPathsNorthFirst) {
  const TextGrid drawn({
      "#####",
      "#..?#",
      "#R.##",
      "#####",
  });
  Knowledge k(drawn, Direction::kNorth, Backtrack::kShortestKnownPath);
  EXPECT_EQ(next(k.explorer()), Direction::kNorth);
  EXPECT_EQ(next(k.explorer()), Direction::kEast);  // Code 2: the cell next to the '?'
}

// The search marks the map in place and clears it again; the robot never leans on stale marks.
TEST(Explorer, MapAwareRunLeavesNoSearchMarksInTheMap) {
  const TextGrid world({
      "###########",
      "#.#...#...#",
      "#.#.#.#.#.#",
      "#...#...#.#",
      "###.#####.#",
      "#R........#",
      "###########",
  });
  bobtest::ExplorationRun run;
  bobtest::explore(world, Direction::kEast, Backtrack::kShortestKnownPath,
                   bobtest::SensorLayout::kFourNeighbors, run);
  EXPECT_EQ(run.stop_reason, StopReason::kNoReachableTarget);
  EXPECT_FALSE(run.hit_wall);
  expect_no_marks(run.explorer.map());
}

// Section 3.4: "the sensor structure requires the robot to be initially positioned in a cell whose
// frontal neighbor is unoccupied".
TEST(Explorer, StartingFacingAWallIsRefusedWithFrontBlocked) {
  const TextGrid world({
      "#####",
      "#..R#",
      "#####",
  });
  std::vector<std::uint8_t> map(PackedMap::bytes_needed(5, 3));
  std::vector<std::uint8_t> final_map(FinalMap::bytes_needed(5, 3));
  Explorer ex;
  ASSERT_EQ(ex.init({}, map.data(), map.size(), final_map.data(), final_map.size(), 5, 3),
            Status::kOk);
  bobtest::sense_exact(ex, world, {3, 1}, Direction::kEast, bobtest::SensorLayout::kFourNeighbors);
  EXPECT_EQ(ex.start({3, 1}, Direction::kEast), Status::kFrontBlocked);
  EXPECT_FALSE(ex.started());
  Direction d = Direction::kNorth;
  EXPECT_EQ(ex.next_move(d), Status::kNotStarted);
  // Facing the grid's edge is the same.
  EXPECT_EQ(ex.start({4, 1}, Direction::kEast), Status::kFrontBlocked);
  // Facing the free cell is fine.
  EXPECT_EQ(ex.start({3, 1}, Direction::kWest), Status::kOk);
  EXPECT_EQ(ex.start({3, 1}, Direction::kWest), Status::kAlreadyStarted);
}

TEST(Explorer, StartOutsideTheGridOrBeforeInitIsAnError) {
  Explorer ex;
  EXPECT_EQ(ex.start({0, 0}, Direction::kNorth), Status::kNotStarted);
  EXPECT_EQ(ex.sense({0, 0}, true), Status::kNotStarted);
  std::vector<std::uint8_t> map(PackedMap::bytes_needed(3, 3));
  std::vector<std::uint8_t> final_map(FinalMap::bytes_needed(3, 3));
  ASSERT_EQ(ex.init({}, map.data(), map.size(), final_map.data(), final_map.size(), 3, 3),
            Status::kOk);
  EXPECT_EQ(ex.start({3, 0}, Direction::kWest), Status::kOutOfBounds);
  EXPECT_EQ(ex.sense({-1, 0}, true), Status::kOutOfBounds);
}

// The mapping memory for the paper's 11 x 14 grid: the 4-bit map (84 bytes) and the final map,
// which also holds the fifth bit of visited cells (28 bytes, decision 0008); nothing else for
// either variant (the map-aware search runs in the map's direction bits, decision 0004).
TEST(Explorer, MappingMemoryForElevenByFourteenIsTheFourBitMapPlusTheFinalMap) {
  EXPECT_EQ(Explorer::memory_bytes(11, 14), 112u);
  for (const Backtrack backtrack : {Backtrack::kTrail, Backtrack::kShortestKnownPath}) {
    std::vector<std::uint8_t> map(PackedMap::bytes_needed(11, 14));
    std::vector<std::uint8_t> final_map(FinalMap::bytes_needed(11, 14), 0);
    ASSERT_EQ(map.size() + final_map.size(), 112u);
    Explorer ex;
    const ExplorerOptions options{backtrack};
    EXPECT_EQ(ex.init(options, map.data(), map.size(), final_map.data(), final_map.size(), 11, 14),
              Status::kOk);
    // Every cell starts unsensed, 1 in the final map; the 5 padding bits of each row stay 0.
    for (std::size_t row = 0; row < 14; ++row) {
      EXPECT_EQ(final_map[2 * row], 0xFF);
      EXPECT_EQ(final_map[2 * row + 1], 0x07);
    }
    EXPECT_EQ(ex.init(options, map.data(), map.size() - 1, final_map.data(), final_map.size(), 11,
                      14),
              Status::kBufferTooSmall);
    EXPECT_EQ(ex.init(options, map.data(), map.size(), final_map.data(), final_map.size() - 1, 11,
                      14),
              Status::kBufferTooSmall);
    EXPECT_EQ(ex.init(options, map.data(), map.size(), nullptr, 0, 11, 14),
              Status::kBufferTooSmall);
    EXPECT_EQ(ex.sense({0, 0}, false), Status::kNotStarted);  // unusable after a failed init
  }
}

// Section 3.4 re-sensing: a later reading changes a sensed cell, except that a visited cell never
// becomes occupied.
TEST(Explorer, ReSensingChangesSensedCellsButNeverMakesAVisitedCellOccupied) {
  std::vector<std::uint8_t> map(PackedMap::bytes_needed(3, 3));
  std::vector<std::uint8_t> final_map(FinalMap::bytes_needed(3, 3));
  Explorer ex;
  ASSERT_EQ(ex.init({}, map.data(), map.size(), final_map.data(), final_map.size(), 3, 3),
            Status::kOk);
  EXPECT_EQ(ex.unsensed_cells(), 9);
  ASSERT_EQ(ex.sense({1, 2}, true), Status::kOk);
  EXPECT_EQ(ex.unsensed_cells(), 8);
  ASSERT_EQ(ex.sense({1, 2}, false), Status::kOk);  // occupied -> free
  EXPECT_EQ(ex.map().state({1, 2}), CellState::kFree);
  ASSERT_EQ(ex.sense({1, 2}, true), Status::kOk);  // free -> occupied
  EXPECT_EQ(ex.map().state({1, 2}), CellState::kOccupied);
  EXPECT_EQ(ex.resensed(), 2u);
  ASSERT_EQ(ex.sense({1, 1}, false), Status::kOk);
  ASSERT_EQ(ex.start({1, 0}, Direction::kNorth), Status::kOk);
  Direction d = Direction::kNorth;
  ASSERT_EQ(ex.next_move(d), Status::kOk);  // into (1, 1): it has unsensed neighbours
  ASSERT_EQ(d, Direction::kNorth);
  ASSERT_EQ(ex.sense({1, 1}, true), Status::kOk);  // stood in: stays visited
  ASSERT_EQ(ex.sense({1, 0}, true), Status::kOk);  // the start cell too
  EXPECT_EQ(ex.map().state({1, 1}), CellState::kVisited);
  EXPECT_EQ(ex.map().state({1, 0}), CellState::kVisited);
  EXPECT_EQ(ex.discarded_readings(), 2u);
  EXPECT_EQ(ex.resensed(), 2u);
  // ... but the final map keeps the obstacles (decision 0008), and a later "free" reading does not
  // clear them.
  ASSERT_EQ(ex.sense({1, 1}, false), Status::kOk);
  EXPECT_TRUE(ex.obstacle_in_visited({1, 1}));
  EXPECT_TRUE(ex.obstacle_in_visited({1, 0}));
  EXPECT_TRUE(ex.final_map().occupied({1, 1}));
  EXPECT_TRUE(ex.final_map().occupied({1, 0}));
  EXPECT_TRUE(ex.final_map().occupied({1, 2}));   // sensed occupied
  EXPECT_TRUE(ex.final_map().occupied({0, 0}));   // unsensed
  EXPECT_EQ(ex.resensed(), 2u);
}

TEST(Explorer, WithReSensingOffTheFirstReadingOfACellStays) {
  std::vector<std::uint8_t> map(PackedMap::bytes_needed(3, 3));
  std::vector<std::uint8_t> final_map(FinalMap::bytes_needed(3, 3));
  Explorer ex;
  ExplorerOptions options;
  options.resense = false;
  ASSERT_EQ(ex.init(options, map.data(), map.size(), final_map.data(), final_map.size(), 3, 3),
            Status::kOk);
  ASSERT_EQ(ex.sense({1, 2}, true), Status::kOk);
  ASSERT_EQ(ex.sense({1, 2}, false), Status::kOk);  // ignored: stays occupied
  EXPECT_EQ(ex.map().state({1, 2}), CellState::kOccupied);
  EXPECT_TRUE(ex.final_map().occupied({1, 2}));
  ASSERT_EQ(ex.sense({1, 1}, false), Status::kOk);
  ASSERT_EQ(ex.start({1, 0}, Direction::kNorth), Status::kOk);
  Direction d = Direction::kNorth;
  ASSERT_EQ(ex.next_move(d), Status::kOk);
  ASSERT_EQ(ex.sense({1, 1}, true), Status::kOk);  // a visited cell: ignored too
  EXPECT_FALSE(ex.final_map().occupied({1, 1}));
  EXPECT_EQ(ex.resensed(), 0u);
  EXPECT_EQ(ex.discarded_readings(), 0u);
  EXPECT_EQ(ex.ignored_readings(), 2u);
}

// A pocket of two cells: the robot drives into the front cell, sees walls all round, and comes
// back; condition (i) stops it at the start. The map-aware variant stops where it is instead.
TEST(Explorer, RobotBoxedInAPocketExploresItAndStops) {
  const TextGrid world({
      "####",
      "#R.#",
      "####",
  });
  bobtest::ExplorationRun trail;
  bobtest::explore(world, Direction::kEast, Backtrack::kTrail,
                   bobtest::SensorLayout::kFourNeighbors, trail);
  EXPECT_EQ(trail.last_status, Status::kFinished);
  EXPECT_EQ(trail.stop_reason, StopReason::kBackAtStart);
  EXPECT_EQ(trail.path, (std::vector<GridCell>{{2, 1}, {1, 1}}));
  EXPECT_EQ(trail.turns, 1u);
  EXPECT_EQ(trail.explorer.quarter_turns(), 2u);

  bobtest::ExplorationRun aware;
  bobtest::explore(world, Direction::kEast, Backtrack::kShortestKnownPath,
                   bobtest::SensorLayout::kFourNeighbors, aware);
  EXPECT_EQ(aware.stop_reason, StopReason::kNoReachableTarget);
  EXPECT_EQ(aware.path, (std::vector<GridCell>{{2, 1}}));
}

TEST(Explorer, RobotWithWallsOnAllFourSidesCannotStart) {
  const TextGrid world({
      "###",
      "#R#",
      "###",
  });
  for (const Direction heading : kClockwiseFromNorth) {
    bobtest::ExplorationRun run;
    bobtest::explore(world, heading, Backtrack::kTrail, bobtest::SensorLayout::kFourNeighbors, run);
    EXPECT_EQ(run.start_status, Status::kFrontBlocked);
    EXPECT_TRUE(run.path.empty());
  }
}

// A corridor one cell wide (far narrower than the 2 sqrt(2) cells section 3.1 asks of a real
// corridor, which is about its alignment with the grid; on the grid one cell is enough): the robot
// drives to its dead end, turns round once, and backtracks to the start.
TEST(Explorer, CorridorOneCellWideIsExploredToItsEndAndBack) {
  const TextGrid world({
      "#######",
      "#R....#",
      "#######",
  });
  bobtest::ExplorationRun run;
  bobtest::explore(world, Direction::kEast, Backtrack::kTrail,
                   bobtest::SensorLayout::kFourNeighbors, run);
  EXPECT_EQ(run.stop_reason, StopReason::kBackAtStart);
  EXPECT_EQ(run.path, (std::vector<GridCell>{
                          {2, 1}, {3, 1}, {4, 1}, {5, 1}, {4, 1}, {3, 1}, {2, 1}, {1, 1}}));
  EXPECT_EQ(run.turns, 1u);
  EXPECT_FALSE(run.hit_wall);

  bobtest::ExplorationRun aware;
  bobtest::explore(world, Direction::kEast, Backtrack::kShortestKnownPath,
                   bobtest::SensorLayout::kFourNeighbors, aware);
  EXPECT_EQ(aware.stop_reason, StopReason::kNoReachableTarget);
  EXPECT_EQ(aware.moves, 4u);
}

// Condition (ii): in an open space bounded only by the grid, the run ends once every cell of the
// grid is sensed, wherever the robot is.
TEST(Explorer, StopsWhenEveryCellOfTheGridIsSensed) {
  const TextGrid world({
      "...",
      ".R.",
      "...",
  });
  bobtest::ExplorationRun run;
  bobtest::explore(world, Direction::kNorth, Backtrack::kTrail,
                   bobtest::SensorLayout::kFourNeighbors, run);
  EXPECT_EQ(run.stop_reason, StopReason::kAllSensed);
  EXPECT_EQ(run.explorer.unsensed_cells(), 0);
  // North sees both upper corners, back, East sees the lower right one, back, South sees the last
  // and the run ends there, away from the start.
  EXPECT_EQ(run.path, (std::vector<GridCell>{{1, 2}, {1, 1}, {2, 1}, {1, 1}, {1, 0}}));
}

}  // namespace
// Explorer::blocked(): the robot bumped into the cell it was sent to and came back. The cell
// becomes occupied and the explorer chooses again from where the robot is.
TEST(Explorer, ABlockedMoveMarksTheCellOccupiedAndRestoresThePosition) {
  Knowledge k(TextGrid({
                  "?????",
                  "#...#",
                  "#.R.#",
                  "#####",
              }),
              Direction::kNorth);
  Explorer& ex = k.explorer();
  EXPECT_EQ(ex.blocked(), Status::kNotStarted);  // no move yet
  EXPECT_EQ(next(ex), Direction::kNorth);
  EXPECT_EQ(ex.position(), (GridCell{2, 2}));
  EXPECT_EQ(ex.blocked(), Status::kOk);
  EXPECT_EQ(ex.position(), (GridCell{2, 1}));
  EXPECT_EQ(ex.map().state({2, 2}), CellState::kOccupied);
  EXPECT_EQ(ex.moves(), 0u);
  EXPECT_EQ(ex.blocked_moves(), 1u);
  EXPECT_EQ(ex.blocked(), Status::kNotStarted);  // only the last move can be taken back
  Direction d = Direction::kNorth;
  const Status s = ex.next_move(d);
  EXPECT_TRUE(s == Status::kFinished || d != Direction::kNorth);
}

// A cell the robot has stood in stays free (section 3.4); a bump only sends the robot back.
TEST(Explorer, ABlockedMoveIntoAVisitedCellKeepsItVisited) {
  Knowledge k(TextGrid({
                  "##?##",
                  "#.R.?",
                  "#####",
              }),
              Direction::kEast);
  Explorer& ex = k.explorer();
  EXPECT_EQ(next(ex), Direction::kEast);  // to (3, 1)
  const Direction back = next(ex);        // nothing left there: back towards the start
  EXPECT_EQ(back, Direction::kWest);
  EXPECT_EQ(ex.position(), (GridCell{2, 1}));
  EXPECT_EQ(ex.blocked(), Status::kOk);
  EXPECT_EQ(ex.position(), (GridCell{3, 1}));
  EXPECT_EQ(ex.map().state({2, 1}), CellState::kVisited);
  // The body met something on the way into it: an obstacle inside a visited cell, kept in the
  // final map (decision 0008), while the explorer still sends the robot back through it.
  EXPECT_TRUE(ex.obstacle_in_visited({2, 1}));
  EXPECT_TRUE(ex.final_map().occupied({2, 1}));
  EXPECT_EQ(next(ex), Direction::kWest);
}

// Decision 0008: a reading inside a cell the robot stood in (the body passed an obstacle 3-4 cm
// inside the cell's edge) makes the cell occupied in the final map -- what the user gets -- while
// the explorer's navigation is unchanged: the cell stays visited and the trail backtracks
// through it to the start. A cell visited without a detection stays 0.
TEST(Explorer, VisitedCellWithADetectionIsOccupiedInTheFinalMapAndStillTraversable) {
  for (const Backtrack backtrack : {Backtrack::kTrail, Backtrack::kShortestKnownPath}) {
    SCOPED_TRACE(backtrack == Backtrack::kTrail ? "trail" : "map-aware");
    Knowledge k(TextGrid({
                    "#####",
                    "?.R.?",
                    "#####",
                }),
                Direction::kEast, backtrack);
    Explorer& ex = k.explorer();
    EXPECT_EQ(next(ex), Direction::kEast);  // into (3, 1)
    ASSERT_EQ(ex.sense({4, 1}, true), Status::kOk);
    ASSERT_EQ(ex.sense({3, 1}, true), Status::kOk);  // a reading inside the cell it stands in
    EXPECT_EQ(ex.map().state({3, 1}), CellState::kVisited);
    EXPECT_TRUE(ex.obstacle_in_visited({3, 1}));
    EXPECT_FALSE(ex.obstacle_in_visited({2, 1}));
    EXPECT_EQ(next(ex), Direction::kWest);  // back through the start to (1, 1), next to a '?'
    EXPECT_EQ(next(ex), Direction::kWest);
    ASSERT_EQ(ex.sense({0, 1}, true), Status::kOk);  // the last unsensed cell
    Direction d = Direction::kNorth;
    EXPECT_EQ(ex.next_move(d), Status::kFinished);
    const FinalMap& final_map = ex.final_map();
    EXPECT_TRUE(final_map.occupied({3, 1}));
    EXPECT_FALSE(final_map.occupied({2, 1}));
    EXPECT_FALSE(final_map.occupied({1, 1}));
    EXPECT_TRUE(final_map.occupied({4, 1}));
    EXPECT_TRUE(final_map.occupied({0, 1}));
    // write_final_map() hands out the same map.
    std::vector<std::uint8_t> copy(FinalMap::bytes_needed(5, 3), 0xAA);
    ASSERT_EQ(ex.write_final_map(copy.data(), copy.size()), Status::kOk);
    EXPECT_TRUE(std::equal(copy.begin(), copy.end(), final_map.data()));
    EXPECT_EQ(ex.write_final_map(copy.data(), copy.size() - 1), Status::kBufferTooSmall);
  }
}

}  // namespace tessera::bob
