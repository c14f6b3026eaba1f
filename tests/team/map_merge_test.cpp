#include "tessera/team/map_merge.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tessera::team {
namespace {

using ::testing::HasSubstr;

// A w x h map of 0.1 m cells, every cell `value`, its lower-left corner at the map frame's origin.
OccupancyGridMessage grid(std::uint32_t w, std::uint32_t h, std::int8_t value) {
  OccupancyGridMessage m;
  m.resolution_m = 0.1F;
  m.width = w;
  m.height = h;
  m.data.assign(std::size_t{w} * h, value);
  return m;
}

std::int8_t& at(OccupancyGridMessage& m, std::uint32_t x, std::uint32_t y) {
  return m.data[std::size_t{y} * m.width + x];
}

TEST(MapMerger, MapsAtKnownPosesCoverTheUnionOverlapsAddAndObstaclesAreKept) {
  MapMerger team(0.1);
  OccupancyGridMessage a = grid(20, 10, 20);  // 2 m x 1 m, free-ish
  at(a, 15, 5) = 70;                          // one hit at (1.55, 0.55) in a's frame
  OccupancyGridMessage b = grid(20, 10, 20);
  ASSERT_TRUE(team.update("r1", a, Pose2{}).ok());
  ASSERT_TRUE(team.update("r2", b, Pose2{1.0, 0.0, 0.0}).ok());  // b's frame 1 m further in x
  EXPECT_EQ(team.robots(), 2U);
  const OccupancyGrid merged = team.merged();
  ASSERT_EQ(merged.geometry().width(), 30);
  ASSERT_EQ(merged.geometry().height(), 10);
  // Seen by r1 only, by both, by r2 only.
  EXPECT_NEAR(*merged.probability_at({2, 2}), 0.2, 1e-6);
  const double both = probability(2.0F * log_odds(0.2));
  EXPECT_NEAR(*merged.probability_at({12, 2}), both, 1e-6);
  EXPECT_NEAR(*merged.probability_at({25, 2}), 0.2, 1e-6);
  // r1's occupied cell where r2 saw free: the obstacle is kept (a planner must not drive into
  // it); r1's weaker evidence (0.6 < kKeptOccupied) with r2's free adds up.
  EXPECT_NEAR(*merged.probability_at({15, 5}), 0.7, 1e-6);
  at(a, 16, 5) = 60;
  ASSERT_TRUE(team.update("r1", a, Pose2{}).ok());
  EXPECT_NEAR(*team.merged().probability_at({16, 5}), probability(log_odds(0.6) + log_odds(0.2)),
              1e-6);
  // Two robots that both see it occupied add their evidence.
  OccupancyGridMessage c = grid(20, 10, 20);
  at(c, 5, 5) = 70;
  ASSERT_TRUE(team.update("r2", c, Pose2{1.0, 0.0, 0.0}).ok());
  EXPECT_NEAR(*team.merged().probability_at({15, 5}), probability(2.0F * log_odds(0.7)), 1e-6);
}

TEST(MapMerger, ARotatedMapLandsOnTheRightCellsAndUnknownStaysUnknown) {
  MapMerger team(0.1);
  OccupancyGridMessage a = grid(10, 10, -1);  // 1 m x 1 m, unknown but one wall cell
  at(a, 8, 1) = 100;                          // centre (0.85, 0.15) in a's frame
  // a's frame turned by 90 degrees about the team origin: (0.85, 0.15) -> (-0.15, 0.85).
  ASSERT_TRUE(team.update("r1", a, Pose2{0.0, 0.0, std::numbers::pi / 2}).ok());
  const OccupancyGrid merged = team.merged();
  const GridGeometry& g = merged.geometry();
  ASSERT_EQ(g.width(), 10);
  const Cell wall = g.cell_at_unchecked({-0.15, 0.85});
  ASSERT_TRUE(merged.known(wall));
  EXPECT_GT(*merged.probability_at(wall), 0.99);
  std::size_t known = 0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) known += merged.known({x, y}) ? 1 : 0;
  }
  EXPECT_EQ(known, 1U);
}

TEST(MapMerger, AMapOfAnotherResolutionOrInconsistentSizeIsRefused) {
  MapMerger team(0.05);
  const Status coarse = team.update("r2", grid(4, 4, 0), Pose2{});
  ASSERT_FALSE(coarse.ok());
  EXPECT_EQ(coarse.error().kind, ErrorKind::kInput);
  EXPECT_THAT(coarse.error().message, HasSubstr("map of r2: resolution 0.1"));
  MapMerger fine(0.1);
  OccupancyGridMessage short_data = grid(4, 4, 0);
  short_data.data.pop_back();
  EXPECT_THAT(fine.update("r3", short_data, Pose2{}).error().message, HasSubstr("4 x 4 cells"));
  EXPECT_THAT(fine.update("r3", grid(2, 2, 0), Pose2{std::nan(""), 0, 0}).error().message,
              HasSubstr("not finite"));
  EXPECT_EQ(fine.robots(), 0U);
  EXPECT_EQ(fine.merged().geometry().size(), 0U);
}

TEST(MapMerger, ARobotsNewerMapReplacesItsOlderOne) {
  MapMerger team(0.1);
  ASSERT_TRUE(team.update("r1", grid(2, 2, 90), Pose2{}).ok());
  ASSERT_TRUE(team.update("r1", grid(2, 2, 10), Pose2{}).ok());
  EXPECT_NEAR(*team.merged().probability_at({0, 0}), 0.1, 1e-6);
}

}  // namespace
}  // namespace tessera::team
