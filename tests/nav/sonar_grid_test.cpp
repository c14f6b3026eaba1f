#include "tessera/nav/sonar_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace tessera {
namespace {

constexpr double kNoEcho = std::numeric_limits<double>::infinity();

// A robot at (0, 0) facing +x with one sonar straight ahead on its edge (0.2 m out).
std::vector<ObstacleRange> ahead(double range_m) { return {{0.0, range_m}}; }

TEST(SonarGrid, AnEchoMarksItsArcOccupiedAndTheConeBeforeItFree) {
  SonarGrid grid;
  for (int i = 0; i < 3; ++i) grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(1.0));
  // The echo is 1.0 m from the sonar at x = 0.2 m: the wall at x = 1.2 m.
  EXPECT_TRUE(grid.occupied({1.21, 0.01}));
  EXPECT_LT(grid.log_odds({0.7, 0.01}), 0.0);  // free space in front of it
  EXPECT_EQ(grid.log_odds({1.6, 0.01}), 0.0);  // behind it: never seen
  EXPECT_EQ(grid.log_odds({0.7, 0.5}), 0.0);   // outside the cone
}

TEST(SonarGrid, OneEchoIsNotEnoughTwoAre) {
  SonarGrid grid;
  grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(1.0));
  EXPECT_FALSE(grid.occupied({1.21, 0.01}));
  grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(1.0));
  EXPECT_TRUE(grid.occupied({1.21, 0.01}));
}

TEST(SonarGrid, ConesThatSeePastAPhantomEchoClearIt) {
  SonarGrid grid;
  for (int i = 0; i < 3; ++i) grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(1.0));
  ASSERT_TRUE(grid.occupied({1.21, 0.01}));
  // Later sweeps read nothing there (the echo came from a wall aslant, now seen past).
  for (int i = 0; i < 6; ++i) grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(kNoEcho));
  EXPECT_FALSE(grid.occupied({1.21, 0.01}));
}

TEST(SonarGrid, TheRobotsPoseAndTheSonarsBearingPlaceTheEcho) {
  SonarGrid grid;
  // At (5, 5) facing +y, the sonar at +90 degrees (left) points to -x.
  const Pose2 T_map_robot{5.0, 5.0, std::numbers::pi / 2};
  for (int i = 0; i < 3; ++i) grid.insert(T_map_robot, {{std::numbers::pi / 2, 0.5}});
  EXPECT_TRUE(grid.occupied({4.31, 5.01}));  // 0.2 m edge + 0.5 m range
  EXPECT_FALSE(grid.occupied({5.69, 5.01}));
}

TEST(SonarGrid, OccupiedWithinListsTheOccupiedCellsInTheDiscSorted) {
  SonarGrid grid;
  for (int i = 0; i < 3; ++i) grid.insert(Pose2{0.0, 0.0, 0.0}, ahead(1.0));
  const std::vector<Vec2> near = grid.occupied_within({1.2, 0.0}, 0.3);
  ASSERT_FALSE(near.empty());
  for (std::size_t i = 0; i < near.size(); ++i) {
    EXPECT_LE((near[i] - Vec2{1.2, 0.0}).norm(), 0.3);
    EXPECT_TRUE(grid.occupied(near[i]));
    if (i > 0) {
      EXPECT_TRUE(near[i - 1].x < near[i].x ||
                  (near[i - 1].x == near[i].x && near[i - 1].y < near[i].y));
    }
  }
  EXPECT_TRUE(grid.occupied_within({-3.0, 0.0}, 0.5).empty());
}

TEST(SonarGrid, ValidateNamesTheBadField) {
  SonarGridOptions o;
  EXPECT_FALSE(validate(o));
  o.half_cone_rad = 2.0;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("half_cone_rad"), std::string::npos);
  o = {};
  o.free_log_odds = 0.1;
  ASSERT_TRUE(validate(o));
  EXPECT_NE(validate(o)->find("free_log_odds"), std::string::npos);
}

}  // namespace
}  // namespace tessera
