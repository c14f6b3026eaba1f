#include "tessera/slam/localizer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/map_at_truth.hpp"
#include "support/text_world.hpp"
#include "tessera/core/angle.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera::slam {
namespace {

using support::map_at_truth;

/// A run through the built-in office (0.1 m cells) with a 270-degree lidar, 5 scans per second and
/// drifting odometry; `seed` draws the start and the noise.
SimulatedLaserRun office_run(std::uint64_t seed, double duration_s) {
  const World office = builtin_world("office", 0.1);
  LaserRunOptions o;
  o.lidar.beams = 270;
  o.lidar.fov_rad = deg_to_rad(270.0);
  o.lidar.max_range_m = 10.0;
  o.scan_rate_hz = 5.0;
  o.max_duration_s = duration_s;
  o.odometry.heading_drift_rad_per_m = 0.02;
  Result<SimulatedLaserRun> r = simulate_laser_run(office, o, seed);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return std::move(r).value();
}

/// The office mapped by a first robot.
const ProbabilityGrid& office_map() {
  static const ProbabilityGrid map = map_at_truth(office_run(3, 0.0));
  return map;
}

struct PoseError {
  double m = 0.0;
  double rad = 0.0;
};

PoseError error_of(const Pose2& estimate, const Pose2& truth) {
  const Pose2 e = between(truth, estimate);
  return {std::hypot(e.x, e.y), std::abs(normalize_angle(e.theta))};
}

TEST(Localizer, TracksARobotFromAKnownPoseWithoutDrift) {
  const SimulatedLaserRun run = office_run(11, 40.0);
  const LocalizerOptions options;
  Localizer localizer(office_map(), options);
  localizer.set_pose(run.truth.front().pose);
  double worst_m = 0.0;
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    const LocalizedScan s = localizer.add_scan(run.log.scans[i]);
    ASSERT_NE(s.state, LocalizationState::kLost) << "scan " << i;
    EXPECT_TRUE(s.confident) << "scan " << i;
    worst_m = std::max(worst_m, error_of(s.T_map_robot, run.truth[i].pose).m);
  }
  // Odometry alone drifts 0.02 rad per metre; the map holds the pose.
  EXPECT_LT(worst_m, 0.1);
  EXPECT_EQ(localizer.stats().searches, 0);
}

// A session that mapped only what lay within 0.8 m of its robot: a robot with a 10 m lidar sees
// far beyond that map. The part of each scan on the map places it, so it is trusted, although
// counting the points beyond the map as misses would put its score under the bar; and where that
// part is too thin to hold the pose, it is not trusted.
TEST(Localizer, ARobotSeeingFarBeyondTheMapIsTrustedOnWhatTheMapShows) {
  const ProbabilityGrid near_map = map_at_truth(
      office_run(3, 0.0), {.min_range_m = 0.1, .max_range_m = 0.8, .missing_ray_length_m = 0.0});

  const SimulatedLaserRun run = office_run(11, 40.0);
  const LocalizerOptions options;
  Localizer localizer(near_map, options);
  localizer.set_pose(run.truth.front().pose);
  int beyond = 0, trusted_beyond = 0;
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    const LocalizedScan s = localizer.add_scan(run.log.scans[i]);
    ASSERT_NE(s.state, LocalizationState::kLost) << "scan " << i;
    if (s.score < options.min_tracking_score) {  // a scan mostly beyond the map
      ++beyond;
      trusted_beyond += s.confident ? 1 : 0;
    }
    if (!s.confident) continue;
    const PoseError e = error_of(s.T_map_robot, run.truth[i].pose);
    EXPECT_LT(e.m, 0.1) << "scan " << i;
    EXPECT_LT(e.rad, deg_to_rad(3.0)) << "scan " << i;
  }
  ASSERT_GT(beyond, static_cast<int>(run.log.scans.size()) / 4);
  EXPECT_GE(trusted_beyond, beyond * 4 / 5);
}

