#include "tessera/sim/laser_run.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "support/data.hpp"
#include "tessera/io/map_file.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

using ::testing::HasSubstr;

/// A cheap run of the office: few beams, a short lidar.
LaserRunOptions cheap_options() {
  LaserRunOptions o;
  o.lidar.beams = 36;
  o.lidar.max_range_m = 4.0;
  o.max_duration_s = 60.0;
  return o;
}

const World& office() {
  static const World world = builtin_world("office", 0.1);
  return world;
}

TEST(LaserRun, SameSeedSameRunAndAnotherSeedAnotherRun) {
  const LaserRunOptions o = cheap_options();
  const Result<SimulatedLaserRun> a = simulate_laser_run(office(), o, 7);
  const Result<SimulatedLaserRun> b = simulate_laser_run(office(), o, 7);
  const Result<SimulatedLaserRun> c = simulate_laser_run(office(), o, 8);
  ASSERT_TRUE(a.ok() && b.ok() && c.ok());
  ASSERT_EQ(a->log.scans.size(), b->log.scans.size());
  for (std::size_t k = 0; k < a->log.scans.size(); ++k) {
    EXPECT_EQ(a->log.scans[k].scan.ranges_m, b->log.scans[k].scan.ranges_m);
    EXPECT_EQ(a->log.scans[k].odometry.x, b->log.scans[k].odometry.x);
    EXPECT_EQ(a->log.scans[k].odometry.theta, b->log.scans[k].odometry.theta);
    EXPECT_EQ(a->truth[k].pose.y, b->truth[k].pose.y);
  }
  // Another seed: another random start.
  EXPECT_NE(a->truth.front().pose.x, c->truth.front().pose.x);
}

TEST(LaserRun, LogHasOneScanPerStampAtTheScanRateAndStartsAtTheTruth) {
  LaserRunOptions o = cheap_options();
  o.scan_rate_hz = 8.0;
  o.start = Pose2{2.0, 4.0, 0.3};
  const Result<SimulatedLaserRun> run = simulate_laser_run(office(), o, 1);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const LaserLog& log = run->log;
  ASSERT_EQ(log.scans.size(), run->truth.size());
  ASSERT_EQ(log.odometry.size(), run->truth.size());
  EXPECT_EQ(log.backward_stamps, 0);
  EXPECT_EQ(log.scans.size(), 481u);  // 60 s at 8 Hz, the first at t = 0
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    EXPECT_DOUBLE_EQ(log.scans[k].t_s, static_cast<double>(k) / 8.0);
    EXPECT_EQ(run->truth[k].t_s, log.scans[k].t_s);
    EXPECT_EQ(log.odometry[k].t_s, log.scans[k].t_s);
    EXPECT_EQ(log.odometry[k].pose.x, log.scans[k].odometry.x);
    EXPECT_EQ(log.scans[k].scan.ranges_m.size(), 36u);
  }
  EXPECT_EQ(run->truth.front().pose.x, 2.0);
  EXPECT_NEAR(run->truth.front().pose.theta, 0.3, 1e-12);
  EXPECT_EQ(log.scans.front().odometry.y, 4.0);
  EXPECT_DOUBLE_EQ(run->duration_s, 60.0);
  EXPECT_FALSE(run->tour_completed);
}

TEST(LaserRun, ScansFromTheTruePoseMatchCastRay) {
  LaserRunOptions o = cheap_options();
  o.max_duration_s = 20.0;
  o.laser_in_robot = {0.1, -0.05, 0.2};
  o.lidar.range_noise_stddev_m = 0.0;
  const Result<SimulatedLaserRun> exact = simulate_laser_run(office(), o, 3);
  o.lidar.range_noise_stddev_m = 0.02;
  const Result<SimulatedLaserRun> noisy = simulate_laser_run(office(), o, 3);
  ASSERT_TRUE(exact.ok() && noisy.ok());
  ASSERT_EQ(exact->truth.size(), noisy->truth.size());
  std::size_t returns = 0;
  for (std::size_t k = 0; k < exact->truth.size(); ++k) {
    const StampedScan& s = exact->log.scans[k];
    EXPECT_EQ(s.laser_in_robot.x, 0.1);
    const Pose2 T_world_laser = exact->truth[k].pose * s.laser_in_robot;
    for (std::size_t i = 0; i < s.scan.ranges_m.size(); ++i) {
      const double angle = T_world_laser.theta + s.scan.angle_min_rad +
                           static_cast<double>(i) * s.scan.angle_increment_rad;
      const double truth_m = office().cast_ray(T_world_laser.translation(), angle, 4.0);
      EXPECT_EQ(s.scan.ranges_m[i], truth_m) << "scan " << k << " beam " << i;
      const double noisy_m = noisy->log.scans[k].scan.ranges_m[i];
      if (truth_m >= 4.0) {
        EXPECT_EQ(noisy_m, 4.0);  // no return, no noise
      } else {
        ++returns;
        EXPECT_LE(std::abs(noisy_m - truth_m), 3.0 * 0.02 + 1e-12);
      }
    }
  }
  EXPECT_GT(returns, 1000u);
}

