#include "tessera/slam/laser_slam.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "laser_test_world.hpp"
#include "office_run.hpp"
#include "support/data.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/eval/relation_metric.hpp"
#include "tessera/eval/trajectory_error.hpp"
#include "tessera/io/carmen_log.hpp"
#include "tessera/io/relations_file.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera::slam {
namespace {

using testing::office_run;
using testing::simulate_office;
using testing::small_submaps;

double mean_position_error(const std::vector<StampedPose2>& estimate,
                           const std::vector<StampedPose2>& truth) {
  double sum = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    sum += (estimate[i].pose.translation() - truth[i].pose.translation()).norm();
  }
  return sum / static_cast<double>(truth.size());
}

// The lecture's point of SLAM: matching against the map beats dead reckoning, and closing the
// loop through the pose graph keeps the whole trajectory near the truth. Odometry starts at the
// true start pose and so does the SLAM trajectory, so no alignment is needed.
TEST(LaserSlam, SimulatedLoopEndsFarCloserToTheTruthThanOdometry) {
  const SimulatedLaserRun& run = office_run();
  ASSERT_GT(run.log.scans.size(), 150u);
  Result<LaserSlamResult> r = run_laser_slam(run.log, small_submaps());
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->trajectory.size(), run.log.scans.size());
  std::vector<StampedPose2> odometry;
  for (const StampedScan& s : run.log.scans) odometry.push_back({s.t_s, s.odometry});
  const double odometry_error = mean_position_error(odometry, run.truth);
  const double slam_error = mean_position_error(r->trajectory, run.truth);
  std::printf("mean position error: odometry %.3f m, SLAM %.3f m; %d loop closures\n",
              odometry_error, slam_error, r->stats.loop_closures);
  EXPECT_LT(slam_error, 0.5 * odometry_error);
  // 0.02 m with the translation tied to odometry at 10/m; 0.06-0.09 m at 3/m (decision 0013): in
  // this 0.1 m-cell world with 2-degree beams the scans pin translation worse than the simulated
  // odometry does, while real logs (odometry scale errors of 2 %) need the weaker tie.
  EXPECT_LT(slam_error, 0.1);
  EXPECT_GT(r->stats.loop_closures, 0);
  EXPECT_GT(r->stats.optimizations, 0);
  EXPECT_GT(r->map.known_count(), 1000u);
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    ASSERT_EQ(r->trajectory[i].t_s, run.log.scans[i].t_s);
  }
}

// A log without odometry (a bag of scans alone): with use_odometry off the scans alone carry the
// robot round the office and the loop closes; what the scans' odometry fields hold is not read
// (here: poses scattered metres apart, which would throw every prediction off if they were).
TEST(LaserSlam, WithoutOdometryTheScansAloneFollowTheRobot) {
  const SimulatedLaserRun& run = office_run();
  LaserLog log = run.log;
  Rng scatter(5);
  for (StampedScan& s : log.scans) {
    s.odometry =
        Pose2{scatter.uniform(-3.0, 3.0), scatter.uniform(-3.0, 3.0), scatter.uniform(-3.0, 3.0)};
  }
  LaserSlamOptions options = small_submaps();
  options.use_odometry = false;
  Result<LaserSlamResult> r = run_laser_slam(log, options);
  ASSERT_TRUE(r.ok()) << r.error().message;
  Result<AbsoluteTrajectoryError> ate = absolute_trajectory_error(r->trajectory, run.truth);
  ASSERT_TRUE(ate.ok()) << ate.error().message;
  std::printf("without odometry: ATE %.3f m over %zu scans, %d loop closures\n", ate->trans_m.rmse,
              ate->trans_m.count, r->stats.loop_closures);
  EXPECT_EQ(ate->trans_m.count, run.truth.size());
  EXPECT_LT(ate->trans_m.rmse, 0.1);
  EXPECT_GT(r->stats.loop_closures, 0);
}

