#include "tessera/slam/gridmatch.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "tessera/core/rng.hpp"
#include "tessera/sensors/lidar.hpp"
#include "tessera/sim/builtin_world.hpp"
#include "tessera/sim/simulator.hpp"
#include "tessera/sim/world.hpp"

namespace tessera::slam {
namespace {

using ::testing::ElementsAre;
using ::testing::ElementsAreArray;
using ::testing::HasSubstr;

constexpr double kDeg = std::numbers::pi / 180.0;

// ---- Helpers ----------------------------------------------------------------------------------

/// A World drawn as text, top row first ('#' solid, anything else free), cells cell_m wide.
World ascii_world(const std::vector<std::string>& rows_top_first, double cell_m) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first[0].size());
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(w * h), 0);
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const char ch = rows_top_first[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)];
      solid[static_cast<std::size_t>((h - 1 - row) * w + x)] = ch == '#' ? 1 : 0;
    }
  }
  return World(GridGeometry({0.0, 0.0}, cell_m, w, h), std::move(solid));
}

/// An occupancy grid drawn as text, top row first: '?' unknown, '#' obstacle (p = 0.9), anything
/// else open (p = 0.1), the lecture's figure values.
OccupancyGrid ascii_map(const std::vector<std::string>& rows_top_first, double cell_m) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first[0].size());
  OccupancyGrid map(GridGeometry({0.0, 0.0}, cell_m, w, h));
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const char ch = rows_top_first[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)];
      if (ch != '?') map.set_probability({x, h - 1 - row}, ch == '#' ? 0.9 : 0.1);
    }
  }
  return map;
}

/// A ternary grid drawn as text, top row first: '?' 0, '.' -1, '#' +1.
TernaryGrid ascii_ternary(const std::vector<std::string>& rows_top_first, double cell_m) {
  const int h = static_cast<int>(rows_top_first.size());
  const int w = static_cast<int>(rows_top_first[0].size());
  TernaryGrid g(GridGeometry({0.0, 0.0}, cell_m, w, h));
  for (int row = 0; row < h; ++row) {
    for (int x = 0; x < w; ++x) {
      const char ch = rows_top_first[static_cast<std::size_t>(row)][static_cast<std::size_t>(x)];
      if (ch != '?') g.set({x, h - 1 - row}, ch == '#' ? kTernaryOccupied : kTernaryFree);
    }
  }
  return g;
}

char symbol(std::int8_t v) { return v < 0 ? '.' : (v > 0 ? '#' : '?'); }

/// The map's threshold view as text, top row first.
std::vector<std::string> rows_of(const OccupancyGrid& m) {
  std::vector<std::string> rows;
  for (int y = m.geometry().height() - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < m.geometry().width(); ++x) row += symbol(ternary_value(m, {x, y}));
    rows.push_back(row);
  }
  return rows;
}

/// A ternary grid as text, top row first.
std::vector<std::string> rows_of(const TernaryGrid& g) {
  std::vector<std::string> rows;
  for (int y = g.geometry().height() - 1; y >= 0; --y) {
    std::string row;
    for (int x = 0; x < g.geometry().width(); ++x) row += symbol(g.at({x, y}));
    rows.push_back(row);
  }
  return rows;
}

/// A robot-frame grid drawn as the lecture draws it, for a robot moving up the page: the top row
/// is the farthest ahead (largest x), each row runs from the robot's left (largest y) to its right.
std::vector<std::string> heading_up_rows(const TernaryGrid& g) {
  std::vector<std::string> rows;
  for (int x = g.geometry().width() - 1; x >= 0; --x) {
    std::string row;
    for (int y = g.geometry().height() - 1; y >= 0; --y) row += symbol(g.at({x, y}));
    rows.push_back(row);
  }
  return rows;
}

/// An exact scan (no noise) of `world` from T_world_sensor.
RangeScan ideal_scan(const World& world, const Pose2& T_world_sensor, const LidarOptions& o) {
  RangeScan scan = empty_scan(o);
  for (std::size_t i = 0; i < scan.ranges_m.size(); ++i) {
    const double a = T_world_sensor.theta + scan.angle_min_rad +
                     static_cast<double>(i) * scan.angle_increment_rad;
    scan.ranges_m[i] = world.cast_ray(T_world_sensor.translation(), a, o.max_range_m);
  }
  return scan;
}