TEST(LaserRun, TruePosesKeepTheClearanceAndTheSpeedLimits) {
  LaserRunOptions o = cheap_options();
  o.max_duration_s = 120.0;
  o.tour.clearance_m = 0.3;
  o.max_speed_m_per_s = 0.6;
  o.max_turn_rate_rad_per_s = 0.8;
  const Result<SimulatedLaserRun> run = simulate_laser_run(office(), o, 11);
  ASSERT_TRUE(run.ok()) << run.error().message;
  const double dt_s = 1.0 / o.scan_rate_hz;
  for (std::size_t k = 0; k < run->truth.size(); ++k) {
    const Pose2& p = run->truth[k].pose;
    ASSERT_GE(office().distance_to_solid(p.translation(), 0.3), 0.3 - 1e-9) << "scan " << k;
    if (k == 0) continue;
    const Pose2 step = between(run->truth[k - 1].pose, p);
    EXPECT_LE(std::hypot(step.x, step.y), o.max_speed_m_per_s * dt_s + 1e-9) << "scan " << k;
    EXPECT_LE(std::abs(step.theta), o.max_turn_rate_rad_per_s * dt_s + 1e-9) << "scan " << k;
  }
  EXPECT_GT(run->path_length_m, 30.0);  // it does drive
}

TEST(LaserRun, PerfectOdometryIsTheTruth) {
  LaserRunOptions o = cheap_options();
  o.odometry = perfect_odometry();
  const Result<SimulatedLaserRun> run = simulate_laser_run(office(), o, 5);
  ASSERT_TRUE(run.ok());
  for (std::size_t k = 0; k < run->truth.size(); ++k) {
    const Pose2 e = between(run->truth[k].pose, run->log.scans[k].odometry);
    ASSERT_LT(std::hypot(e.x, e.y), 1e-9) << "scan " << k;
    ASSERT_LT(std::abs(e.theta), 1e-9) << "scan " << k;
  }
}

// A spinning lidar (lidar_sweep_s): beam i is taken i * sweep / beams after the stamp, from
// where the robot then is, so the first beam is the stamp's and the later ones differ from a scan
// taken at once while the robot moves; each scan carries the robot's velocity over its sweep,
// from the odometry (perfect here: the true motion from the first beam to the last, but for
// odometry read at the stamps and interpolated between them along the chord).
TEST(LaserRun, ASweepingLidarTakesItsBeamsOneAfterTheOther) {
  LaserRunOptions o = cheap_options();
  o.max_duration_s = 20.0;
  o.scan_rate_hz = 5.0;
  o.odometry = perfect_odometry();
  o.lidar.range_noise_stddev_m = 0.0;
  const Result<SimulatedLaserRun> at_once = simulate_laser_run(office(), o, 3);
  o.lidar_sweep_s = 0.2;
  const Result<SimulatedLaserRun> swept = simulate_laser_run(office(), o, 3);
  ASSERT_TRUE(at_once.ok() && swept.ok());
  ASSERT_EQ(swept->truth.size(), at_once->truth.size());
  std::size_t moved_beams = 0;
  double fastest_turn_rad_per_s = 0.0;
  for (std::size_t k = 0; k + 1 < swept->truth.size(); ++k) {
    const StampedScan& s = swept->log.scans[k];
    EXPECT_EQ(s.scan.first_beam_s, 0.0);
    EXPECT_NEAR(s.scan.time_increment_s, 0.2 / 36.0, 1e-15);
    EXPECT_EQ(s.scan.ranges_m[0], at_once->log.scans[k].scan.ranges_m[0]) << "scan " << k;
    for (std::size_t i = 1; i < s.scan.ranges_m.size(); ++i) {
      moved_beams += s.scan.ranges_m[i] != at_once->log.scans[k].scan.ranges_m[i] ? 1 : 0;
    }
    const Pose2 driven = displacement(s.robot_velocity, 0.2);
    const Pose2 truth = between(swept->truth[k].pose, swept->truth[k + 1].pose);
    EXPECT_NEAR(driven.x, truth.x, 1e-3) << "scan " << k;
    EXPECT_NEAR(driven.y, truth.y, 1e-3) << "scan " << k;
    EXPECT_NEAR(driven.theta, truth.theta, 1e-3) << "scan " << k;
    fastest_turn_rad_per_s =
        std::max(fastest_turn_rad_per_s, std::abs(s.robot_velocity.omega_rad_per_s));
  }
  EXPECT_GT(moved_beams, 100u);
  EXPECT_NEAR(fastest_turn_rad_per_s, o.max_turn_rate_rad_per_s, 0.05);
  // A sweep longer than a scan period is refused.
  o.lidar_sweep_s = 0.25;
  const Result<SimulatedLaserRun> too_long = simulate_laser_run(office(), o, 3);
  ASSERT_FALSE(too_long.ok());
  EXPECT_THAT(too_long.error().message,
              HasSubstr("lidar_sweep_s must be in [0, 1 / scan_rate_hz]"));
}