// A spinning lidar on a turning robot (5 Hz, each scan swept over 0.2 s, turns at up to 1
// rad/s): placed from the stamp's pose, each scan is bent by up to 0.2 rad; placed beam by beam
// from the robot's velocity over its sweep (scan_points.hpp), the run keeps nearly as close to the
// truth as with a lidar that takes its scans at once. The odometry errs in scale, drift and
// distance, not in its turns, so that the velocity it gives is the sweep's and this test is about
// the sweep alone. Measured, seeds 1-5 and 7: 0.02-0.11 m beam by beam, 0.06-1.06 m from the
// stamp (seed 7 turns fastest: 0.113 against 1.055 m), 0.03-0.10 m taken at once; with the default
// odometry 0.03-0.13, 0.07-0.97 and 0.02-0.05 m.
TEST(LaserSlam, ASweptLidarsScansArePlacedWhereEachBeamWasTaken) {
  LaserRunOptions o = testing::office_run_options(5.0);
  o.odometry = perfect_odometry();
  o.odometry.heading_drift_rad_per_m = 0.01;
  o.odometry.distance_scale_error = 0.01;
  o.odometry.trans_var_m2_per_m = 1e-4;
  const SimulatedLaserRun at_once = testing::simulate_office(o);
  o.lidar_sweep_s = 0.2;
  const SimulatedLaserRun swept = testing::simulate_office(o);
  LaserLog bent = swept.log;
  for (StampedScan& s : bent.scans) s.robot_velocity = {};  // each scan from its stamp's pose
  const Result<LaserSlamResult> unwarped = run_laser_slam(swept.log, small_submaps());
  const Result<LaserSlamResult> warped = run_laser_slam(bent, small_submaps());
  const Result<LaserSlamResult> reference = run_laser_slam(at_once.log, small_submaps());
  ASSERT_TRUE(unwarped.ok() && warped.ok() && reference.ok());
  const double unwarped_m = mean_position_error(unwarped->trajectory, swept.truth);
  const double warped_m = mean_position_error(warped->trajectory, swept.truth);
  const double at_once_m = mean_position_error(reference->trajectory, at_once.truth);
  std::printf(
      "mean position error: %.3f m placed beam by beam, %.3f m from the stamp (%.3f m "
      "for scans taken at once)\n",
      unwarped_m, warped_m, at_once_m);
  EXPECT_LT(unwarped_m, 0.25 * warped_m);
  EXPECT_LT(unwarped_m, 2.0 * at_once_m);
}