/// Every candidate as "(dx,dy,dh) S=.. of .." for failure messages.
std::string table(const GridMatchResult& r) {
  std::ostringstream os;
  for (const GridMatchCandidate& c : r.candidates) {
    os << "(" << c.offset.dx_steps << "," << c.offset.dy_steps << "," << c.offset.dheading_steps
       << ") S=" << c.similarity.score << " of " << c.similarity.overlap_cells << "\n";
  }
  return os.str();
}

/// S of the candidate with `offset`; fails the test if there is none.
int score_of(const GridMatchResult& r, CandidateOffset offset) {
  for (const GridMatchCandidate& c : r.candidates) {
    if (c.offset == offset) return c.similarity.score;
  }
  ADD_FAILURE() << "no candidate (" << offset.dx_steps << "," << offset.dy_steps << ","
                << offset.dheading_steps << ")";
  return 0;
}

double angle_error(double a, double b) { return std::fabs(normalize_angle(a - b)); }
double position_error(const Pose2& a, const Pose2& b) {
  return (a.translation() - b.translation()).norm();
}

// ---- The lecture's numerical example -----------------------------------------------------------
//
// Lecture, "Numerical example for a SLAM algorithm": the robot moves towards the top of the
// diagram, near a corner of the room, with a projection of the wall to its left (a supporting
// pillar). Cells are roughly the robot's size; every explored cell is either free or obstacle;
// walls are one cell thick; the robot senses walls up to 5 cells away. It moves one cell up, and
// odometry says it kept its heading, but its right wheel ran over a low-friction area: the actual
// heading is 15 degrees clockwise ("correct position, wrong heading"). The test poses are the
// expected cell and its four neighbours, each with the expected heading, 15 deg CW and 15 deg CCW;
// the maps compared are 8 x 5 (5 cells ahead, 2 behind, 2 to each side).
//
// The slides' figures are missing from the notes, so this is a room consistent with the text.

constexpr double kCellM = 0.3;  // "roughly the same size as the robot itself"
constexpr double kRangeM = 5.0 * kCellM;

/// The room (sim/builtin_world.cpp, "lecture-corner"), top row y = 8 first:
///   ############   the wall ahead; with the left wall it makes the corner
///   #...........
///   ##..........   y = 6: the pillar
///   ##..........   y = 5: the pillar
///   #...........   y = 4: the robot after the move, (3, 4)
///   #...........   y = 3: the robot before the move, (3, 3)
///   #...........
///   #...........
///   ############   y = 0
World lecture_room() { return builtin_world("lecture-corner", kCellM); }

LidarOptions lecture_lidar() {
  LidarOptions o;
  o.beams = 360;
  o.max_range_m = kRangeM;
  o.range_noise_stddev_m = 0.0;
  return o;
}

Pose2 at_cell(int x, int y, double theta) {
  return {(x + 0.5) * kCellM, (y + 0.5) * kCellM, theta};
}

/// The lecture's 8 x 5 window.
GridGeometry lecture_window() { return robot_window(kCellM, 2, 5, 2); }

/// The current map m of the example: what the robot perceived before the move, from (3, 3) heading
/// up, everything within its 5-cell range written in.
OccupancyGrid lecture_current_map(const World& room) {
  OccupancyGrid map(room.geometry());
  const Pose2 before = at_cell(3, 3, 0.5 * std::numbers::pi);
  (void)update_map(map,
                   perception_from_scan(ideal_scan(room, before, lecture_lidar()),
                                        robot_window(kCellM, kRangeM)),
                   before);
  return map;
}

TEST(LectureExample, CurrentMapIsWhatTheRobotSawBeforeTheMove) {
  const World room = lecture_room();
  // The corner and the pillar are known; the wall behind the pillar and everything beyond five
  // cells is unexplored ("?").
  EXPECT_THAT(rows_of(lecture_current_map(room)), ElementsAre("?#####??????",  //
                                                              "??....??????",  //
                                                              "?#.....?????",  //
                                                              "##......????",  //
                                                              "#.......????",  //
                                                              "#.......????",  //
                                                              "#.......????",  //
                                                              "#.......????",  //
                                                              "#########???"));
}

TEST(LectureExample, ActualPerceptionShowsTheWallsTurnedBy15Degrees) {
  const World room = lecture_room();
  const Pose2 actual = at_cell(3, 4, 0.5 * std::numbers::pi - 15.0 * kDeg);
  const TernaryGrid p =
      perception_from_scan(ideal_scan(room, actual, lecture_lidar()), lecture_window());
  // Drawn as the lecture draws it: the robot is in the middle of the sixth row, moving up. The
  // robot turned clockwise, so the room looks turned counter-clockwise: the pillar (rows 5 and 6,
  // two cells to the left) and the wall ahead, four cells ahead on the left but farther than five
  // (out of range) at the right end.
  EXPECT_THAT(heading_up_rows(p), ElementsAre("?????",  //
                                              "####.",  //
                                              ".....",  //
                                              ".....",  //
                                              "#....",  //
                                              "#....",  //
                                              ".....",  //
                                              "....."));
}

