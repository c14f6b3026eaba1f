// Whole explorations of small hand-made worlds with an exact cell sensor: every reachable cell ends
// up sensed, the final 1-bit map is exact, and the map-aware variant is never longer than the
// paper's trail backtracking.

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bob_world.hpp"
#include "tessera/bob/explorer.hpp"
#include "tessera/bob/final_map.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera::bob {
namespace {

using bobtest::ExplorationRun;
using bobtest::SensorLayout;
using bobtest::TextGrid;

struct NamedWorld {
  const char* name;
  Direction heading;
  std::vector<std::string> rows;
};

// 'R' is the start cell. All free cells are reachable from it, so the final map must equal the
// world exactly (solid cells nobody can see are unsensed, and unsensed is 1 in the final map).
std::vector<NamedWorld> hand_made_worlds() {
  return {
      {"room with a pillar",
       Direction::kNorth,
       {"#########", "#.......#", "#.......#", "#..##...#", "#..##...#", "#R......#", "#########"}},
      {"two rooms and a door",
       Direction::kEast,
       {"###########", "#....#....#", "#....#....#", "#.........#", "#....#....#", "#R...#....#",
        "###########"}},
      {"loop round a block",
       Direction::kNorth,
       {"#######", "#.....#", "#.###.#", "#.###.#", "#R....#", "#######"}},
      {"dead ends and alcoves",
       Direction::kEast,
       {"###########", "#.#...#...#", "#.#.#.#.#.#", "#...#...#.#", "###.#####.#", "#R........#",
        "###########"}},
      // Section 4's experiments used an 11 x 14 grid (rows 11 cells wide, 14 rows), open at the
      // grid's edge like the paper's open configurations; firmware/bob/main.cpp runs the same one.
      {"open 11 x 14 lab",
       Direction::kNorth,
       {"...........", "...........", "..###......", "..#........", "..#....##..", "..#....##..",
        "...........", "...........", "......#....", ".....###...", "...........", "..##.......",
        "...........", "R.........."}},
  };
}

/// Checks the end state of a run against the world.
void expect_complete_and_exact(const TextGrid& world, const ExplorationRun& run, const char* what) {
  SCOPED_TRACE(what);
  EXPECT_EQ(run.start_status, Status::kOk);
  EXPECT_EQ(run.last_status, Status::kFinished);
  EXPECT_FALSE(run.hit_wall);
  const std::vector<std::uint8_t> reachable = world.reachable_from(world.find('R'));
  const PackedMap& map = run.explorer.map();
  FinalMap final_map;
  std::vector<std::uint8_t> copy = run.final_map;
  ASSERT_EQ(final_map.init(copy.data(), copy.size(), world.width(), world.height()), Status::kOk);
  ASSERT_EQ(final_map.assign_from(map), Status::kOk);
  // Exact readings of whole cells never place an obstacle inside a visited cell, so the final map
  // the explorer kept is the one the 4-bit map alone gives.
  EXPECT_EQ(copy, run.final_map);
  for (int y = 0; y < world.height(); ++y) {
    for (int x = 0; x < world.width(); ++x) {
      const GridCell c{x, y};
      if (reachable[world.index(c)] != 0) {
        EXPECT_TRUE(map.is_known_free(c)) << "reachable cell not known free: " << x << "," << y;
      }
      EXPECT_EQ(final_map.occupied(c), world.solid(c)) << "final map wrong at " << x << "," << y;
    }
  }
}

TEST(Exploration, EveryHandMadeWorldEndsFullySensedWithAnExactFinalMapForBothVariants) {
  for (const NamedWorld& w : hand_made_worlds()) {
    const TextGrid world(w.rows);
    for (const SensorLayout layout : {SensorLayout::kFourNeighbors, SensorLayout::kSnowplow}) {
      ExplorationRun trail;
      bobtest::explore(world, w.heading, Backtrack::kTrail, layout, trail);
      expect_complete_and_exact(world, trail, w.name);
      ExplorationRun aware;
      bobtest::explore(world, w.heading, Backtrack::kShortestKnownPath, layout, aware);
      expect_complete_and_exact(world, aware, w.name);
    }
  }
}

TEST(Exploration, MapAwareBacktrackingIsNeverLongerThanTrailBacktracking) {
  for (const NamedWorld& w : hand_made_worlds()) {
    const TextGrid world(w.rows);
    for (const SensorLayout layout : {SensorLayout::kFourNeighbors, SensorLayout::kSnowplow}) {
      ExplorationRun trail;
      bobtest::explore(world, w.heading, Backtrack::kTrail, layout, trail);
      ExplorationRun aware;
      bobtest::explore(world, w.heading, Backtrack::kShortestKnownPath, layout, aware);
      EXPECT_LE(aware.moves, trail.moves) << w.name;
    }
  }
}

TEST(Exploration, TrailBacktrackingEndsAtTheStartInClosedWorlds) {
  for (const NamedWorld& w : hand_made_worlds()) {
    if (w.rows.front().find('#') == std::string::npos) continue;  // open world: condition (ii)
    const TextGrid world(w.rows);
    ExplorationRun run;
    bobtest::explore(world, w.heading, Backtrack::kTrail, SensorLayout::kFourNeighbors, run);
    EXPECT_EQ(run.stop_reason, StopReason::kBackAtStart) << w.name;
    EXPECT_EQ(run.explorer.position(), world.find('R')) << w.name;
  }
}

// The snowplow layout cannot see the cell behind the start at rest: the robot must come back to
// the start to chart it, and then explore what lies behind.
TEST(Exploration, SnowplowSensingChartsTheCellBehindTheStartOnTheWayBack) {
  const TextGrid world({
      "#####",
      "#...#",
      "#.#.#",
      "#R#.#",
      "#.###",
      "#####",
  });
  for (const Backtrack b : {Backtrack::kTrail, Backtrack::kShortestKnownPath}) {
    ExplorationRun run;
    bobtest::explore(world, Direction::kNorth, b, SensorLayout::kSnowplow, run);
    expect_complete_and_exact(world, run, b == Backtrack::kTrail ? "trail" : "map-aware");
    EXPECT_EQ(run.explorer.map().state({1, 1}), CellState::kVisited);
  }
}

// A built-in floor plan at the paper's 0.22 m cell: a real-sized maze for the explorer.
TEST(Exploration, LabyrinthAtPaperCellSizeIsFullyExploredByBothVariants) {
  const World maze = builtin_world("labyrinth", 0.22);
  ASSERT_GT(maze.geometry().width(), 0);
  const int w = maze.geometry().width();
  const int h = maze.geometry().height();
  std::vector<std::string> rows;
  for (int y = h - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < w; ++x) row += maze.solid(Cell{x, y}) ? '#' : '.';
    rows.push_back(row);
  }
  // Start in the first free cell whose North neighbour is free too.
  bool placed = false;
  for (int y = 0; y < h - 1 && !placed; ++y) {
    for (int x = 0; x < w && !placed; ++x) {
      if (maze.free(Cell{x, y}) && maze.free(Cell{x, y + 1})) {
        rows[static_cast<std::size_t>(h - 1 - y)][static_cast<std::size_t>(x)] = 'R';
        placed = true;
      }
    }
  }
  ASSERT_TRUE(placed);
  const TextGrid world(rows);
  const std::vector<std::uint8_t> reachable = world.reachable_from(world.find('R'));
  for (const Backtrack b : {Backtrack::kTrail, Backtrack::kShortestKnownPath}) {
    ExplorationRun run;
    bobtest::explore(world, Direction::kNorth, b, SensorLayout::kSnowplow, run);
    EXPECT_EQ(run.last_status, Status::kFinished);
    EXPECT_FALSE(run.hit_wall);
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        if (reachable[world.index({x, y})] != 0) {
          EXPECT_TRUE(run.explorer.map().is_known_free({x, y})) << x << "," << y;
        }
      }
    }
  }
}

}  // namespace
}  // namespace tessera::bob