// Issue 12: a loop must be found after metres of drift. Local SLAM is made to follow a badly
// drifting odometry (no search, heavy ties to the prior), so the estimate comes back to the start
// a few metres and degrees off, beyond loop_closer.window. With the window growing with the path
// between node and submap the loop is found, verified and closed; with a fixed window it is not.
TEST(LaserSlam, LoopAfterDriftBeyondTheBaseWindowIsClosedByTheGrowingWindow) {
  static const SimulatedLaserRun run = [] {
    OdometryErrorOptions odometry;
    odometry.heading_drift_rad_per_m = 0.02;
    odometry.distance_scale_error = 0.05;
    return simulate_office(2.0, odometry);
  }();
  LaserSlamOptions o;
  o.submaps.travel_per_submap_m = 5.0;
  o.real_time_search = false;
  o.refiner.translation_weight = 1e3;
  o.refiner.rotation_weight = 1e3;
  o.global_sampling_ratio = 0.0;
  // A small base window, and growth for an odometry that drifts by about a fifth of the distance
  // (the defaults are for real robots and larger buildings).
  o.loop_closer.window = {0.5, 0.1};
  o.loop_window_growth_m_per_m = 0.3;
  o.loop_window_growth_rad_per_m = 0.05;
  const Result<LaserSlamResult> growing = run_laser_slam(run.log, o);
  o.loop_window_growth_m_per_m = 0.0;
  o.loop_window_growth_rad_per_m = 0.0;
  const Result<LaserSlamResult> fixed = run_laser_slam(run.log, o);
  ASSERT_TRUE(growing.ok() && fixed.ok());

  std::vector<StampedPose2> odometry;
  for (const StampedScan& s : run.log.scans) odometry.push_back({s.t_s, s.odometry});
  const Pose2 drift = between(run.truth.back().pose, odometry.back().pose);
  const double growing_error = mean_position_error(growing->trajectory, run.truth);
  const double fixed_error = mean_position_error(fixed->trajectory, run.truth);
  std::printf("odometry ends %.2f m off; largest loop correction: fixed window %.2f m, growing "
              "%.2f m; mean error %.3f m and %.3f m; %d candidates\n",
              std::hypot(drift.x, drift.y), fixed->stats.max_loop_correction_m,
              growing->stats.max_loop_correction_m, fixed_error, growing_error,
              growing->stats.loop_candidates);
  ASSERT_GT(std::hypot(drift.x, drift.y), 1.5 * o.loop_closer.window.linear_m);
  // Loops further off than the base window are found (as candidates, then verified) only with
  // the growing window, and they do not make the trajectory worse.
  EXPECT_GT(growing->stats.loop_candidates, 0);
  EXPECT_GT(growing->stats.max_loop_correction_m, o.loop_closer.window.linear_m);
  EXPECT_LE(fixed->stats.max_loop_correction_m, o.loop_closer.window.linear_m);
  EXPECT_LE(growing_error, fixed_error);
}

// Issue 18 item 7: in a building of right angles (the office) the Manhattan option engages on
// most scans (the refinement's pull and the graph's priors) and the trajectory comes out closer
// to the truth (0.089 -> 0.027 m mean error when written); its effect on real logs is measured in
// docs/slam-manhattan.md.
TEST(LaserSlam, ManhattanOptionImprovesTheMapInABuildingOfRightAngles) {
  const SimulatedLaserRun& run = office_run();
  LaserSlamOptions o = small_submaps();
  const Result<LaserSlamResult> plain = run_laser_slam(run.log, o);
  o.manhattan = true;
  const Result<LaserSlamResult> manhattan = run_laser_slam(run.log, o);
  ASSERT_TRUE(plain.ok() && manhattan.ok());
  EXPECT_EQ(plain->stats.manhattan_priors, 0);
  EXPECT_EQ(plain->stats.manhattan_pulls, 0);
  EXPECT_GT(manhattan->stats.manhattan_priors, manhattan->stats.nodes / 2);
  EXPECT_GT(manhattan->stats.manhattan_pulls, manhattan->stats.scans / 2);
  EXPECT_EQ(manhattan->graph.heading_priors.size(),
            static_cast<std::size_t>(manhattan->stats.manhattan_priors));
  const double plain_m = mean_position_error(plain->trajectory, run.truth);
  const double manhattan_m = mean_position_error(manhattan->trajectory, run.truth);
  std::printf("mean position error: %.3f m without, %.3f m with the Manhattan option\n", plain_m,
              manhattan_m);
  EXPECT_LT(manhattan_m, 0.7 * plain_m);
  o.manhattan_sigma_rad = 0.0;
  EXPECT_TRUE(validate(o));
}