TEST(LectureExample, CorrectPositionWith15DegreesClockwiseWins) {
  const World room = lecture_room();
  const OccupancyGrid map = lecture_current_map(room);
  const Pose2 odometry =
      at_cell(3, 4, 0.5 * std::numbers::pi);  // "intended": one cell up, heading kept
  const Pose2 actual = at_cell(3, 4, 0.5 * std::numbers::pi - 15.0 * kDeg);
  const TernaryGrid p =
      perception_from_scan(ideal_scan(room, actual, lecture_lidar()), lecture_window());

  const GridMatchResult r = match(map, p, odometry);
  ASSERT_EQ(r.candidates.size(), 15u);
  EXPECT_EQ(r.winner().offset, (CandidateOffset{0, 0, -1})) << table(r);
  EXPECT_NEAR(position_error(r.T_map_robot(), actual), 0.0, 1e-12);
  EXPECT_NEAR(angle_error(r.T_map_robot().theta, actual.theta), 0.0, 1e-12);

  // Our S table in the layout of the lecture's table (a.t): rows intended position, up, down,
  // left, right; columns intended orientation, 15 deg CW, 15 deg CCW.
  const CandidateOffset positions[5] = {{0, 0, 0}, {0, 1, 0}, {0, -1, 0}, {-1, 0, 0}, {1, 0, 0}};
  std::vector<int> ours;
  for (const CandidateOffset& at : positions) {
    for (const int dh : {0, -1, 1}) ours.push_back(score_of(r, {at.dx_steps, at.dy_steps, dh}));
  }
  EXPECT_THAT(ours, ElementsAreArray({28, 34, 24,  //
                                      19, 19, 17,  //
                                      20, 23, 21,  //
                                      21, 26, 18,  //
                                      29, 27, 26}))
      << table(r);
  // The lecture's table: its winner is the same cell, (intended position, 15 deg CW) with 32,
  // 4 ahead of the next (down one cell, CW: 28) and 10 ahead of what odometry says (22). Ours
  // wins by 5 over the next (right one cell, intended heading: 29) and by 6 over odometry.
  const std::vector<int> lecture{22, 32, 20,  //
                                 23, 25, 16,  //
                                 19, 28, 21,  //
                                 6,  7,  18,  //
                                 22, 18, 18};
  const auto best_cell = [](const std::vector<int>& t) {
    return std::max_element(t.begin(), t.end()) - t.begin();
  };
  EXPECT_EQ(best_cell(lecture), 1);  // row "intended position", column "15 deg CW"
  EXPECT_EQ(best_cell(ours), best_cell(lecture));
  EXPECT_EQ(r.margin, 5);
  EXPECT_EQ(r.winner().similarity.score - r.candidates[0].similarity.score, 6);
  // At the true pose the perfect sensor and the map agree wherever both know a cell.
  EXPECT_EQ(r.winner().similarity.disagree_cells(), 0);
  EXPECT_EQ(r.winner().similarity.overlap_cells, 34);
}

TEST(LectureExample, UpdateAtTheWinningPoseAddsTheNewlySeenArea) {
  const World room = lecture_room();
  OccupancyGrid map = lecture_current_map(room);
  const Pose2 actual = at_cell(3, 4, 0.5 * std::numbers::pi - 15.0 * kDeg);
  const RangeScan scan = ideal_scan(room, actual, lecture_lidar());
  const GridMatchResult r = match(map, perception_from_scan(scan, lecture_window()),
                                  at_cell(3, 4, 0.5 * std::numbers::pi));
  ASSERT_EQ(r.winner().offset, (CandidateOffset{0, 0, -1}));
  // "More complicated in practice": the update writes everything within the sensor's five-cell
  // radius at the winning pose, so cells the map did not know are added, and cells beyond the
  // radius are not touched.
  const MapUpdateStats stats =
      update_map(map, perception_from_scan(scan, robot_window(kCellM, kRangeM)), r.T_map_robot());
  // One cell up, the range circle reaches two cells the map did not know: (6, 7) and (7, 6).
  EXPECT_THAT(rows_of(map), ElementsAre("?#####??????",  //
                                        "??.....?????",  //
                                        "?#......????",  //
                                        "##......????",  //
                                        "#.......????",  //
                                        "#.......????",  //
                                        "#.......????",  //
                                        "#.......????",  //
                                        "#########???"));
  EXPECT_EQ(stats.newly_known_cells, 2u);
  EXPECT_EQ(stats.flipped_cells, 0u);   // at the right pose nothing the map knew is contradicted
  EXPECT_GT(stats.written_cells, 40u);  // the known cells within range were written again
}

