#include "tessera/team/map_match.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "tessera/core/angle.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/lidar_scan.hpp"

namespace tessera::team {
namespace {

// A robot's map of the office in its own map frame (its start pose), from scans taken at
// `poses_world`: what a teammate publishes, without the SLAM.
OccupancyGrid seen_map(const World& world, const Pose2& T_world_start,
                       const std::vector<Pose2>& poses_world, std::uint64_t seed) {
  OccupancyGrid map(GridGeometry({-20.0, -20.0}, 0.05, 800, 800));
  Rng rng(seed);
  const LidarOptions lidar;
  for (int pass = 0; pass < 3; ++pass) {
    for (const Pose2& p : poses_world) {
      const RangeScan scan = simulate_lidar_scan(world, p, lidar, rng);
      insert_scan(map, T_world_start.inverse() * p, scan, {}, nullptr);
    }
  }
  return map;
}

const World& office() {
  static const World w = builtin_world("office", 0.05);
  return w;
}

// Robot A has seen the corridor's west half and the hall; robot B, started elsewhere and turned,
// the corridor's east half and the hall's middle. They share the corridor around x = 4.5 m and
// part of the hall.
const Pose2 kStartA{1.5, 7.1, 0.0};
const Pose2 kStartB{8.0, 4.0, 2.0};
OccupancyGrid map_a() {
  return seen_map(office(), kStartA, {kStartA, {4.5, 7.1, 0.3}, {4.5, 4.5, 1.0}, {2.0, 4.5, 0.0}},
                  1);
}
OccupancyGrid map_b() {
  return seen_map(office(), kStartB, {kStartB, {7.0, 7.1, 0.0}, {4.5, 7.1, 2.0}, {4.5, 4.5, 0.5}},
                  2);
}

TEST(MapMatch, FindsWhereATeammateStartedFromTheMapsAlone) {
  const Result<std::optional<MapMatch>> m = match_maps(map_a(), map_b());
  ASSERT_TRUE(m.ok()) << m.error().message;
  ASSERT_TRUE(m->has_value());
  const MapMatch& match = **m;
  const Pose2 truth = kStartA.inverse() * kStartB;
  std::printf(
      "found %.3f %.3f %.4f, truth %.3f %.3f %.4f; overlap %.1f m2, conflict %.4f, "
      "walls %.3f\n",
      match.T_fixed_moving.x, match.T_fixed_moving.y, match.T_fixed_moving.theta, truth.x, truth.y,
      truth.theta, match.overlap_m2, match.conflict, match.wall_agreement);
  EXPECT_NEAR(match.T_fixed_moving.x, truth.x, 0.05);
  EXPECT_NEAR(match.T_fixed_moving.y, truth.y, 0.05);
  EXPECT_NEAR(normalize_angle(match.T_fixed_moving.theta - truth.theta), 0.0, 0.01);
  EXPECT_TRUE(match.accepted) << "overlap " << match.overlap_m2 << " m2, conflict "
                              << match.conflict << ", walls " << match.wall_agreement;
  EXPECT_GE(match.overlap_m2, 6.0);
  EXPECT_LE(match.conflict, 0.01);
}

TEST(MapMatch, AWrongPlacementConflictsAndIsRefused) {
  const OccupancyGrid a = map_a(), b = map_b();
  const Pose2 truth = kStartA.inverse() * kStartB;
  EXPECT_TRUE(judge_map_match(a, b, truth).accepted);
  for (const Pose2& off : {Pose2{0.6, 0.0, 0.0}, Pose2{0.0, -0.8, 0.0}, Pose2{0.0, 0.0, 0.2}}) {
    const MapMatch m = judge_map_match(a, b, off * truth);
    EXPECT_FALSE(m.accepted) << off.x << " " << off.y << " " << off.theta << ": conflict "
                             << m.conflict << ", walls " << m.wall_agreement;
  }
}

// Two rooms of different size, each seen by one robot only: there is nothing to match, and no
// placement may be accepted (a rectangle fits into another by its corners).
TEST(MapMatch, MapsOfDifferentPlacesAreNotAccepted) {
  const Pose2 start_a{2.5, 10.0, 0.0};
  const OccupancyGrid a = seen_map(office(), start_a, {start_a, {3.5, 10.5, 1.0}}, 3);
  const Pose2 start_b{12.0, 2.0, -1.0};
  const OccupancyGrid b = seen_map(office(), start_b, {start_b, {13.5, 4.0, 0.5}}, 4);
  const Result<std::optional<MapMatch>> m = match_maps(a, b);
  ASSERT_TRUE(m.ok()) << m.error().message;
  if (m->has_value()) {
    std::printf("best: overlap %.1f m2, conflict %.4f, walls %.3f\n", (*m)->overlap_m2,
                (*m)->conflict, (*m)->wall_agreement);
    EXPECT_FALSE((*m)->accepted) << "overlap " << (*m)->overlap_m2 << " m2, conflict "
                                 << (*m)->conflict << ", walls " << (*m)->wall_agreement;
  }
}

TEST(MapMatch, EmptyMapsHaveNoMatchAndOtherResolutionsAreInputErrors) {
  const OccupancyGrid a = map_a();
  const Result<std::optional<MapMatch>> empty =
      match_maps(a, OccupancyGrid(GridGeometry({0.0, 0.0}, 0.05, 10, 10)));
  ASSERT_TRUE(empty.ok());
  EXPECT_FALSE(empty->has_value());
  const Result<std::optional<MapMatch>> coarse =
      match_maps(a, OccupancyGrid(GridGeometry({0.0, 0.0}, 0.1, 10, 10)));
  ASSERT_FALSE(coarse.ok());
  EXPECT_EQ(coarse.error().kind, ErrorKind::kInput);
  EXPECT_NE(coarse.error().message.find("resolutions differ"), std::string::npos);
  MapMatchOptions bad;
  bad.free_below = 0.8;
  EXPECT_FALSE(match_maps(a, a, bad).ok());
}

}  // namespace
}  // namespace tessera::team
