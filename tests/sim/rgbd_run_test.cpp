#include "tessera/sim/rgbd_run.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "sim/rgbd_room.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

RgbdRunOptions square_drive() {
  RgbdRunOptions o;
  o.start = {1.0, 1.0, 0.0};
  o.waypoints_m = {{5.0, 1.0}, {5.0, 3.5}, {1.0, 3.5}, {1.0, 1.0}};
  o.frame_rate_hz = 2.0;
  return o;
}

TEST(RgbdRun, DrivesEveryWaypointAndRecordsAtTheFrameRate) {
  const World room = support::rgbd_room();
  const Result<SimulatedRgbdRun> run = simulate_rgbd_run(room, square_drive(), 3);
  ASSERT_TRUE(run.ok()) << run.error().message;
  EXPECT_TRUE(run->completed);
  const Pose2 end = run->frames.back().truth;
  EXPECT_NEAR(end.x, 1.0, 0.02);
  EXPECT_NEAR(end.y, 1.0, 0.02);
  EXPECT_NEAR(run->path_length_m, 13.0, 0.1);
  for (std::size_t i = 0; i < run->frames.size(); ++i) {
    EXPECT_DOUBLE_EQ(run->frames[i].t_s, static_cast<double>(i) / 2.0);
  }
  // 13 m at 0.3 m/s plus four turns: about a minute.
  EXPECT_GT(run->duration_s, 13.0 / 0.3);
  EXPECT_LT(run->duration_s, 13.0 / 0.3 + 30.0);
}

TEST(RgbdRun, OdometryDriftsWithTheThesisPresetAndNotWhenPerfect) {
  const World room = support::rgbd_room();
  RgbdRunOptions o = square_drive();
  const Result<SimulatedRgbdRun> drifting = simulate_rgbd_run(room, o, 3);
  o.odometry = perfect_odometry();
  const Result<SimulatedRgbdRun> perfect = simulate_rgbd_run(room, o, 3);
  ASSERT_TRUE(drifting.ok() && perfect.ok());
  const RgbdRunFrame& d = drifting->frames.back();
  EXPECT_GT(std::hypot(d.odometry.x - d.truth.x, d.odometry.y - d.truth.y), 0.2);
  const RgbdRunFrame& p = perfect->frames.back();
  EXPECT_NEAR(p.odometry.x, p.truth.x, 1e-9);
  EXPECT_NEAR(p.odometry.y, p.truth.y, 1e-9);
}

TEST(RgbdRun, SameSeedSameRunAnotherSeedOtherOdometry) {
  const World room = support::rgbd_room();
  const auto a = simulate_rgbd_run(room, square_drive(), 5);
  const auto b = simulate_rgbd_run(room, square_drive(), 5);
  const auto c = simulate_rgbd_run(room, square_drive(), 6);
  ASSERT_EQ(a->frames.size(), b->frames.size());
  for (std::size_t i = 0; i < a->frames.size(); ++i) {
    EXPECT_EQ(a->frames[i].odometry.x, b->frames[i].odometry.x);
    EXPECT_EQ(a->frames[i].truth.y, b->frames[i].truth.y);
  }
  EXPECT_NE(a->frames.back().odometry.x, c->frames.back().odometry.x);
}

TEST(RgbdRun, FramesRenderTheSameInAnyOrder) {
  const World room = support::rgbd_room();
  RgbdRunOptions o = square_drive();
  o.neck_sweep_amplitude_rad = 0.5;
  const auto run = simulate_rgbd_run(room, o, 2);
  ASSERT_TRUE(run.ok());
  const RgbdCamera cam = support::room_camera({}, /*noise=*/true);
  const RgbdFrame late = render_rgbd_run_frame(cam, *run, 10);
  const RgbdFrame early = render_rgbd_run_frame(cam, *run, 3);
  const RgbdFrame late_again = render_rgbd_run_frame(cam, *run, 10);
  EXPECT_EQ(late.depth_m, late_again.depth_m);
  EXPECT_EQ(late.rgb, late_again.rgb);
  EXPECT_NE(late.depth_m, early.depth_m);
  EXPECT_DOUBLE_EQ(late.t_s, run->frames[10].t_s);
  // The neck sweeps: pan(t) = 0.5 sin(2 pi t / 10 s).
  EXPECT_NEAR(run->frames[5].neck_pan_rad, 0.5 * std::sin(2.0 * std::numbers::pi * 2.5 / 10.0),
              1e-12);
}

TEST(RgbdRun, FollowsATourWhenNoWaypointsAreGiven) {
  const World room = support::rgbd_room();
  RgbdRunOptions o;
  o.start = {1.0, 1.0, 0.0};
  o.tour.waypoint_spacing_m = 2.0;
  o.frame_rate_hz = 1.0;
  const auto run = simulate_rgbd_run(room, o, 1);
  ASSERT_TRUE(run.ok()) << run.error().message;
  EXPECT_TRUE(run->completed);
  EXPECT_GT(run->waypoints_m.size(), 3u);
  EXPECT_GT(run->path_length_m, 10.0);
}

TEST(RgbdRun, ALegThroughAWallOrBadOptionsAreInputErrors) {
  const World room = support::rgbd_room();
  RgbdRunOptions o = square_drive();
  o.waypoints_m = {{5.0, 1.0}, {8.0, 1.0}};
  const auto through = simulate_rgbd_run(room, o, 1);
  ASSERT_FALSE(through.ok());
  EXPECT_EQ(through.error().kind, ErrorKind::kInput);
  EXPECT_THAT(through.error().message, HasSubstr("rgbd run: waypoint 1 (8.000, 1.000)"));
  o = square_drive();
  o.start = {0.1, 1.0, 0.0};
  EXPECT_THAT(simulate_rgbd_run(room, o, 1).error().message, HasSubstr("start (0.100, 1.000)"));
  o = square_drive();
  o.frame_rate_hz = 0.0;
  EXPECT_THAT(simulate_rgbd_run(room, o, 1).error().message,
              HasSubstr("rgbd run options: frame_rate_hz"));
  o = square_drive();
  o.neck_pan_rad = 2.0;
  EXPECT_THAT(simulate_rgbd_run(room, o, 1).error().message, HasSubstr("180-degree neck"));
}

TEST(RgbdRun, StopsAtTheDurationLimit) {
  const World room = support::rgbd_room();
  RgbdRunOptions o = square_drive();
  o.max_duration_s = 10.0;
  const auto run = simulate_rgbd_run(room, o, 1);
  ASSERT_TRUE(run.ok());
  EXPECT_FALSE(run->completed);
  EXPECT_DOUBLE_EQ(run->duration_s, 10.0);
}

}  // namespace
}  // namespace tessera