// ---- compare(p, e) ----------------------------------------------------------------------------

TEST(Similarity, FollowsTheLecturesThreeCases) {
  // Top row: one or both unknown (0 each); middle row: both known and different (-1 each); bottom
  // row: both known and equal (+1 each).
  const TernaryGrid p = ascii_ternary({"??.#", "#.#.", ".#.#"}, 1.0);
  const TernaryGrid e = ascii_ternary({".#??", ".#.#", ".#.#"}, 1.0);
  const Similarity s = similarity(p, e);
  EXPECT_EQ(s.agree_cells, 4);
  EXPECT_EQ(s.disagree_cells(), 4);
  EXPECT_EQ(s.overlap_cells, 8);
  EXPECT_EQ(s.score, 0);
  // The lecture's "Matrix (c)", cell by cell ('.' is -1, '#' is +1).
  EXPECT_THAT(rows_of(similarity_cells(p, e)), ElementsAre("????", "....", "####"));
  // S does not depend on which map is which.
  EXPECT_EQ(similarity(e, p), s);
}

TEST(Similarity, UnknownCellsContributeNothing) {
  const TernaryGrid p = ascii_ternary({"#..", "#.."}, 1.0);
  const TernaryGrid known = ascii_ternary({"#..", "#.."}, 1.0);
  const TernaryGrid half = ascii_ternary({"#..", "???"}, 1.0);
  EXPECT_EQ(similarity(p, known), (Similarity{6, 6, 6}));
  EXPECT_EQ(similarity(p, half), (Similarity{3, 3, 3}));
  // Unknown in the perception (beyond the sensor's range) is the same: 0.
  const TernaryGrid blind(p.geometry());
  EXPECT_EQ(similarity(blind, known), (Similarity{0, 0, 0}));
}

TEST(Similarity, OnlyTheOverlapOfPerceptionAndMapCounts) {
  // The map knows a 4 x 4 room; the robot, at its right edge, perceives cells beyond it. Those lie
  // outside the map (expected 0) and do not change S, whatever they hold.
  OccupancyGrid map = ascii_map({"####", "#...", "#...", "####"}, 1.0);
  const GridGeometry window = robot_window(1.0, 1, 3, 1);  // 5 x 3, robot in column 1
  const Pose2 T_map_robot{2.5, 1.5, 0.0};                  // cell (2, 1), facing +x
  TernaryGrid inside = expected_map(map, window, T_map_robot);
  // Drawn heading up: the bottom wall is on the robot's right; the two rows farthest ahead lie
  // beyond the map's right edge.
  EXPECT_THAT(heading_up_rows(inside), ElementsAre("???", "???", "..#", "..#", "..#"));
  const Similarity base = similarity(inside, expected_map(map, window, T_map_robot));
  EXPECT_EQ(base, (Similarity{9, 9, 9}));
  TernaryGrid beyond = inside;
  beyond.set({3, 0}, kTernaryOccupied);  // one cell beyond the map's edge, seen as obstacle
  beyond.set({4, 2}, kTernaryFree);
  EXPECT_EQ(similarity(beyond, expected_map(map, window, T_map_robot)), base);
}

// ---- The test poses T ------------------------------------------------------------------------

TEST(CandidateOffsets, DefaultsAreTheLecturesFivePositionsTimesThreeHeadings) {
  const std::vector<CandidateOffset> t = candidate_offsets(GridMatchOptions{});
  EXPECT_THAT(t, ElementsAre(CandidateOffset{0, 0, 0}, CandidateOffset{0, 0, -1},
                             CandidateOffset{0, 0, 1},  // the odometry position
                             CandidateOffset{0, 1, 0}, CandidateOffset{0, 1, -1},
                             CandidateOffset{0, 1, 1},  // up
                             CandidateOffset{-1, 0, 0}, CandidateOffset{-1, 0, -1},
                             CandidateOffset{-1, 0, 1},  // left
                             CandidateOffset{1, 0, 0}, CandidateOffset{1, 0, -1},
                             CandidateOffset{1, 0, 1},  // right
                             CandidateOffset{0, -1, 0}, CandidateOffset{0, -1, -1},
                             CandidateOffset{0, -1, 1}));  // down
}

