#include "tessera/bob/direction.hpp"

#include <gtest/gtest.h>

namespace tessera::bob {
namespace {

TEST(Direction, ClockwiseOrderStartsNorthAndNorthIsPlusY) {
  EXPECT_EQ(kClockwiseFromNorth[0], Direction::kNorth);
  EXPECT_EQ(kClockwiseFromNorth[1], Direction::kEast);
  EXPECT_EQ(kClockwiseFromNorth[2], Direction::kSouth);
  EXPECT_EQ(kClockwiseFromNorth[3], Direction::kWest);
  EXPECT_EQ(step({3, 4}, Direction::kNorth), (GridCell{3, 5}));
  EXPECT_EQ(step({3, 4}, Direction::kEast), (GridCell{4, 4}));
  EXPECT_EQ(step({3, 4}, Direction::kSouth), (GridCell{3, 3}));
  EXPECT_EQ(step({3, 4}, Direction::kWest), (GridCell{2, 4}));
}

TEST(Direction, TurnsCountQuarterTurnsAndAReversalCountsTwo) {
  EXPECT_EQ(quarter_turns(Direction::kNorth, Direction::kNorth), 0);
  EXPECT_EQ(quarter_turns(Direction::kNorth, Direction::kEast), 1);
  EXPECT_EQ(quarter_turns(Direction::kNorth, Direction::kWest), 1);
  EXPECT_EQ(quarter_turns(Direction::kEast, Direction::kWest), 2);
  EXPECT_EQ(opposite(Direction::kSouth), Direction::kNorth);
  EXPECT_EQ(clockwise(Direction::kWest), Direction::kNorth);
  EXPECT_EQ(counter_clockwise(Direction::kNorth), Direction::kWest);
}

}  // namespace
}  // namespace tessera::bob