TEST(Localizer, FindsARobotWithNoInitialPoseAndIsNeverConfidentlyWrong) {
  const LocalizerOptions options;
  int found = 0;
  for (const std::uint64_t seed : {21, 22, 23, 24}) {
    const SimulatedLaserRun run = office_run(seed, 15.0);
    Localizer localizer(office_map(), options);
    std::optional<double> found_at_s;
    for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
      const LocalizedScan s = localizer.add_scan(run.log.scans[i]);
      if (!s.confident) continue;
      if (!found_at_s) found_at_s = s.t_s;
      const PoseError e = error_of(s.T_map_robot, run.truth[i].pose);
      EXPECT_LT(e.m, 0.1) << "seed " << seed << " scan " << i;
      EXPECT_LT(e.rad, deg_to_rad(3.0)) << "seed " << seed << " scan " << i;
    }
    if (found_at_s && *found_at_s <= 5.0) ++found;
  }
  EXPECT_GE(found, 3);
}

/// The rows of a 6 m x 4 m room (text_world, 0.1 m cells). A bare one is the same turned by half
/// a turn; an L-shaped one (a 1.9 m x 1.5 m block in one corner) has no symmetry.
std::vector<std::string> room_rows(bool l_shaped) {
  std::vector<std::string> rows(40, "#" + std::string(58, '.') + "#");
  rows.front() = rows.back() = std::string(60, '#');
  if (l_shaped) {
    for (int y = 1; y <= 15; ++y) rows[static_cast<std::size_t>(y)].replace(40, 19, 19, '#');
  }
  return rows;
}

/// The room runs' lidar and pace: 10 m range, 5 scans per second, `duration_s` long.
LaserRunOptions room_run_options(double duration_s) {
  LaserRunOptions o;
  o.lidar.max_range_m = 10.0;
  o.scan_rate_hz = 5.0;
  o.max_duration_s = duration_s;
  return o;
}

/// Scans of the bare room for `duration_s`.
SimulatedLaserRun bare_room_run(double duration_s) {
  Result<SimulatedLaserRun> run = simulate_laser_run(support::text_world(room_rows(false), 0.1),
                                                     room_run_options(duration_s), 5);
  EXPECT_TRUE(run.ok()) << run.error().message;
  return std::move(run).value();
}

// The robot starts in a room the session never mapped and then is in the office (as if it drove
// through a door). For 3 s the view joins the room's scans to the office's and fits nowhere; the
// newest scan alone fits the map, so the robot is found within a second of reaching the office,
// not once the room has left the view, and never confidently wrong.
TEST(Localizer, AViewThatFitsNowhereIsPlacedByItsNewestScan) {
  const SimulatedLaserRun room = bare_room_run(2.0);
  const SimulatedLaserRun office = office_run(21, 6.0);
  const LocalizerOptions options;
  Localizer localizer(office_map(), options);
  for (const StampedScan& scan : room.log.scans) {
    EXPECT_FALSE(localizer.add_scan(scan).confident);
  }
  const Pose2 T_odom_jump =
      room.log.scans.back().odometry * office.log.scans.front().odometry.inverse();
  const double t0 = room.log.scans.back().t_s + 0.2;
  std::optional<double> found_after_s;
  for (std::size_t i = 0; i < office.log.scans.size(); ++i) {
    StampedScan scan = office.log.scans[i];
    scan.t_s += t0;
    scan.odometry = T_odom_jump * scan.odometry;
    const LocalizedScan s = localizer.add_scan(scan);
    if (!s.confident) continue;
    const PoseError e = error_of(s.T_map_robot, office.truth[i].pose);
    EXPECT_LT(e.m, 0.1) << "scan " << i;
    EXPECT_LT(e.rad, deg_to_rad(3.0)) << "scan " << i;
    if (!found_after_s) found_after_s = s.t_s - t0;
  }
  ASSERT_TRUE(found_after_s.has_value());
  EXPECT_LE(*found_after_s, 1.5);
  EXPECT_GT(localizer.stats().newest_scan_only, 0);
}