TEST(CandidateOffsets, SearchIsConfigurable) {
  GridMatchOptions o;
  o.position_radius_steps = 2;
  EXPECT_EQ(candidate_offsets(o).size(), 13u * 3u);  // a diamond of 13 positions
  o.square_positions = true;
  EXPECT_EQ(candidate_offsets(o).size(), 25u * 3u);
  o.position_radius_steps = 0;
  o.heading_radius_steps = 3;
  const std::vector<CandidateOffset> t = candidate_offsets(o);
  ASSERT_EQ(t.size(), 7u);
  EXPECT_EQ(t[5], (CandidateOffset{0, 0, -3}));
  EXPECT_EQ(t[6], (CandidateOffset{0, 0, 3}));
  // Ring 1 of a square comes before ring 2, and every offset appears once.
  o.position_radius_steps = 2;
  o.heading_radius_steps = 0;
  const std::vector<CandidateOffset> sq = candidate_offsets(o);
  ASSERT_EQ(sq.size(), 25u);
  for (std::size_t k = 1; k < 9; ++k) {
    EXPECT_LE(std::max(std::abs(sq[k].dx_steps), std::abs(sq[k].dy_steps)), 1) << k;
  }
  for (std::size_t k = 0; k < sq.size(); ++k) {
    for (std::size_t j = k + 1; j < sq.size(); ++j) EXPECT_FALSE(sq[k] == sq[j]) << k << " " << j;
  }
}

TEST(CandidatePose, StepsAreCellsInTheMapsAxesAndHeadingSteps) {
  const GridGeometry map_geometry({0.0, 0.0}, 0.25, 20, 20);
  GridMatchOptions o;
  o.position_step_cells = 2.0;
  o.heading_step_rad = 10.0 * kDeg;
  o.snap_to_cell_centre = false;
  const Pose2 odometry{1.01, 2.02, 175.0 * kDeg};
  const Pose2 t = candidate_pose(map_geometry, odometry, {1, -1, 1}, o);
  EXPECT_DOUBLE_EQ(t.x, 1.51);  // the map's +x whatever the heading
  EXPECT_DOUBLE_EQ(t.y, 1.52);
  EXPECT_NEAR(t.theta, -175.0 * kDeg, 1e-12);  // wrapped into [-pi, pi)
  // The lecture's cells: the lattice starts at the centre of the cell odometry is in, (4, 8).
  o.snap_to_cell_centre = true;
  const Pose2 s = candidate_pose(map_geometry, odometry, {1, -1, 0}, o);
  EXPECT_DOUBLE_EQ(s.x, 1.125 + 0.5);
  EXPECT_DOUBLE_EQ(s.y, 2.125 - 0.5);
  EXPECT_DOUBLE_EQ(s.theta, odometry.theta);  // headings are not snapped
}

TEST(GridMatchOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(GridMatchOptions{}).has_value());
  const auto problem = [](auto mutate) {
    GridMatchOptions o;
    mutate(o);
    return validate(o).value_or("");
  };
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.position_radius_steps = -1; }),
              HasSubstr("position_radius_steps"));
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.position_step_cells = 0.0; }),
              HasSubstr("position_step_cells"));
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.heading_radius_steps = -1; }),
              HasSubstr("heading_radius_steps"));
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.heading_step_rad = -0.1; }),
              HasSubstr("heading_step_rad"));
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.heading_radius_steps = 13; }),
              HasSubstr("<= pi"));
  EXPECT_THAT(problem([](GridMatchOptions& o) { o.occupied_threshold = 1.0; }),
              HasSubstr("occupied_threshold"));
}

// ---- The search ---------------------------------------------------------------------------------

TEST(Match, TiesGoToTheFirstTestPoseWhichIsTheOdometryPose) {
  // An empty map tells nothing: every S is 0 and the odometry pose stays.
  const OccupancyGrid unknown(GridGeometry({0.0, 0.0}, 1.0, 10, 10));
  TernaryGrid p(robot_window(1.0, 2, 2, 2));
  p.set({0, 0}, kTernaryOccupied);
  const GridMatchResult r = match(unknown, p, {5.5, 5.5, 0.0});
  EXPECT_EQ(r.best, 0u);
  EXPECT_EQ(r.margin, 0);
  EXPECT_EQ(r.T_map_robot().x, 5.5);
}