// Decision 0039: an odometry that reports 8 % more distance than the robot drove (a wheel
// radius set wrong). Local SLAM's refinement is tied to the odometry's prediction, so the stretch
// leaks into every step the walls do not pin; calibrated from the matches, the prediction is
// right and local SLAM's path follows the truth more closely (one scan a second, as sparse as a
// corrected log; at five a second the scans pin every step and the prior hardly matters). Over
// seeds 1-5, measured: scale 0.923-0.927 (1 / 1.08 = 0.926), 0.033 m on average calibrated
// against 0.036 m (per seed 0.028-0.038 against 0.029-0.048 m; one seed loses 1.3 %).
TEST(LaserSlam, AnOdometryThatReadsLongIsCalibratedFromTheMatches) {
  OdometryErrorOptions odometry;
  odometry.heading_drift_rad_per_m = 0.01;
  odometry.distance_scale_error = 0.08;
  double with_sum_m = 0.0, without_sum_m = 0.0;
  for (const std::uint64_t seed : {1, 2, 3, 4, 5}) {
    const SimulatedLaserRun run = simulate_office(1.0, odometry, seed);
    LaserSlamOptions o = small_submaps();
    o.loop_closure = false;
    const Result<LaserSlamResult> calibrated = run_laser_slam(run.log, o);
    o.odometry_calibration.enabled = false;
    const Result<LaserSlamResult> uncalibrated = run_laser_slam(run.log, o);
    ASSERT_TRUE(calibrated.ok() && uncalibrated.ok());
    const double with_m = mean_position_error(calibrated->local_trajectory, run.truth);
    const double without_m = mean_position_error(uncalibrated->local_trajectory, run.truth);
    std::printf(
        "seed %d, odometry 8 %% long: local SLAM %.4f m calibrated (scale %.4f), %.4f m "
        "without\n",
        static_cast<int>(seed), with_m, calibrated->stats.odometry_translation_scale, without_m);
    EXPECT_NEAR(calibrated->stats.odometry_translation_scale, 1.0 / 1.08, 0.01) << seed;
    EXPECT_EQ(uncalibrated->stats.odometry_translation_scale, 1.0);
    EXPECT_LT(with_m, 1.05 * without_m) << seed;
    with_sum_m += with_m;
    without_sum_m += without_m;
  }
  EXPECT_LT(with_sum_m, 0.95 * without_sum_m);
}

// Decision 0037's pass (on by default since decision 0038): after the final optimisation every
// scan is matched against the map of all of them, where during the run it saw only its submap.
// With five scans a second and with one (as sparse as a corrected log keeps them), the pass brings
// the trajectory closer to the truth (measured 0.091 -> 0.079 m and 0.051 -> 0.048 m; with 5x the
// option's ties, 0.052 and 0.018 m). Local SLAM alone (no loop closure) runs no pass.
TEST(LaserSlam, MatchingEveryScanAgainstTheWholeMapBringsItCloserToTheTruth) {
  OdometryErrorOptions odometry;
  odometry.heading_drift_rad_per_m = 0.02;
  for (const double rate_hz : {5.0, 1.0}) {
    const SimulatedLaserRun run = simulate_office(rate_hz, odometry);
    LaserSlamOptions o = small_submaps();
    o.final_map_passes = 0;
    const Result<LaserSlamResult> without = run_laser_slam(run.log, o);
    o.final_map_passes = 1;
    const Result<LaserSlamResult> with = run_laser_slam(run.log, o);
    ASSERT_TRUE(without.ok() && with.ok());
    const double without_m = mean_position_error(without->trajectory, run.truth);
    const double with_m = mean_position_error(with->trajectory, run.truth);
    std::printf(
        "%.0f Hz: mean position error %.4f m without, %.4f m with the whole-map pass (%.3f s)\n",
        rate_hz, without_m, with_m, with->stats.whole_map_s);
    EXPECT_LT(with_m, 0.96 * without_m);
    EXPECT_GT(with->stats.whole_map_s, 0.0);
    EXPECT_EQ(without->stats.whole_map_s, 0.0);
  }
  EXPECT_EQ(LaserSlamOptions{}.final_map_passes, 1);
  LaserSlamOptions local = small_submaps();
  local.loop_closure = false;
  const Result<LaserSlamResult> local_only = run_laser_slam(office_run().log, local);
  ASSERT_TRUE(local_only.ok());
  EXPECT_EQ(local_only->stats.whole_map_s, 0.0);
}