/// A kidnapping: the robot drives 10 s, then its scans are another run's, elsewhere in the
/// office; its odometry goes on as if nothing happened. When it was noticed (the pose withdrawn,
/// or doubted because the scans jumped), when it was found again, and the localizer's counts;
/// no jump before the kidnapping, and every confident pose after it right.
struct Kidnapping {
  std::optional<double> noticed_after_s, found_after_s;
  LocalizerStats stats;
};
Kidnapping kidnap(const LocalizerOptions& options) {
  const SimulatedLaserRun before = office_run(31, 10.0);
  const SimulatedLaserRun after = office_run(32, 20.0);
  Localizer localizer(office_map(), options);
  localizer.set_pose(before.truth.front().pose);
  for (const StampedScan& scan : before.log.scans) localizer.add_scan(scan);
  EXPECT_EQ(localizer.stats().jumps, 0);
  const Pose2 T_odom_jump =
      before.log.scans.back().odometry * after.log.scans.front().odometry.inverse();
  const double t0 = before.log.scans.back().t_s + 0.2;
  Kidnapping k;
  for (std::size_t i = 0; i < after.log.scans.size(); ++i) {
    StampedScan scan = after.log.scans[i];
    scan.t_s += t0;
    scan.odometry = T_odom_jump * scan.odometry;
    const LocalizedScan s = localizer.add_scan(scan);
    const bool doubted = localizer.stats().jumps > 0;
    if ((s.state != LocalizationState::kTracking || doubted) && !k.noticed_after_s) {
      k.noticed_after_s = s.t_s - t0;
    }
    if (!s.confident) continue;
    const PoseError e = error_of(s.T_map_robot, after.truth[i].pose);
    if (e.m < 0.1 && e.rad < deg_to_rad(3.0)) {
      if (!k.found_after_s) k.found_after_s = s.t_s - t0;
    } else {
      ADD_FAILURE() << "a confident wrong pose after the kidnapping, scan " << i << ": " << e.m
                    << " m";
    }
  }
  k.stats = localizer.stats();
  // Every search ends one way: accepted, or refused for exactly one reason.
  const LocalizerStats& st = k.stats;
  EXPECT_EQ(st.searches, st.relocalizations + st.no_match + st.unfit + st.see_through +
                             st.ambiguous + st.unconfirmed);
  return k;
}

TEST(Localizer, AKidnappedRobotIsDoubtedAtOnceAndFoundAgain) {
  // The first scan after the jump disagrees with the one before it: the pose is doubted there,
  // before the map has contradicted it for lost_after_s, and a global search places the robot.
  const Kidnapping k = kidnap(LocalizerOptions{});
  ASSERT_TRUE(k.noticed_after_s.has_value());
  EXPECT_EQ(*k.noticed_after_s, 0.0);
  EXPECT_EQ(k.stats.jumps, 1);
  EXPECT_EQ(k.stats.glitches, 0);  // the scans never come back to where they were
  ASSERT_TRUE(k.found_after_s.has_value());
  EXPECT_LE(*k.found_after_s, 8.0);
  EXPECT_GE(k.stats.relocalizations, 1);
}

TEST(Localizer, AKidnappedRobotIsLostWhereTheScansDoNotShowAJump) {
  // With the jump test off, the map's contradiction alone notices the kidnapping.
  LocalizerOptions options;
  options.min_scan_agreement = 0.0;
  const Kidnapping k = kidnap(options);
  EXPECT_EQ(k.stats.jumps, 0);
  ASSERT_TRUE(k.noticed_after_s.has_value());
  EXPECT_LE(*k.noticed_after_s, options.lost_after_s + 0.5);
  ASSERT_TRUE(k.found_after_s.has_value());
  EXPECT_LE(*k.found_after_s, 8.0);
  EXPECT_GE(k.stats.losses, 1);
  EXPECT_GE(k.stats.relocalizations, 1);
}

TEST(Localizer, OneBadScanIsAGlitchNotAKidnapping) {
  // One scan of the run is another place's (a bad scan); the next agrees with the one before it
  // again, so the doubt ends there: confident again at once, and no loss.
  const SimulatedLaserRun run = office_run(11, 20.0);
  const SimulatedLaserRun elsewhere = office_run(32, 20.0);
  const LocalizerOptions options;
  Localizer localizer(office_map(), options);
  localizer.set_pose(run.truth.front().pose);
  constexpr std::size_t kBad = 50;
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    StampedScan scan = run.log.scans[i];
    if (i == kBad) scan.scan = elsewhere.log.scans[i].scan;
    const LocalizedScan s = localizer.add_scan(scan);
    ASSERT_NE(s.state, LocalizationState::kLost) << "scan " << i;
    if (i == kBad) {
      EXPECT_FALSE(s.confident);
      continue;
    }
    EXPECT_TRUE(s.confident) << "scan " << i;
    EXPECT_LT(error_of(s.T_map_robot, run.truth[i].pose).m, 0.1) << "scan " << i;
  }
  EXPECT_EQ(localizer.stats().jumps, 1);
  EXPECT_EQ(localizer.stats().glitches, 1);
  EXPECT_EQ(localizer.stats().losses, 0);
}