TEST(Match, TiesGoToTheFirstInCandidateOrder) {
  // A corridor looks the same one cell up or down. Odometry puts the robot one cell left of the
  // corridor's middle, where it is; the three test poses in the middle column within reach tie,
  // and the first of them in candidate_offsets() order wins: ring 1, top row first.
  const OccupancyGrid map = ascii_map(std::vector<std::string>(9, "#...#"), 1.0);
  const GridGeometry window = robot_window(1.0, 2, 2, 2);
  const TernaryGrid p = expected_map(map, window, {2.5, 4.5, 0.0});
  GridMatchOptions o;
  o.square_positions = true;
  o.heading_radius_steps = 0;
  const GridMatchResult r = match(map, p, {1.5, 4.5, 0.0}, o);
  EXPECT_EQ(r.winner().offset, (CandidateOffset{1, 1, 0})) << table(r);
  EXPECT_EQ(r.winner().similarity, (Similarity{25, 25, 25}));
  EXPECT_EQ(score_of(r, {1, 0, 0}), 25);
  EXPECT_EQ(score_of(r, {1, -1, 0}), 25);
  EXPECT_EQ(r.margin, 0);
}

TEST(Match, CellRobotFindsItsCellFromItsEightNeighbours) {
  // The lecture's cell robot: only positions, no heading. Odometry puts it one cell left of where
  // it is; its 8 neighbours show the pillar's corner, which fits only the true cell.
  const std::vector<std::string> rows{"#####",  //
                                      "#...#",  //
                                      "#.#.#",  //
                                      "#...#",  //
                                      "#####"};
  const World world = ascii_world(rows, 1.0);
  Simulator sim(world, 1);
  const Result<int> robot = sim.add_robot({3, 1}, {});
  ASSERT_TRUE(robot.ok());
  const OccupancyGrid map = ascii_map(rows, 1.0);
  const TernaryGrid p = perception_from_cells(sim.sense_cells(*robot), 1.0);
  GridMatchOptions o;
  o.heading_radius_steps = 0;
  const GridMatchResult r = match(map, p, {2.5, 1.5, 0.0}, o);
  EXPECT_EQ(r.candidates.size(), 5u);
  EXPECT_EQ(r.winner().offset, (CandidateOffset{1, 0, 0})) << table(r);
  EXPECT_EQ(r.winner().similarity, (Similarity{9, 9, 9}));
}

// ---- m <- update(m, p, n) -----------------------------------------------------------------------

TEST(UpdateMap, WritesKnownPerceptionCellsAndLeavesTheRestAlone) {
  OccupancyGrid map = ascii_map({"??????",  //
                                 "??????",  //
                                 "#.....",  //
                                 "??????"},
                                1.0);
  // Robot at cell (2, 1) facing +y (up). Its 3 x 3 window: ahead-left obstacle, the rest free,
  // the cell behind-right unknown.
  TernaryGrid p(robot_window(1.0, 1, 1, 1));
  for (int x = 0; x < 3; ++x) {
    for (int y = 0; y < 3; ++y) p.set({x, y}, kTernaryFree);
  }
  p.set({2, 2}, kTernaryOccupied);  // ahead (+x) and left (+y)
  p.set({0, 0}, kTernaryUnknown);   // behind and right
  const MapUpdateStats stats = update_map(map, p, {2.5, 1.5, 0.5 * std::numbers::pi});
  EXPECT_THAT(rows_of(map), ElementsAre("??????",  //
                                        "?#..??",  //
                                        "#.....",  //
                                        "?..???"));
  EXPECT_EQ(stats.written_cells, 8u);
  EXPECT_EQ(stats.newly_known_cells, 5u);
  EXPECT_EQ(stats.flipped_cells, 0u);
  EXPECT_NEAR(*map.probability_at({1, 2}), 0.9, 1e-6);  // the lecture's figure values
  EXPECT_NEAR(*map.probability_at({2, 2}), 0.1, 1e-6);
}