// Issue 17: wrong loop closures must not bend the map. A third of the accepted constraints are
// replaced by constraints 1-4 m and 0.2-1 rad off; the robust loss holds them during the run and
// the final optimisation switches them off, so the trajectory stays where the clean run has it.
TEST(LaserSlam, WrongLoopClosuresAreSwitchedOffAndCounted) {
  const SimulatedLaserRun& run = office_run();
  const Result<LaserSlamResult> clean = run_laser_slam(run.log, small_submaps());
  LaserSlamOptions o = small_submaps();
  o.wrong_closure_share = 0.3;
  o.wrong_closure_seed = 3;
  const Result<LaserSlamResult> wrong = run_laser_slam(run.log, o);
  ASSERT_TRUE(clean.ok() && wrong.ok());
  const double clean_error = mean_position_error(clean->trajectory, run.truth);
  const double wrong_error = mean_position_error(wrong->trajectory, run.truth);
  std::printf("mean error clean %.3f m, with %d wrong closures %.3f m; %d switched off\n",
              clean_error, wrong->stats.loop_wrong_injected, wrong_error,
              wrong->stats.loop_rejected);
  EXPECT_GT(wrong->stats.loop_wrong_injected, 5);
  EXPECT_GE(wrong->stats.loop_rejected, wrong->stats.loop_wrong_injected);
  EXPECT_LT(wrong_error, 1.1 * clean_error + 0.005);
}

// No randomness and one thread: the same log gives the same trajectory to the last bit.
TEST(LaserSlam, RunsAreDeterministic) {
  LaserLog log = office_run().log;
  log.scans.resize(60);
  const Result<LaserSlamResult> a = run_laser_slam(log, small_submaps());
  const Result<LaserSlamResult> b = run_laser_slam(log, small_submaps());
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->trajectory.size(), b->trajectory.size());
  for (std::size_t i = 0; i < a->trajectory.size(); ++i) {
    EXPECT_EQ(a->trajectory[i].pose.x, b->trajectory[i].pose.x);
    EXPECT_EQ(a->trajectory[i].pose.theta, b->trajectory[i].pose.theta);
  }
  EXPECT_EQ(a->graph.edges.size(), b->graph.edges.size());
}

// Issue 16 (a resumed session): the second half of the run comes as another log whose odometry
// has its own origin. Started where relocalization would put it (a few centimetres off), it
// builds its own submaps, is joined to the first half by loop closures and ends as near the truth
// as one uninterrupted run; the jump in odometry between the halves is never taken for motion.
TEST(LaserSlam, ANewTrajectoryWithItsOwnOdometryOriginJoinsTheMap) {
  const SimulatedLaserRun& run = office_run();
  const std::size_t half = run.log.scans.size() / 2;
  LaserLog log = run.log;
  const Pose2 T_other_origin{5.0, -3.0, 1.2};
  for (std::size_t i = half; i < log.scans.size(); ++i) {
    log.scans[i].odometry = T_other_origin * log.scans[i].odometry;
  }
  const Pose2 start = run.truth[half].pose * Pose2{0.04, -0.03, 0.02};
  const Result<LaserSlamResult> joined =
      run_laser_slam(log, small_submaps(), {{static_cast<int>(half), start}});
  const Result<LaserSlamResult> whole = run_laser_slam(run.log, small_submaps());
  ASSERT_TRUE(joined.ok() && whole.ok());
  ASSERT_EQ(joined->trajectory.size(), log.scans.size());
  const double joined_error = mean_position_error(joined->trajectory, run.truth);
  const double whole_error = mean_position_error(whole->trajectory, run.truth);
  std::printf("mean position error: one run %.3f m, two trajectories %.3f m\n", whole_error,
              joined_error);
  EXPECT_LT(joined_error, 1.2 * whole_error + 0.01);
  EXPECT_LT(
      (joined->trajectory[half].pose.translation() - run.truth[half].pose.translation()).norm(),
      0.1);
  // The second trajectory's nodes were matched into the first one's submaps.
  EXPECT_GT(joined->stats.loop_closures, 0);
  EXPECT_GT(joined->stats.submaps, 0);
}