/// Runs the localizer from the true start over the run, the sensor blind (no returns) from scan
/// kBlindFrom until the robot has driven `blind_m`: odometry alone carries the pose. Returns the
/// answers from the first scan after the blind stretch on, and the stats.
struct AfterBlindStretch {
  std::vector<LocalizedScan> answers;
  LocalizerStats stats;
};
AfterBlindStretch after_blind_stretch(const LocalizerOptions& options, double blind_m) {
  const SimulatedLaserRun run = office_run(11, 40.0);
  Localizer localizer(office_map(), options);
  localizer.set_pose(run.truth.front().pose);
  constexpr std::size_t kBlindFrom = 20;
  double driven_m = 0.0;
  AfterBlindStretch out;
  for (std::size_t i = 0; i < run.log.scans.size(); ++i) {
    StampedScan scan = run.log.scans[i];
    const bool blind = i >= kBlindFrom && driven_m < blind_m;
    if (i > kBlindFrom) {
      driven_m += (run.truth[i].pose.translation() - run.truth[i - 1].pose.translation()).norm();
    }
    if (blind) {
      std::fill(scan.scan.ranges_m.begin(), scan.scan.ranges_m.end(), scan.scan.max_range_m);
    }
    const LocalizedScan s = localizer.add_scan(scan);
    if (i >= kBlindFrom && !blind) out.answers.push_back(s);
  }
  out.stats = localizer.stats();
  return out;
}

TEST(Localizer, APoseCarriedFarWithoutTheMapIsConfirmedBySearchBeforeItIsTrusted) {
  // Odometry carried the pose 3 m with no return from the map: when the scans come back, the
  // pose may fit a look-alike place (ACES: 2.8 m along a corridor, decision 0043), so it is
  // trusted again only once a global search has placed the robot; carried 1 m, at once.
  const LocalizerOptions options;
  const AfterBlindStretch far = after_blind_stretch(options, 3.0);
  ASSERT_FALSE(far.answers.empty());
  EXPECT_EQ(far.stats.strays, 1);
  const auto first_trusted = std::find_if(far.answers.begin(), far.answers.end(),
                                          [](const LocalizedScan& s) { return s.confident; });
  ASSERT_NE(first_trusted, far.answers.end());
  EXPECT_EQ(first_trusted->state, LocalizationState::kRelocalized);
  EXPECT_FALSE(far.answers.front().confident);

  const AfterBlindStretch near = after_blind_stretch(options, 1.0);
  ASSERT_FALSE(near.answers.empty());
  EXPECT_EQ(near.stats.strays, 0);
  EXPECT_TRUE(near.answers.front().confident);
  EXPECT_EQ(near.stats.searches, 0);
}

TEST(Localizer, ASymmetricRoomIsNeverClaimed) {
  // A bare rectangle looks the same turned by half a turn: two places explain every scan, so no
  // search may accept one.
  const SimulatedLaserRun run = bare_room_run(20.0);
  const LocalizerOptions options;
  Localizer localizer(map_at_truth(run), options);
  for (const StampedScan& scan : run.log.scans) {
    EXPECT_EQ(localizer.add_scan(scan).state, LocalizationState::kLost);
  }
  EXPECT_GT(localizer.stats().searches, 0);
  EXPECT_EQ(localizer.stats().ambiguous, localizer.stats().searches);
}