TEST(UpdateMap, OverwriteFollowsThePerceptionLogOddsWeighsItAddUnknownKeepsIt) {
  const OccupancyGrid before = ascii_map({"...", "...", "..."}, 1.0);
  TernaryGrid p(robot_window(1.0, 0, 0, 0));  // one cell: the robot's
  p.set({0, 0}, kTernaryOccupied);
  OccupancyGrid overwrite = before;
  MapUpdateStats s = update_map(overwrite, p, {1.5, 1.5, 0.0});
  EXPECT_EQ(s, (MapUpdateStats{1, 0, 1}));
  EXPECT_EQ(ternary_value(overwrite, {1, 1}), kTernaryOccupied);

  MapUpdateOptions o;
  o.rule = MapUpdateRule::kLogOdds;
  OccupancyGrid log_odds = before;  // p = 0.1: one hit (0.7) is not enough to turn it
  s = update_map(log_odds, p, {1.5, 1.5, 0.0}, o);
  EXPECT_EQ(s, (MapUpdateStats{1, 0, 0}));
  EXPECT_EQ(ternary_value(log_odds, {1, 1}), kTernaryFree);
  EXPECT_GT(*log_odds.probability_at({1, 1}), 0.1);
  for (int k = 0; k < 3; ++k) s = update_map(log_odds, p, {1.5, 1.5, 0.0}, o);
  EXPECT_EQ(ternary_value(log_odds, {1, 1}), kTernaryOccupied);

  o.rule = MapUpdateRule::kAddUnknown;  // keeps what the map knows, adds only new cells
  OccupancyGrid add_unknown = before;
  EXPECT_EQ(update_map(add_unknown, p, {1.5, 1.5, 0.0}, o), (MapUpdateStats{0, 0, 0}));
  EXPECT_EQ(ternary_value(add_unknown, {1, 1}), kTernaryFree);
  add_unknown.set_unknown({1, 1});
  EXPECT_EQ(update_map(add_unknown, p, {1.5, 1.5, 0.0}, o), (MapUpdateStats{1, 1, 0}));
  EXPECT_NEAR(*add_unknown.probability_at({1, 1}), 0.9, 1e-6);
}

TEST(UpdateMap, TurnedWindowLeavesNoHolesAndStopsAtTheMapsEdge) {
  OccupancyGrid map(GridGeometry({0.0, 0.0}, 1.0, 12, 12));
  TernaryGrid p(robot_window(1.0, 5, 5, 5));  // 11 x 11, all free
  for (int x = 0; x < 11; ++x) {
    for (int y = 0; y < 11; ++y) p.set({x, y}, kTernaryFree);
  }
  const Pose2 T_map_robot{3.5, 6.5, 20.0 * kDeg};  // close to the left edge, turned
  const MapUpdateStats s = update_map(map, p, T_map_robot);
  // Every map cell within 5 cells of the robot is written (the turned square holds that disc),
  // none beyond the window's corners (7.8 cells), and none twice.
  for (int y = 0; y < 12; ++y) {
    for (int x = 0; x < 12; ++x) {
      const double d = (map.geometry().center_of({x, y}) - T_map_robot.translation()).norm();
      if (d <= 5.0) {
        EXPECT_TRUE(map.known({x, y})) << x << "," << y;
      }
      if (d > 7.8) {
        EXPECT_FALSE(map.known({x, y})) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(s.written_cells, map.known_count());
  EXPECT_EQ(s.newly_known_cells, map.known_count());
  EXPECT_LT(map.known_count(), 121u);  // part of the window lies beyond the map's left edge
}

TEST(MapUpdateOptions, DefaultsAreValidAndBrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(MapUpdateOptions{}).has_value());
  MapUpdateOptions o;
  o.p_free = 0.0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("p_free"));
  o = {};
  o.p_occupied = 1.0;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("p_occupied"));
  o = {};
  o.p_free = 0.9;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("p_free must be < p_occupied"));
  o = {};
  o.model.p_hit = 0.3;
  EXPECT_THAT(validate(o).value_or(""), HasSubstr("model: "));
}

// ---- Several steps: the loop of the formal algorithm --------------------------------------------

/// The world of the run: a room with furniture, so that every pose sees something to match.
const std::vector<std::string>& run_room() {
  static const std::vector<std::string> rows{
      "####################",  //
      "#..................#",  //
      "#..................#",  //
      "#...##.......#.....#",  //
      "#...##.......#.....#",  //
      "#............###...#",  //
      "#..................#",  //
      "#......#...........#",  //
      "#......#.......##..#",  //
      "#..............##..#",  //
      "#..................#",  //
      "#..................#",  //
      "####################",  //
  };
  return rows;
}

/// Cells of a loop round the room (4-neighbour moves), twice round.
std::vector<Cell> run_path() {
  std::vector<Cell> loop;
  for (int x = 2; x <= 17; ++x) loop.push_back({x, 2});
  for (int y = 3; y <= 10; ++y) loop.push_back({17, y});
  for (int x = 16; x >= 2; --x) loop.push_back({x, 10});
  for (int y = 9; y >= 2; --y) loop.push_back({2, y});
  std::vector<Cell> path = loop;
  path.insert(path.end(), loop.begin() + 1, loop.end());
  return path;
}

