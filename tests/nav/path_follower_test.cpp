#include "tessera/nav/path_follower.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "taught_corridor.hpp"
#include "tessera/fusion/hex_cell_map.hpp"
#include "tessera/nav/cell_polyline.hpp"
#include "tessera/nav/greedy_cell_controller.hpp"
#include "tessera/nav/wavefront.hpp"
#include "unicycle.hpp"

namespace tessera {
namespace {

constexpr double kDt = 0.1;  // 10 Hz, the rate of the P3DX's odometry messages

TEST(PathFollower, DrivesAnLShapedPolylineAndStopsWithinTheGoalTolerance) {
  PathFollower follower({{0, 0}, {2, 0}, {2, 1.5}});
  const nav_test::DriveResult r = nav_test::drive(follower, {0.0, 0.0, 0.0}, kDt, 60.0);
  ASSERT_TRUE(r.arrived);
  EXPECT_LT((r.poses.back().translation() - Vec2{2, 1.5}).norm(), 0.05);
  EXPECT_LT(r.length_m, 1.1 * 3.5);
  EXPECT_LE(r.heading_reversals, 1);  // the 90 degree corner: at most one overshoot, no swinging
  // Once arrived it stays stopped.
  const VelocityCommand c = follower.command({5.0, 5.0, 0.0});
  EXPECT_EQ(c.v_m_per_s, 0.0);
  EXPECT_EQ(c.omega_rad_per_s, 0.0);
}

TEST(PathFollower, ProgressNeverMovesBackwardsSoBorderCrossingsDoNotChangeTheTarget) {
  PathFollower follower({{0, 0}, {1, 0}, {2, 0}});
  (void)follower.command({1.2, 0.0, 0.0});
  EXPECT_NEAR(follower.progress_m(), 1.2, 1e-12);
  // Pushed back behind where it was (e.g. by avoidance): the target stays ahead of 1.2 m.
  (void)follower.command({0.5, 0.1, 0.0});
  EXPECT_NEAR(follower.progress_m(), 1.2, 1e-12);
  // Cross-track is measured to the path ahead of the progress point: here its start, (1, 0).
  EXPECT_NEAR(follower.cross_track_m(), std::hypot(0.5, 0.1), 1e-12);
}

TEST(PathFollower, TurnRateIsLimitedAndALargeHeadingErrorTurnsInPlace) {
  PathFollowerOptions o;
  o.max_turn_rate_rad_per_s = 0.4;
  PathFollower follower({{0, 0}, {3, 0}}, o);
  const VelocityCommand behind = follower.command({0.0, 0.0, 3.0});  // facing backwards
  EXPECT_EQ(behind.v_m_per_s, 0.0);
  EXPECT_NEAR(std::abs(behind.omega_rad_per_s), 0.4, 1e-12);
  const VelocityCommand ahead = follower.command({0.0, 0.0, 0.0});
  EXPECT_NEAR(ahead.v_m_per_s, o.max_speed_m_per_s, 1e-9);
  EXPECT_NEAR(ahead.omega_rad_per_s, 0.0, 1e-9);
}

TEST(PathFollowerOptions, ValidateNamesTheBadField) {
  EXPECT_FALSE(validate(PathFollowerOptions{}).has_value());
  PathFollowerOptions o;
  o.lookahead_m = 0.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("lookahead_m"));
  o = {};
  o.min_speed_fraction = 1.5;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("min_speed_fraction"));
}

// Thesis sections 5.2.1 / 6.1 / 6.2 item 3: on a taught corridor whose cells tie in wavefront value
// at a border lying on the straight line to the goal, the thesis' navigation (re-deciding the best
// neighbour at every border and facing it, GreedyCellController) swings its heading at every cell;
// committing to the cell path and following its line-of-sight polyline (PathFollower) drives
// straight, within 1.15 x the cell-path length (the bar). Same robot and limits.
TEST(PathFollower, DrivesATiedCorridorStraightWhereTheThesisNavigationZigzags) {
  const fusion::HexCellMap map = nav_test::taught_corridor(nav_test::corridor_length_m());
  const CellGraph g = map.graph(fusion::CellAdjacency::kTraversed);
  const std::size_t goal = *map.find(map.lattice().cell_at({nav_test::corridor_length_m(), 0.0}));
  const WavefrontField field = wavefront(g, goal);
  const std::vector<std::size_t> cells = wavefront_path(g, field, 0);
  const double cell_path_m = cell_path_length_m(g, cells);
  const Pose2 start{g.centres_m[0].x, g.centres_m[0].y, 0.0};
  // The tie: between consecutive shared cells the path has a choice of two cells of equal value.
  ASSERT_GE(cells.size(), 13u);
  int ties = 0;
  for (std::size_t i = 0; i + 1 < cells.size(); ++i) {
    int best = 0;
    for (const std::size_t n : g.adjacent[cells[i]]) {
      if (field.value[n] == field.value[cells[i]] + 1) ++best;
    }
    if (best >= 2) ++ties;
  }
  EXPECT_GE(ties, 5);

  GreedyCellController greedy(g, goal);  // thesis: face the best neighbour, drive, re-decide
  const nav_test::DriveResult thesis = nav_test::drive(greedy, start, kDt, 300.0);
  GreedyCellControllerOptions smooth_options;
  smooth_options.turn_then_drive = false;  // the same re-deciding with our smooth heading law
  GreedyCellController smooth(g, goal, smooth_options);
  const nav_test::DriveResult greedy_smooth = nav_test::drive(smooth, start, kDt, 300.0);
  PathFollower follower(cell_path_polyline(g, cells, start.translation(), g.centres_m[goal]));
  const nav_test::DriveResult ours = nav_test::drive(follower, start, kDt, 300.0);

  const auto record = [&](const std::string& name, const nav_test::DriveResult& r) {
    ::testing::Test::RecordProperty(name + "_length_ratio",
                                    std::to_string(r.length_m / cell_path_m));
    ::testing::Test::RecordProperty(name + "_reversals", std::to_string(r.heading_reversals));
    ::testing::Test::RecordProperty(name + "_time_s", std::to_string(r.time_s));
    ::testing::Test::RecordProperty(name + "_arrived", r.arrived ? "true" : "false");
  };
  ::testing::Test::RecordProperty("cell_path_m", std::to_string(cell_path_m));
  ::testing::Test::RecordProperty("cells", std::to_string(cells.size()));
  record("thesis", thesis);
  record("thesis_smooth_heading", greedy_smooth);
  record("ours", ours);

  ASSERT_TRUE(ours.arrived);
  EXPECT_LE(ours.length_m / cell_path_m, 1.15);
  EXPECT_EQ(ours.heading_reversals, 0);
  EXPECT_LT((ours.poses.back().translation() - g.centres_m[goal]).norm(), 0.05);

  // The baseline reproduces the thesis' complaint: a heading swing at (nearly) every cell, and a
  // longer, slower drive.
  EXPECT_TRUE(thesis.arrived);
  EXPECT_GE(thesis.heading_reversals, static_cast<int>(cells.size()) / 2);
  EXPECT_GT(thesis.length_m, ours.length_m);
  EXPECT_GT(thesis.time_s, ours.time_s);
}

}  // namespace
}  // namespace tessera
