#include "tessera/slam/loop_closer.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "laser_test_world.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera::slam {
namespace {

using testing::furnished_room;
using testing::grid_from_scans;
using testing::ideal_scan;
using testing::kT_grid_world;

/// A finished submap: the room seen from a dozen poses along a loop, so walls are well known.
ProbabilityGrid room_submap(const World& room) {
  std::vector<Pose2> poses;
  for (int i = 0; i < 12; ++i) {
    const double a = 2.0 * std::numbers::pi * i / 12.0;
    poses.push_back({4.0 + 2.0 * std::cos(a), 4.0 + 1.5 * std::sin(a), a + 1.0});
  }
  return grid_from_scans(room, poses);
}

std::vector<Vec2> points_of(const World& world, const Pose2& T_world_robot) {
  return scan_to_points(ideal_scan(world, T_world_robot), {}, ScanPointsOptions{}).returns_m;
}

// A revisit 0.6 m and 8.6 degrees away from where the estimate puts it is found and refined to
// sub-cell accuracy.
TEST(LoopCloser, FindsAKnownClosure) {
  const World room = furnished_room();
  const ProbabilityGrid grid = room_submap(room);
  LoopCloser closer(LoopCloserOptions{});
  closer.add_submap(7, grid);
  EXPECT_TRUE(closer.has_submap(7));
  EXPECT_GT(closer.memory_bytes(), grid.values().size());
  const Pose2 truth_world{5.0, 3.0, -0.7};
  const Pose2 truth = kT_grid_world * truth_world;
  const Pose2 guess{truth.x + 0.5, truth.y - 0.35, truth.theta + 0.15};
  const std::vector<Vec2> points = points_of(room, truth_world);
  const std::optional<LoopMatch> m =
      closer.match(7, grid, guess, voxel_filter(points, 0.2), points);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->T_submap_robot.x, truth.x, 0.02);
  EXPECT_NEAR(m->T_submap_robot.y, truth.y, 0.02);
  EXPECT_NEAR(m->T_submap_robot.theta, truth.theta, 0.005);
  EXPECT_GE(m->refined_score, closer.options().min_score);
}

// A scan of another building does not reach the score threshold anywhere in the window, and a
// scan of this room from a pose far outside the window is not forced onto its edge.
TEST(LoopCloser, RejectsAWrongPlace) {
  const World room = furnished_room();
  const ProbabilityGrid grid = room_submap(room);
  LoopCloser closer(LoopCloserOptions{});
  closer.add_submap(0, grid);
  const World office = builtin_world("office", 0.05);
  Pose2 elsewhere{0.0, 0.0, 0.3};  // the first free cell near the office's middle
  for (double dx = 0.0; dx < 4.0 && elsewhere.x == 0.0; dx += 0.25) {
    const Vec2 p{8.0 + dx, 6.0};
    if (!office.solid(office.geometry().cell_at_unchecked(p))) elsewhere = {p.x, p.y, 0.3};
  }
  ASSERT_NE(elsewhere.x, 0.0);
  const std::vector<Vec2> foreign = points_of(office, elsewhere);
  const Pose2 guess = kT_grid_world * Pose2{5.0, 3.0, -0.7};
  EXPECT_FALSE(closer.match(0, grid, guess, voxel_filter(foreign, 0.2), foreign).has_value());

  const Pose2 truth_world{4.5, 4.5, 2.0};
  const std::vector<Vec2> points = points_of(room, truth_world);
  ASSERT_TRUE(closer.match(0, grid, kT_grid_world * truth_world, voxel_filter(points, 0.2), points)
                  .has_value());
  const Pose2 far_guess = kT_grid_world * Pose2{10.0, 4.0, 2.0};  // 5.5 m off, window 2 m
  EXPECT_FALSE(closer.match(0, grid, far_guess, voxel_filter(points, 0.2), points).has_value());
}

TEST(LoopCloserOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(LoopCloserOptions{}).has_value());
  LoopCloserOptions o;
  o.min_score = 0.95;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("min_score"));
  o = {};
  o.branch_and_bound_depth = 0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("branch_and_bound_depth"));
}

}  // namespace
}  // namespace tessera::slam