// A snapshot (an autosave) is the run so far and leaves the run as it was: finishing afterwards
// gives what a run without the snapshot gives.
TEST(LaserSlam, ASnapshotIsTheRunSoFarAndChangesNothing) {
  LaserLog log = office_run().log;
  log.scans.resize(80);
  LaserSlam slam(small_submaps());
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    ASSERT_TRUE(slam.add_scan(log.scans[i]).ok());
    if (i == 39) {
      const LaserSlamResult so_far = slam.snapshot();
      EXPECT_EQ(so_far.trajectory.size(), 40u);
      EXPECT_EQ(so_far.stats.scans, 40);
      EXPECT_EQ(so_far.vertex_scan.size(), so_far.graph.poses.size());
      EXPECT_GT(so_far.map.known_count(), 100u);
      EXPECT_EQ(so_far.trajectory.back().pose.x, slam.latest_pose().x);
    }
  }
  const Result<LaserSlamResult> with = slam.finish();
  const Result<LaserSlamResult> without = run_laser_slam(log, small_submaps());
  ASSERT_TRUE(with.ok() && without.ok());
  ASSERT_EQ(with->trajectory.size(), without->trajectory.size());
  for (std::size_t i = 0; i < with->trajectory.size(); ++i) {
    EXPECT_EQ(with->trajectory[i].pose.x, without->trajectory[i].pose.x);
  }
}

TEST(LaserSlam, TrajectoryStartsMustBeScansOfTheLogInOrder) {
  LaserLog log = office_run().log;
  log.scans.resize(20);
  for (const std::vector<TrajectoryStart>& starts : {std::vector<TrajectoryStart>{{-1, {}}},
                                                     {{20, {}}},
                                                     {{10, {}}, {5, {}}},
                                                     {{0, {}}, {0, {}}}}) {
    const Result<LaserSlamResult> r = run_laser_slam(log, small_submaps(), starts);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.error().kind, ErrorKind::kInput);
    EXPECT_THAT(r.error().message, ::testing::HasSubstr("in increasing order"));
  }
}

// A trimmed session's first kept scan is not the run's first (issue 16): a start at scan 0
// places it where the session had it, and the run goes on from there as from any start.
TEST(LaserSlam, AStartAtTheFirstScanPlacesIt) {
  LaserLog log = office_run().log;
  log.scans.resize(30);
  const Pose2 T_map_first{3.0, -2.0, 0.7};
  const Result<LaserSlamResult> placed = run_laser_slam(log, small_submaps(), {{0, T_map_first}});
  const Result<LaserSlamResult> plain = run_laser_slam(log, small_submaps());
  ASSERT_TRUE(placed.ok() && plain.ok());
  EXPECT_NEAR(placed->trajectory.front().pose.x, T_map_first.x, 1e-9);
  EXPECT_NEAR(placed->trajectory.front().pose.theta, T_map_first.theta, 1e-9);
  // The same run, moved rigidly: the last pose relative to the first is unchanged, up to what
  // submap cells turned against the scans change in the matches (measured 0.011 rad).
  const Pose2 a = between(placed->trajectory.front().pose, placed->trajectory.back().pose);
  const Pose2 b = between(plain->trajectory.front().pose, plain->trajectory.back().pose);
  EXPECT_NEAR(a.x, b.x, 0.05);
  EXPECT_NEAR(a.y, b.y, 0.05);
  EXPECT_NEAR(a.theta, b.theta, 0.03);
}

TEST(LaserSlam, ReportsProgressForEveryScan) {
  LaserLog log = office_run().log;
  log.scans.resize(30);
  LaserSlamOptions o;
  int calls = 0;
  SlamProgress last;
  o.progress = [&](const SlamProgress& p) {
    ++calls;
    last = p;
  };
  ASSERT_TRUE(run_laser_slam(log, o).ok());
  EXPECT_EQ(calls, 30);
  EXPECT_EQ(last.scans_done, 30);
  EXPECT_EQ(last.scans_total, 30);
  EXPECT_GE(last.nodes, 1);
}