struct RunOutcome {
  double worst_position_m = 0.0;
  double worst_heading_rad = 0.0;
  double worst_dead_reckoning_m = 0.0;
  int first_lost_step = -1;  // first step off by a cell or 15 degrees or more; -1 if none
};

/// The formal algorithm's loop over run_path() in run_room(), with a lidar of range_cells cells and
/// odometry that misses a clockwise turn of bias_deg on every move (the low-friction right wheel),
/// plus random slip. The map starts from the first scan at the known start pose.
RunOutcome run_loop(const GridMatchOptions& match_options, double bias_deg, double range_cells,
                    std::uint64_t seed) {
  const World world = ascii_world(run_room(), kCellM);
  RobotSpec spec;
  spec.kind = RobotKind::kLidar;
  spec.lidar.beams = 360;
  spec.lidar.max_range_m = range_cells * kCellM;
  spec.lidar.range_noise_stddev_m = 0.01;
  Simulator sim(world, seed);
  const std::vector<Cell> path = run_path();
  const Result<int> added = sim.add_robot(path.front(), spec);
  TESSERA_ASSERT(added.ok());
  const int robot = *added;
  const GridGeometry window = robot_window(kCellM, spec.lidar.max_range_m);

  Rng rng(seed + 100);
  Pose2 truth = sim.pose(robot);
  Pose2 estimate = truth;  // the lecture's c
  Pose2 dead_reckoning = truth;
  OccupancyGrid map(world.geometry());
  (void)update_map(map, perception_from_scan(sim.scan(robot), window), estimate);
  RunOutcome out;
  for (std::size_t k = 1; k < path.size(); ++k) {
    TESSERA_ASSERT(sim.move_to_adjacent(robot, path[k]).moved);  // 01-02: move a short distance
    const Pose2 truth_now = sim.pose(robot);
    const Pose2 T_prev_now = between(truth, truth_now);
    // What odometry reports: the true motion without the turn the slipping wheel caused.
    const Pose2 odometry_increment{
        T_prev_now.x + rng.gaussian(0.01), T_prev_now.y + rng.gaussian(0.01),
        normalize_angle(T_prev_now.theta + bias_deg * kDeg + rng.gaussian(1.0 * kDeg))};
    truth = truth_now;
    dead_reckoning = dead_reckoning * odometry_increment;
    const Pose2 guess = estimate * odometry_increment;                    // 03: n <- odometry(c)
    const TernaryGrid p = perception_from_scan(sim.scan(robot), window);  // 04
    const GridMatchStep step = match_and_update(map, p, guess, match_options);  // 05-10
    estimate = step.match.T_map_robot();                                        // 11: c <- n
    const double position_m = position_error(estimate, truth);
    const double heading_rad = angle_error(estimate.theta, truth.theta);
    out.worst_position_m = std::max(out.worst_position_m, position_m);
    out.worst_heading_rad = std::max(out.worst_heading_rad, heading_rad);
    out.worst_dead_reckoning_m =
        std::max(out.worst_dead_reckoning_m, position_error(dead_reckoning, truth));
    if (out.first_lost_step < 0 && (position_m >= kCellM || heading_rad >= 15.0 * kDeg)) {
      out.first_lost_step = static_cast<int>(k);
    }
  }
  return out;
}

TEST(GridMatchRun, KeepsThePoseWithinACellWhileDeadReckoningDriftsAway) {
  // Twice round the room (92 moves), odometry missing 3 degrees of clockwise turn per move. The
  // test poses span the lecture's +-15 degrees in 5 degree steps (7 headings) around the lecture's
  // 5 cells; the lidar sees 12 cells. With the lecture's own 15 degree steps the estimate is
  // always a multiple of 15 degrees away from odometry, a turn error below 7.5 degrees is never
  // corrected, the overwritten map turns with it, and the run is lost (for seeds 1 to 10) after 5
  // to 48 moves.
  GridMatchOptions o;
  o.heading_step_rad = 5.0 * kDeg;
  o.heading_radius_steps = 3;
  for (std::uint64_t seed = 1; seed <= 5; ++seed) {
    const RunOutcome r = run_loop(o, 3.0, 12.0, seed);
    EXPECT_EQ(r.first_lost_step, -1) << "seed " << seed;
    EXPECT_LT(r.worst_position_m, kCellM) << "seed " << seed;
    EXPECT_LT(r.worst_heading_rad, 15.0 * kDeg) << "seed " << seed;
    // Dead reckoning alone gets more than ten cells away from the truth.
    EXPECT_GT(r.worst_dead_reckoning_m, 10.0 * kCellM) << "seed " << seed;
  }
}

}  // namespace
}  // namespace tessera::slam