// Dead reckoning drifts: averaged over seeds and over stretches of the run, the position error
// grows with the distance driven. Early stretches only: the tour comes back home, and late in a
// run errors can partly cancel (measured: 0.04, 0.20 and 0.63 m).
TEST(LaserRun, OdometryErrorGrowsWithDistance) {
  LaserRunOptions o = cheap_options();
  o.lidar.beams = 4;
  o.max_duration_s = 0.0;
  constexpr int kSeeds = 6;
  // Mean position error over the stretches [0, 1), [1, 15) and [15, 40) m driven.
  const std::vector<double> stretch_ends_m = {1.0, 15.0, 40.0};
  std::vector<double> sum_m(stretch_ends_m.size(), 0.0);
  std::vector<int> count(stretch_ends_m.size(), 0);
  for (int seed = 0; seed < kSeeds; ++seed) {
    const Result<SimulatedLaserRun> run =
        simulate_laser_run(office(), o, static_cast<std::uint64_t>(seed));
    ASSERT_TRUE(run.ok());
    ASSERT_GT(run->path_length_m, stretch_ends_m.back()) << "seed " << seed;
    double driven_m = 0.0;
    for (std::size_t k = 1; k < run->truth.size(); ++k) {
      const Pose2 step = between(run->truth[k - 1].pose, run->truth[k].pose);
      driven_m += std::hypot(step.x, step.y);
      const auto stretch = static_cast<std::size_t>(
          std::upper_bound(stretch_ends_m.begin(), stretch_ends_m.end(), driven_m) -
          stretch_ends_m.begin());
      if (stretch >= stretch_ends_m.size()) break;
      const Vec2 e = run->truth[k].pose.translation() - run->log.scans[k].odometry.translation();
      sum_m[stretch] += e.norm();
      ++count[stretch];
    }
  }
  std::vector<double> mean_m(sum_m.size());
  for (std::size_t i = 0; i < sum_m.size(); ++i) mean_m[i] = sum_m[i] / count[i];
  EXPECT_LT(mean_m[0], 0.1);
  for (std::size_t i = 1; i < mean_m.size(); ++i) {
    EXPECT_GT(mean_m[i], 1.5 * mean_m[i - 1]) << "stretch " << i;
  }
  EXPECT_GT(mean_m.back(), 0.3);
}

// With a short lidar, a complete tour of a small world sees nearly all of its reachable free space.
TEST(LaserRun, TourSeesMostOfTheReachableFreeSpaceOfASmallWorld) {
  LaserRunOptions o;
  o.lidar.beams = 90;
  o.lidar.max_range_m = 3.0;
  o.max_duration_s = 0.0;
  o.tour.waypoint_spacing_m = 2.5;
  const Result<SimulatedLaserRun> run = simulate_laser_run(office(), o, 2);
  ASSERT_TRUE(run.ok()) << run.error().message;
  EXPECT_TRUE(run->tour_completed);
  const Vec2 start = run->truth.front().pose.translation();
  const Vec2 end = run->truth.back().pose.translation();
  EXPECT_LT((end - start).norm(), 1e-9);  // back at the start
  OccupancyGrid map(office().geometry());
  for (std::size_t k = 0; k < run->truth.size(); ++k) {
    const StampedScan& s = run->log.scans[k];
    insert_scan(map, run->truth[k].pose * s.laser_in_robot, s.scan, ScanInsertOptions{}, nullptr);
  }
  const GridGeometry& g = office().geometry();
  const std::vector<std::uint8_t> reachable = office().reachable_from(*g.cell_at(start));
  std::size_t reachable_cells = 0, seen_free = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (reachable[i] == 0) continue;
    ++reachable_cells;
    if (map.state(g.cell_of(i)) == CellState::kFree) ++seen_free;
  }
  EXPECT_GT(static_cast<double>(seen_free) / static_cast<double>(reachable_cells), 0.95);
  // Places are revisited: the tour drives more than once through some spot.
  EXPECT_GT(run->path_length_m, 60.0);
}