// A robot standing still in the bare room: the view does not change, so after an ambiguous
// search the next waits for the robot to move (or for max_idle_search_s), instead of asking the
// same question every search_every_s. Once it drives, the searches come at their pace again.
TEST(Localizer, AnUnplacedViewIsSearchedAgainOnlyWhenItChanges) {
  const SimulatedLaserRun run = bare_room_run(10.0);
  std::vector<StampedScan> scans;
  for (int k = 0; k < 100; ++k) {  // 20 s standing at the first scan's pose, 5 scans a second
    StampedScan s = run.log.scans.front();
    s.t_s = 0.2 * k;
    scans.push_back(s);
  }
  const LocalizerOptions options;
  Localizer still(map_at_truth(run), options);
  for (const StampedScan& s : scans) EXPECT_EQ(still.add_scan(s).state, LocalizationState::kLost);
  // One search at the start, then one every max_idle_search_s (5 s): at 0, 5, 10 and 15 s.
  EXPECT_EQ(still.stats().searches, 4);
  EXPECT_EQ(still.stats().ambiguous, 4);

  // Asked every time (at the scans' pace, 0.6 s apart): 34 searches, all ambiguous.
  LocalizerOptions every_time = options;
  every_time.max_idle_search_s = options.search_every_s;
  Localizer eager(map_at_truth(run), every_time);
  for (const StampedScan& s : scans) (void)eager.add_scan(s);
  EXPECT_EQ(eager.stats().searches, 34);

  // Then it drives (the run's own scans, after the standing ones): its view changes, and it is
  // searched as often as the eager localizer searches it.
  const int still_before = still.stats().searches;
  const int eager_before = eager.stats().searches;
  for (const StampedScan& s : run.log.scans) {
    StampedScan later = s;
    later.t_s += 20.0;
    (void)still.add_scan(later);
    (void)eager.add_scan(later);
  }
  const int eager_driving = eager.stats().searches - eager_before;
  EXPECT_GT(eager_driving, 10);
  EXPECT_GE(still.stats().searches - still_before, eager_driving - 1);
}

/// The room's map with a square block of wall of side `side_m` from (1.5, 1.2) m, where the robot
/// sees open floor (furniture since removed, or a look-alike place whose walls fit the returns
/// but stand in the view's free space). Returns how many known cells it covers.
int add_block(ProbabilityGrid& map, double side_m) {
  const GridGeometry& g = map.geometry();
  int blocked = 0;
  for (double y = 1.2; y < 1.2 + side_m; y += 0.025) {
    for (double x = 1.5; x < 1.5 + side_m; x += 0.025) {
      const Cell c = g.cell_at_unchecked({x, y});
      if (g.contains(c) && map.known(c) && map.probability(c) < 0.9f) {
        map.set_probability(c, 0.9);
        ++blocked;
      }
    }
  }
  return blocked;
}

/// Every confident answer of a localizer over the run's scans.
std::vector<LocalizedScan> confident_poses(const ProbabilityGrid& map, const SimulatedLaserRun& run,
                                           const LocalizerOptions& options) {
  Localizer localizer(map, options);
  std::vector<LocalizedScan> confident;
  for (const StampedScan& scan : run.log.scans) {
    const LocalizedScan at = localizer.add_scan(scan);
    if (at.confident) confident.push_back(at);
  }
  return confident;
}

TEST(Localizer, APoseTheMapExplainsOnlyHalfIsFollowedButNotTrusted) {
  // A session that saw the room's walls only faintly (once, from afar): every wall cell at 0.55.
  // The scans still land on those walls, so the pose is followed and never lost, but it fits
  // only as well as a pose slid along a corridor seen from its end does (0.51-0.56 on ACES,
  // decision 0043): not trusted. Trusted at that fit when min_confident_fit is lowered.
  Result<SimulatedLaserRun> run =
      simulate_laser_run(support::text_world(room_rows(true), 0.1), room_run_options(10.0), 7);
  ASSERT_TRUE(run.ok()) << run.error().message;
  ProbabilityGrid map = map_at_truth(*run);
  const GridGeometry& g = map.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (map.known({x, y}) && map.probability({x, y}) > 0.55f) map.set_probability({x, y}, 0.55);
    }
  }
  const auto follow = [&](const LocalizerOptions& options) {
    Localizer localizer(map, options);
    localizer.set_pose(run->truth.front().pose);
    int trusted = 0;
    for (std::size_t i = 0; i < run->log.scans.size(); ++i) {
      const LocalizedScan s = localizer.add_scan(run->log.scans[i]);
      EXPECT_NE(s.state, LocalizationState::kLost) << "scan " << i;
      EXPECT_LT(error_of(s.T_map_robot, run->truth[i].pose).m, 0.1) << "scan " << i;
      EXPECT_GE(s.map_fit, options.min_tracking_score) << "scan " << i;
      EXPECT_LT(s.map_fit, LocalizerOptions{}.min_confident_fit) << "scan " << i;
      trusted += s.confident ? 1 : 0;
    }
    return trusted;
  };
  LocalizerOptions options;
  EXPECT_EQ(follow(options), 0);
  options.min_confident_fit = options.min_tracking_score;
  EXPECT_EQ(follow(options), static_cast<int>(run->log.scans.size()));
}

