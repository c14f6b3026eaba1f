#include "tessera/sim/team_starts.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "support/text_world.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

// A 4 m x 3 m room of 0.1 m cells, walls all round.
World room() {
  std::vector<std::string> rows(30, "#" + std::string(38, '.') + "#");
  rows.front() = rows.back() = std::string(40, '#');
  return support::text_world(rows, 0.1);
}

TEST(TeamStarts, RobotsStartTogetherApartWithRoomOnTheMapLattice) {
  const World world = room();
  Result<std::vector<Pose2>> starts = team_starts(world, 3, 0.3, 0.6, 0.05);
  ASSERT_TRUE(starts.ok()) << starts.error().message;
  ASSERT_EQ(starts->size(), 3u);
  // The first near the room's centre; all within a couple of metres of it.
  EXPECT_NEAR((*starts)[0].x, 2.0, 0.1);
  EXPECT_NEAR((*starts)[0].y, 1.5, 0.1);
  for (std::size_t i = 0; i < 3; ++i) {
    const Pose2& s = (*starts)[i];
    // Centres of 0.05 m lattice cells: x = (k + 0.5) * 0.05.
    EXPECT_NEAR(std::fmod(s.x, 0.05), 0.025, 1e-9) << i;
    EXPECT_NEAR(std::fmod(s.y, 0.05), 0.025, 1e-9) << i;
    for (std::size_t j = 0; j < i; ++j) {
      EXPECT_GE(std::hypot(s.x - (*starts)[j].x, s.y - (*starts)[j].y), 0.6);
    }
    EXPECT_LT(std::hypot(s.x - 2.0, s.y - 1.5), 2.0);
  }
  // The same world, the same starts (a team of one starts where a team's first robot does).
  Result<std::vector<Pose2>> one = team_starts(world, 1, 0.3, 0.6, 0.05);
  ASSERT_TRUE(one.ok());
  EXPECT_EQ((*one)[0].x, (*starts)[0].x);
  EXPECT_EQ((*one)[0].y, (*starts)[0].y);
}

TEST(TeamStarts, TooManyRobotsOrNoRoomAreInputErrors) {
  const World world = room();
  Result<std::vector<Pose2>> many = team_starts(world, 40, 0.3, 0.6, 0.05);
  ASSERT_FALSE(many.ok());
  EXPECT_EQ(many.error().kind, ErrorKind::kInput);
  EXPECT_THAT(many.error().message, HasSubstr("40 asked"));
  Result<std::vector<Pose2>> none = team_starts(world, 1, 5.0, 0.6, 0.05);
  ASSERT_FALSE(none.ok());
  EXPECT_THAT(none.error().message, HasSubstr("no room for a robot"));
}

}  // namespace
}  // namespace tessera