TEST(LaserSlam, EmptyLogAndBadOptionsAreErrors) {
  const Result<LaserSlamResult> empty = run_laser_slam(LaserLog{}, LaserSlamOptions{});
  ASSERT_FALSE(empty.ok());
  EXPECT_EQ(empty.error().kind, ErrorKind::kInput);
  LaserSlamOptions bad;
  bad.submaps.resolution_m = 0.0;
  LaserLog one_scan;
  one_scan.scans.emplace_back();
  const Result<LaserSlamResult> r = run_laser_slam(one_scan, bad);
  ASSERT_FALSE(r.ok());
  EXPECT_EQ(r.error().kind, ErrorKind::kUsage);
  EXPECT_THAT(r.error().message, ::testing::HasSubstr("submaps.resolution_m"));
  LaserSlamOptions no_passes;
  no_passes.final_map_passes = -1;
  EXPECT_THAT(validate(no_passes).value_or(""), ::testing::HasSubstr("final_map_passes"));
  LaserSlamOptions loose;
  loose.final_map_refiner.occupied_space_weight = 0.0;
  EXPECT_THAT(validate(loose).value_or(""), ::testing::HasSubstr("final_map_refiner."));
}

// The first 300 scans of the real Intel log (raw odometry, 60 s; the full-log figures are in
// bench/slam). The robot stands for 30 s, then drives: local SLAM must fix odometry's heading
// error, which the Kummerle relations inside the slice measure (4 of them: a smoke test of
// accuracy, not a benchmark).
TEST(LaserSlam, IntelSliceBeatsRawOdometryOnTheRelations) {
  const auto log_path = support::data_path("laser/intel/intel-raw-first5505-sot.clf");
  const auto relations_path = support::data_path("laser/intel/intel.relations");
  TESSERA_REQUIRE_DATA(log_path);
  TESSERA_REQUIRE_DATA(relations_path);
  Result<LaserLog> log = read_carmen_log(log_path);
  ASSERT_TRUE(log.ok()) << log.error().message;
  log->scans.resize(300);
  Result<std::vector<Relation>> relations = read_relations(relations_path);
  ASSERT_TRUE(relations.ok()) << relations.error().message;

  const Result<LaserSlamResult> r = run_laser_slam(*log, LaserSlamOptions{});
  ASSERT_TRUE(r.ok()) << r.error().message;
  ASSERT_EQ(r->trajectory.size(), 300u);
  for (std::size_t i = 0; i < 300; ++i) ASSERT_EQ(r->trajectory[i].t_s, log->scans[i].t_s);

  constexpr double kIntelTimeOffsetS = 976052857.337284;  // intel/SOURCES.md
  std::vector<StampedPose2> odometry;
  for (const StampedScan& s : log->scans) odometry.push_back({s.t_s, s.odometry});
  const Result<RelationMetric> slam = relation_metric(r->trajectory, *relations, kIntelTimeOffsetS);
  const Result<RelationMetric> odo = relation_metric(odometry, *relations, kIntelTimeOffsetS);
  ASSERT_TRUE(slam.ok() && odo.ok());
  std::printf("Intel 300 scans, %zu relations: odometry %.4f m %.3f deg, SLAM %.4f m %.3f deg\n",
              slam->count, odo->trans_mean_m, rad_to_deg(odo->rot_mean_rad), slam->trans_mean_m,
              rad_to_deg(slam->rot_mean_rad));
  EXPECT_GE(slam->count, 4u);
  EXPECT_LT(slam->rot_mean_rad, 0.5 * odo->rot_mean_rad);
  EXPECT_LT(slam->trans_mean_m, odo->trans_mean_m);
  EXPECT_LT(slam->trans_mean_m, 0.05);
}

}  // namespace
}  // namespace tessera::slam