TEST(Localizer, AViewThatSeesThroughTheMapsWallsIsRefused) {
  // An L-shaped room (no symmetry), mapped; then the map gets a 1.5 m block of wall in the middle
  // of the room, where the robot now sees open floor. The returns still fit the room's walls
  // best, unambiguously: only the free-space test refuses the place, and with that test switched
  // off the same search accepts it.
  Result<SimulatedLaserRun> run =
      simulate_laser_run(support::text_world(room_rows(true), 0.1), room_run_options(10.0), 7);
  ASSERT_TRUE(run.ok()) << run.error().message;
  LocalizerOptions options;
  ProbabilityGrid map = map_at_truth(*run);
  ASSERT_GT(add_block(map, 1.5), 500);

  EXPECT_TRUE(confident_poses(map, *run, options).empty());
  options.max_free_conflict = 1.0;
  const std::vector<LocalizedScan> accepted = confident_poses(map, *run, options);
  ASSERT_FALSE(accepted.empty());
  const std::size_t i = static_cast<std::size_t>(
      std::find_if(run->log.scans.begin(), run->log.scans.end(),
                   [&](const StampedScan& s) { return s.t_s == accepted.front().t_s; }) -
      run->log.scans.begin());
  ASSERT_LT(i, run->truth.size());
  EXPECT_LT(error_of(accepted.front().T_map_robot, run->truth[i].pose).m, 0.1);
}

TEST(Localizer, AViewThatSeesThroughAFewPercentOfTheWallsIsRefused) {
  // A 0.8 m block: the views see through 3.7-5.3 % of the mapped cells their free space covers, as
  // the look-alike places of the Intel lab did that the old bound (5 %) let through (decision
  // 0041). Never confident now (0.75-0.9 m blocks alike; smaller ones are seen through by less
  // than 3 % somewhere along the run); with the old bound the same searches accept the place.
  Result<SimulatedLaserRun> run =
      simulate_laser_run(support::text_world(room_rows(true), 0.1), room_run_options(10.0), 7);
  ASSERT_TRUE(run.ok()) << run.error().message;
  ProbabilityGrid map = map_at_truth(*run);
  ASSERT_GT(add_block(map, 0.8), 0);
  LocalizerOptions options;
  EXPECT_TRUE(confident_poses(map, *run, options).empty());
  options.max_free_conflict = 0.05;
  EXPECT_FALSE(confident_poses(map, *run, options).empty());
}

