#include "tessera/slam/submap_trimmer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <vector>

#include "laser_test_world.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/laser_run.hpp"

namespace tessera::slam {
namespace {

/// Two 6 m x 6 m rooms side by side, joined by a 1 m door in the wall between them.
World two_rooms() {
  constexpr double kRes = 0.02;
  const GridGeometry g({0.0, 0.0}, kRes, 650, 330);
  std::vector<std::uint8_t> solid(g.size(), 0);
  const auto fill = [&](double x0, double y0, double x1, double y1) {
    testing::fill_box(g, solid, x0, y0, x1, y1);
  };
  fill(0.0, 0.0, 13.0, 0.2);
  fill(0.0, 6.2, 13.0, 6.6);
  fill(0.0, 0.0, 0.2, 6.6);
  fill(12.8, 0.0, 13.0, 6.6);
  fill(6.3, 0.0, 6.5, 2.6);  // the middle wall, a door at y 2.6-3.6
  fill(6.3, 3.6, 6.5, 6.6);
  fill(2.0, 4.5, 2.6, 5.1);  // a box in each room
  fill(9.4, 1.0, 10.2, 1.5);
  return World(g, std::move(solid), "two rooms");
}

/// A session of scans taken at `poses` (their true poses are the optimised ones), with a node at
/// every even scan and the nodes grouped into submaps of consecutive nodes as `submap_nodes`
/// lists them (indices of scans).
struct TestSession {
  std::vector<StampedScan> scans;
  std::vector<StampedPose2> trajectory;
  posegraph::PoseGraph graph;
  std::vector<int> vertex_scan;
};

TestSession session_at(const World& world, const std::vector<Pose2>& poses,
                       const std::vector<std::vector<int>>& submap_nodes) {
  TestSession s;
  for (std::size_t i = 0; i < poses.size(); ++i) {
    StampedScan scan;
    scan.t_s = 0.2 * static_cast<double>(i);
    scan.odometry = poses[i];
    scan.scan = testing::ideal_scan(world, poses[i]);
    s.scans.push_back(scan);
    s.trajectory.push_back({scan.t_s, poses[i]});
  }
  std::vector<int> vertex_of_scan(poses.size(), -1);
  for (std::size_t i = 0; i < poses.size(); i += 2) {
    vertex_of_scan[i] = static_cast<int>(s.vertex_scan.size());
    s.vertex_scan.push_back(static_cast<int>(i));
    s.graph.poses.push_back(poses[i]);
  }
  for (const std::vector<int>& nodes : submap_nodes) {
    const int submap = static_cast<int>(s.vertex_scan.size());
    s.vertex_scan.push_back(-1);
    s.graph.poses.push_back(poses[static_cast<std::size_t>(nodes.front())]);
    for (const int scan : nodes) {
      s.graph.edges.push_back({submap,
                               vertex_of_scan[static_cast<std::size_t>(scan)],
                               {},
                               Eigen::Matrix3d::Identity(),
                               false});
    }
  }
  // A loop closure (robust) from the last submap to the first node: not a membership.
  s.graph.edges.push_back(
      {static_cast<int>(s.vertex_scan.size()) - 1, 0, {}, Eigen::Matrix3d::Identity(), true});
  s.graph.ids.resize(s.graph.poses.size());
  for (std::size_t v = 0; v < s.graph.ids.size(); ++v) s.graph.ids[v] = static_cast<int>(v);
  return s;
}

const std::vector<Pose2> kRoomA = {{2.0, 2.0, 0.0}, {2.5, 2.2, 0.3},  {3.0, 3.0, 1.0},
                                   {3.5, 3.0, 1.2}, {4.5, 3.1, -0.4}, {5.0, 3.0, 0.0}};
const std::vector<Pose2> kRoomB = {{8.0, 3.0, 0.0},  {9.0, 2.5, 0.5},   {10.0, 4.0, 2.0},
                                   {10.5, 4.2, 2.2}, {11.0, 3.0, -1.0}, {11.2, 2.8, -1.1}};

std::vector<Pose2> joined(std::initializer_list<std::vector<Pose2>> parts) {
  std::vector<Pose2> out;
  for (const std::vector<Pose2>& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

// The issue 16 case: the earlier pass went through both rooms, the newer one only through room
// A. Room A's submap of the earlier pass is trimmed with the nodes only it holds and the scans
// placed from them; room B's is kept, with the node it shares with room A's; the newer pass is
// kept whole; the kept scans form two trajectories, each started where the session had it.
TEST(SubmapTrimmer, AnEarlierPassIsTrimmedWhereANewerOneSawTheSameRooms) {
  const World world = two_rooms();
  const std::vector<Pose2> poses = joined({kRoomA, kRoomB, kRoomA});
  // Scans 0-11: the first pass (nodes 0, 2, ..., 10); scans 12-17: the second (nodes 12-16).
  const TestSession s = session_at(world, poses, {{0, 2, 4}, {4, 6, 8, 10}, {12, 14, 16}});
  const std::vector<TrajectoryStart> starts = {{12, poses[12]}};
  const SubmapTrim trim =
      trim_covered_submaps(s.scans, s.trajectory, starts, s.graph, s.vertex_scan, {});
  EXPECT_EQ(trim.submaps, 3);
  EXPECT_EQ(trim.submaps_trimmed, 1);
  ASSERT_EQ(trim.fresh_shares.size(), 2u);  // the earlier pass's submaps
  EXPECT_LT(trim.fresh_shares[0], 0.1);
  EXPECT_GT(trim.fresh_shares[1], 0.2);  // measured 0.27: room A sees into B through the door
  EXPECT_EQ(trim.nodes, 9);
  EXPECT_EQ(trim.nodes_trimmed, 2);  // scans 0 and 2; 4 is also in room B's submap
  std::vector<int> expected_scans;
  for (int i = 4; i < 18; ++i) expected_scans.push_back(i);
  EXPECT_EQ(trim.kept_scans, expected_scans);
  ASSERT_EQ(trim.starts.size(), 2u);
  EXPECT_EQ(trim.starts[0].first_scan, 0);  // the first kept scan, where the session had it
  EXPECT_EQ(trim.starts[0].T_map_robot.x, poses[4].x);
  EXPECT_EQ(trim.starts[1].first_scan, 8);  // the newer pass
  EXPECT_EQ(trim.starts[1].T_map_robot.x, poses[12].x);
  EXPECT_EQ(trajectory_count(trim.starts), 2);
  ASSERT_EQ(trim.fresh_areas_m2.size(), 2u);
  EXPECT_LT(trim.fresh_areas_m2[0], 1.0);
  EXPECT_GT(trim.fresh_areas_m2[1], 10.0);

  // Room B's submap is kept for the patch only it saw, even where its share would not keep it;
  // without that test it goes too.
  SubmapTrimOptions share_alone;
  share_alone.min_fresh_share = 0.5;
  EXPECT_EQ(trim_covered_submaps(s.scans, s.trajectory, starts, s.graph, s.vertex_scan, share_alone)
                .submaps_trimmed,
            1);
  share_alone.min_fresh_area_m2 = 1e9;
  EXPECT_EQ(trim_covered_submaps(s.scans, s.trajectory, starts, s.graph, s.vertex_scan, share_alone)
                .submaps_trimmed,
            2);
}

// A segment from the middle of an earlier pass becomes a trajectory of its own: the pass went
// A, B, A, and the newer one saw only room A.
TEST(SubmapTrimmer, WhatIsLeftOfAPassBetweenTrimmedPartsIsATrajectoryOfItsOwn) {
  const World world = two_rooms();
  const std::vector<Pose2> poses = joined({kRoomA, kRoomB, kRoomA, kRoomA});
  const TestSession s =
      session_at(world, poses, {{0, 2}, {4}, {6, 8, 10}, {12, 14, 16}, {18, 20, 22}});
  const SubmapTrim trim =
      trim_covered_submaps(s.scans, s.trajectory, {{18, poses[18]}}, s.graph, s.vertex_scan, {});
  EXPECT_EQ(trim.submaps_trimmed, 3);  // both room A submaps of the first pass, and scan 4's
  std::vector<int> expected_scans;
  for (int i = 6; i < 12; ++i) expected_scans.push_back(i);
  for (int i = 18; i < 24; ++i) expected_scans.push_back(i);
  EXPECT_EQ(trim.kept_scans, expected_scans);
  ASSERT_EQ(trim.starts.size(), 2u);
  EXPECT_EQ(trim.starts[0].first_scan, 0);
  EXPECT_EQ(trim.starts[0].T_map_robot.y, poses[6].y);
  EXPECT_EQ(trim.starts[1].first_scan, 6);
}

// One run revisits its own rooms: nothing is trimmed (only earlier trajectories are), and a
// newer pass that saw another room trims nothing either.
TEST(SubmapTrimmer, OneRunAndPassesThatSawOtherRoomsKeepEverything) {
  const World world = two_rooms();
  const std::vector<Pose2> poses = joined({kRoomA, kRoomB, kRoomA});
  const TestSession s = session_at(world, poses, {{0, 2, 4}, {6, 8, 10}, {12, 14, 16}});
  const SubmapTrim one_run =
      trim_covered_submaps(s.scans, s.trajectory, {}, s.graph, s.vertex_scan, {});
  EXPECT_EQ(one_run.submaps_trimmed, 0);
  EXPECT_EQ(one_run.kept_scans.size(), poses.size());
  EXPECT_TRUE(one_run.starts.empty());

  const std::vector<Pose2> apart = joined({kRoomA, kRoomB});
  const TestSession t = session_at(world, apart, {{0, 2, 4}, {6, 8, 10}});
  // (Room B's scans see into room A through the door: part of it, not all.)
  const SubmapTrim other_room =
      trim_covered_submaps(t.scans, t.trajectory, {{6, apart[6]}}, t.graph, t.vertex_scan, {});
  EXPECT_EQ(other_room.submaps_trimmed, 0);
  EXPECT_EQ(other_room.kept_scans.size(), apart.size());
  ASSERT_EQ(other_room.starts.size(), 1u);
  EXPECT_EQ(other_room.starts[0].first_scan, 6);

  // A session trimmed before places its first scan; kept, it is placed there again.
  const SubmapTrim placed = trim_covered_submaps(
      t.scans, t.trajectory, {{0, apart[0]}, {6, apart[6]}}, t.graph, t.vertex_scan, {});
  ASSERT_EQ(placed.starts.size(), 2u);
  EXPECT_EQ(placed.starts[0].first_scan, 0);
  EXPECT_EQ(placed.starts[0].T_map_robot.x, apart[0].x);
  EXPECT_EQ(placed.starts[1].first_scan, 6);
  EXPECT_EQ(trajectory_count(placed.starts), 2);
}

/// A simulated run through the built-in office (as laser_slam_test's, shorter).
SimulatedLaserRun office_run(const World& world) {
  LaserRunOptions o;
  o.lidar.beams = 180;
  o.lidar.max_range_m = 10.0;
  o.scan_rate_hz = 5.0;
  o.max_duration_s = 40.0;
  o.start = Pose2{2.0, 2.0, 0.0};
  o.odometry.heading_drift_rad_per_m = 0.01;
  Result<SimulatedLaserRun> r = simulate_laser_run(world, o, 7);
  EXPECT_TRUE(r.ok()) << r.error().message;
  return std::move(r).value();
}

/// The shared small-submap options on the office's 0.1 m cells.
LaserSlamOptions small_submaps() {
  LaserSlamOptions o = testing::small_submaps();
  o.map_resolution_m = 0.1;
  return o;
}

int occupied_cells_in(const OccupancyGrid& map, Vec2 lo, Vec2 hi) {
  int n = 0;
  for (double y = lo.y + 0.05; y < hi.y; y += 0.1) {
    for (double x = lo.x + 0.05; x < hi.x; x += 0.1) {
      const std::optional<Cell> c = map.geometry().cell_at({x, y});
      if (c && map.known(*c) && map.probability_at(*c).value_or(0.0) > 0.5) ++n;
    }
  }
  return n;
}

// Issue 16: "the map still shows the building as it is now (a moved obstacle disappears after it
// is seen gone)". A box stood beside the route when the session was mapped and is gone when it
// is resumed along the same route: the saved (trimmed and replayed) session's map shows the
// floor there, as the new pass saw it.
TEST(SubmapTrimmer, AnObstacleSeenGoneByANewerPassLeavesTheSavedMap) {
  const World office = builtin_world("office", 0.1);
  const SimulatedLaserRun now = office_run(office);
  // A 0.4 m box 0.9 m beside the route at 40 % of it, on open floor.
  const Pose2 beside = now.truth[now.truth.size() * 2 / 5].pose * Pose2{0.0, 0.9, 0.0};
  const Vec2 lo{beside.x - 0.2, beside.y - 0.2}, hi{beside.x + 0.2, beside.y + 0.2};
  std::vector<std::uint8_t> solid(office.solid_cells().begin(), office.solid_cells().end());
  const std::size_t solid_before =
      static_cast<std::size_t>(std::count(solid.begin(), solid.end(), 1));
  testing::fill_box(office.geometry(), solid, lo.x, lo.y, hi.x, hi.y);
  // On open floor: every cell of the box was free (0.4 m at 0.1 m cells: 16 cells).
  ASSERT_EQ(static_cast<std::size_t>(std::count(solid.begin(), solid.end(), 1)), solid_before + 16);
  const SimulatedLaserRun then = office_run(World(office.geometry(), solid, "office with a box"));

  const Result<LaserSlamResult> mapped_then = run_laser_slam(then.log, small_submaps());
  LaserLog both = then.log;
  both.scans.insert(both.scans.end(), now.log.scans.begin(), now.log.scans.end());
  const std::vector<TrajectoryStart> starts = {
      {static_cast<int>(then.log.scans.size()), now.truth.front().pose}};
  const Result<LaserSlamResult> resumed = run_laser_slam(both, small_submaps(), starts);
  ASSERT_TRUE(mapped_then.ok() && resumed.ok());
  const Result<TrimmedRun> saved = trim_and_replay(both, starts, *resumed, small_submaps(), {});
  ASSERT_TRUE(saved.ok()) << saved.error().message;
  std::printf(
      "box cells occupied: mapped then %d, resumed %d, saved %d; submaps trimmed %d of "
      "%d, scans kept %zu of %zu\n",
      occupied_cells_in(mapped_then->map, lo, hi), occupied_cells_in(resumed->map, lo, hi),
      occupied_cells_in(saved->result.map, lo, hi), saved->trim.submaps_trimmed,
      saved->trim.submaps, saved->log.scans.size(), both.scans.size());
  EXPECT_GE(occupied_cells_in(mapped_then->map, lo, hi), 3);
  ASSERT_LT(saved->log.scans.size(), both.scans.size());
  EXPECT_EQ(occupied_cells_in(saved->result.map, lo, hi), 0);
  // The newer pass is kept whole, and the saved state is the replay of what was kept.
  EXPECT_GE(saved->log.scans.size(), now.log.scans.size());
  EXPECT_EQ(saved->result.trajectory.size(), saved->log.scans.size());
}

}  // namespace
}  // namespace tessera::slam