TEST(LaserRun, PathLengthLimitEndsTheRun) {
  LaserRunOptions o = cheap_options();
  o.max_duration_s = 0.0;
  o.max_path_length_m = 10.0;
  const Result<SimulatedLaserRun> run = simulate_laser_run(office(), o, 4);
  ASSERT_TRUE(run.ok());
  EXPECT_FALSE(run->tour_completed);
  EXPECT_GE(run->path_length_m, 10.0);
  EXPECT_LT(run->path_length_m, 10.0 + o.max_speed_m_per_s / o.scan_rate_hz + 1e-9);
}

TEST(LaserRun, BadOptionsAreInputErrorsNamingTheField) {
  const auto message = [](const LaserRunOptions& o) {
    const Result<SimulatedLaserRun> r = simulate_laser_run(office(), o, 1);
    EXPECT_FALSE(r.ok());
    if (r.ok()) return std::string();
    EXPECT_EQ(r.error().kind, ErrorKind::kInput);
    return r.error().message;
  };
  LaserRunOptions o;
  o.scan_rate_hz = 0.0;
  EXPECT_EQ(message(o), "laser run options: scan_rate_hz must be in (0, 1000], got 0.000000");
  o = {};
  o.max_speed_m_per_s = -0.5;
  EXPECT_THAT(message(o), HasSubstr("max_speed_m_per_s must be > 0"));
  o = {};
  o.max_turn_rate_rad_per_s = std::numeric_limits<double>::infinity();
  EXPECT_THAT(message(o), HasSubstr("max_turn_rate_rad_per_s must be > 0"));
  o = {};
  o.max_duration_s = -1.0;
  EXPECT_THAT(message(o), HasSubstr("max_duration_s must be >= 0 (0: no limit)"));
  o = {};
  o.steps_per_scan = 0;
  EXPECT_THAT(message(o), HasSubstr("steps_per_scan must be in [1, 1000]"));
  o = {};
  o.lidar.beams = 0;
  EXPECT_THAT(message(o), HasSubstr("laser run options: lidar: beams must be >= 1"));
  o = {};
  o.odometry.rot_var_rad2_per_m = -1.0;
  EXPECT_THAT(message(o), HasSubstr("laser run options: odometry: rot_var_rad2_per_m"));
  o = {};
  o.tour.waypoint_spacing_m = -2.0;
  EXPECT_THAT(message(o), HasSubstr("laser run options: tour: waypoint_spacing_m"));
  o = {};
  o.laser_in_robot = {0.3, 0.0, 0.0};
  EXPECT_THAT(message(o), HasSubstr("laser_in_robot must lie within tour.clearance_m"));
  o = {};
  o.start = Pose2{3.3, 2.8, 0.0};
  EXPECT_EQ(message(o), "start (3.3, 2.8) m is inside an obstacle");
}

TEST(LaserRun, AWorldWithoutRoomForTheRobotIsAnInputError) {
  // A corridor 0.4 m wide: no point in it is 0.25 m from both walls.
  const GridGeometry g({0.0, 0.0}, 0.1, 40, 6);
  std::vector<std::uint8_t> solid(g.size(), 1);
  for (int x = 1; x < 39; ++x) {
    for (int y = 1; y < 5; ++y) solid[g.index_of({x, y})] = 0;
  }
  const Result<SimulatedLaserRun> run = simulate_laser_run(World(g, solid), LaserRunOptions{}, 1);
  ASSERT_FALSE(run.ok());
  EXPECT_EQ(run.error().kind, ErrorKind::kInput);
  EXPECT_EQ(run.error().message,
            "no room for the robot: no free cell is at least clearance_m = 0.25 m from every wall");
}

// One of the floor plans the SLAM figures use (Stage's autolab, 20 x 17 m, resampled to 5 cm): a
// short run with the default lidar is valid.
TEST(LaserRun, RunsOnARealFloorPlan) {
  const auto file = support::data_path("maps/stage_bitmaps/autolab.png");
  TESSERA_REQUIRE_DATA(file);
  Result<LoadedMap> loaded = load_map(file, MapLoadOptions{0.025});
  ASSERT_TRUE(loaded.ok()) << loaded.error().message;
  const World world = World::from_map(loaded->map).resampled(0.05);
  LaserRunOptions o;
  o.max_duration_s = 15.0;
  const Result<SimulatedLaserRun> run = simulate_laser_run(world, o, 1);
  ASSERT_TRUE(run.ok()) << run.error().message;
  EXPECT_EQ(run->log.scans.size(), 151u);
  EXPECT_GT(run->tour.length_m, 60.0);  // the whole tour, of which 15 s are driven
  for (const StampedPose2& p : run->truth) {
    EXPECT_GE(world.distance_to_solid(p.pose.translation(), 0.25), 0.25 - 1e-9);
  }
}

}  // namespace
}  // namespace tessera