// Two identical L-shaped rooms side by side, closed to each other: a robot in the left one sees
// exactly what it would see in the right one, so no search may claim either. In the session's
// map the right room has a 1.5 m block in the open (a cupboard since moved); where the view would
// see through it, that place is passed over, and the robot is found in the left room at once.
// Without passing over (max_runner_ups = 0) the block changes nothing: still ambiguous.
TEST(Localizer, LookAlikeRoomsAreToldApartByWhatStandsInTheOpen) {
  std::vector<std::string> rows;
  for (const std::string& r : room_rows(true)) rows.push_back(r + r);
  const World world = support::text_world(rows, 0.1);
  const LaserRunOptions o = room_run_options(10.0);
  // The simulator starts every run in the left room; the right one is mapped by the same scans
  // placed 6 m to the right.
  Result<SimulatedLaserRun> mapping = simulate_laser_run(world, o, 1);
  ASSERT_TRUE(mapping.ok()) << mapping.error().message;
  std::vector<const StampedScan*> scans;
  std::vector<Pose2> poses;
  for (const double dx_m : {0.0, 6.0}) {
    for (std::size_t i = 0; i < mapping->log.scans.size(); ++i) {
      scans.push_back(&mapping->log.scans[i]);
      poses.push_back({mapping->truth[i].pose.x + dx_m, mapping->truth[i].pose.y,
                       mapping->truth[i].pose.theta});
    }
  }
  const ProbabilityGrid twins =
      frozen_map(scans, poses, LocalizerOptions{}.points, RangeInsertOptions{}, 0.05);
  ProbabilityGrid with_block = twins;
  const GridGeometry& g = with_block.geometry();
  for (double y = 1.2; y < 2.7; y += 0.025) {
    for (double x = 7.5; x < 9.0; x += 0.025) {
      const Cell c = g.cell_at_unchecked({x, y});
      if (g.contains(c) && with_block.known(c)) with_block.set_probability(c, 0.9);
    }
  }

  for (const std::uint64_t seed : {2, 3}) {
    Result<SimulatedLaserRun> run = simulate_laser_run(world, o, seed);
    ASSERT_TRUE(run.ok()) << run.error().message;
    ASSERT_LT(run->truth.front().pose.x, 6.0);
    const auto localize = [&](const ProbabilityGrid& map, int max_runner_ups) {
      LocalizerOptions options;
      options.max_runner_ups = max_runner_ups;
      Localizer localizer(map, options);
      std::optional<double> found_at_s;
      for (std::size_t i = 0; i < run->log.scans.size(); ++i) {
        const LocalizedScan s = localizer.add_scan(run->log.scans[i]);
        if (!s.confident) continue;
        if (!found_at_s) found_at_s = s.t_s - run->log.scans.front().t_s;
        EXPECT_LT(error_of(s.T_map_robot, run->truth[i].pose).m, 0.1) << "seed " << seed;
      }
      return found_at_s;
    };
    EXPECT_FALSE(localize(twins, LocalizerOptions{}.max_runner_ups).has_value()) << seed;
    EXPECT_FALSE(localize(with_block, 0).has_value()) << seed;
    const std::optional<double> found = localize(with_block, LocalizerOptions{}.max_runner_ups);
    ASSERT_TRUE(found.has_value()) << seed;
    EXPECT_LE(*found, 1.0) << seed;
  }
}

TEST(Localizer, OptionsOutsideTheirRangeAreNamed) {
  LocalizerOptions o;
  EXPECT_FALSE(validate(o).has_value());
  o.ambiguity_ratio = 1.5;
  EXPECT_EQ(validate(o).value_or(""), "ambiguity_ratio must be in (0, 1]");
  o = {};
  o.min_tracking_score = 0.95;
  EXPECT_EQ(validate(o).value_or(""), "min_tracking_score must be in (0.1, 0.9)");
  o = {};
  o.max_untrusted_travel_m = 0.0;
  EXPECT_EQ(validate(o).value_or(""), "max_untrusted_travel_m must be > 0");
  o = {};
  o.min_confident_fit = 0.45;
  EXPECT_EQ(validate(o).value_or(""), "min_confident_fit must be in [min_tracking_score, 0.9)");
  o = {};
  o.view_s = 0.0;
  EXPECT_EQ(validate(o).value_or(""), "view_s must be > 0");
  o = {};
  o.max_runner_ups = -1;
  EXPECT_EQ(validate(o).value_or(""), "max_runner_ups must be >= 0");
  o = {};
  o.min_search_score = 0.05;
  EXPECT_EQ(validate(o).value_or(""), "min_search_score must be in (0.1, 0.9)");
  o = {};
  o.max_idle_search_s = -1.0;
  EXPECT_EQ(validate(o).value_or(""), "max_idle_search_s must be >= 0");
  o = {};
  o.new_view_motion.angular_rad = -0.1;
  EXPECT_EQ(validate(o).value_or(""), "new_view_motion must be >= 0");
  o = {};
  o.min_scan_agreement = 1.2;
  EXPECT_EQ(validate(o).value_or(""), "min_scan_agreement must be in [0, 1]");
  o = {};
  o.min_scan_compared = 0;
  EXPECT_EQ(validate(o).value_or(""), "min_scan_compared must be >= 1");
  o = {};
  o.scan_agreement.agreement_m = -0.1;
  EXPECT_EQ(validate(o).value_or(""), "scan_agreement must be >= 0");
  o = {};
  o.max_glitch_s = -1.0;
  EXPECT_EQ(validate(o).value_or(""), "max_glitch_s must be >= 0");
}

}  // namespace
}  // namespace tessera::slam
