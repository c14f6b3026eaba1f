#include "tessera/sim/tour.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "sim/world_fixtures.hpp"
#include "tessera/sim/builtin_world.hpp"

namespace tessera {
namespace {

using support::from_ascii;
using ::testing::HasSubstr;

/// A random world: each cell solid with probability p_solid.
World random_world(int w, int h, double resolution_m, double p_solid, Rng& rng) {
  const GridGeometry g({-1.0, 2.0}, resolution_m, w, h);
  std::vector<std::uint8_t> solid(g.size(), 0);
  for (auto& s : solid) s = rng.uniform(0.0, 1.0) < p_solid ? 1 : 0;
  return World(g, std::move(solid));
}

TEST(RoutePiece, PosesAlongALineAnArcAndATurn) {
  RoutePiece line;
  line.kind = RoutePiece::Kind::kLine;
  line.start = {1.0, 2.0, 0.5 * std::numbers::pi};
  line.length_m = 3.0;
  EXPECT_NEAR(line.end().x, 1.0, 1e-12);
  EXPECT_NEAR(line.end().y, 5.0, 1e-12);
  EXPECT_NEAR(line.pose_at(10.0).y, 5.0, 1e-12);  // clamped

  RoutePiece arc;  // a quarter circle of radius 2, clockwise, starting east
  arc.kind = RoutePiece::Kind::kArc;
  arc.start = {0.0, 0.0, 0.0};
  arc.curvature_1_per_m = -0.5;
  arc.length_m = std::numbers::pi;
  EXPECT_NEAR(arc.end().x, 2.0, 1e-12);
  EXPECT_NEAR(arc.end().y, -2.0, 1e-12);
  EXPECT_NEAR(arc.end().theta, -0.5 * std::numbers::pi, 1e-12);
  EXPECT_DOUBLE_EQ(arc.extent(), std::numbers::pi);

  RoutePiece turn;
  turn.kind = RoutePiece::Kind::kTurn;
  turn.start = {1.0, 1.0, 3.0};
  turn.turn_rad = -1.0;
  EXPECT_DOUBLE_EQ(turn.extent(), 1.0);
  EXPECT_DOUBLE_EQ(turn.pose_at(0.5).x, 1.0);
  EXPECT_NEAR(turn.pose_at(0.5).theta, 2.5, 1e-12);
  EXPECT_NEAR(turn.end().theta, 2.0, 1e-12);
}

// room_for_robot's definition, checked by brute force on random worlds: a cell has room when its
// centre is at least clearance / r + sqrt(2) cells from every solid cell centre (the frame around
// the grid included); then every point of it is at least the clearance from every solid cell.
TEST(RoomForRobot, MatchesBruteForceAndKeepsEveryPointOfARoomCellAtTheClearance) {
  Rng rng(3);
  for (int trial = 0; trial < 6; ++trial) {
    const World world = random_world(23, 17, 0.1, 0.02 + 0.01 * trial, rng);
    const double clearance_m = 0.05 * trial;
    const std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
    const GridGeometry& g = world.geometry();
    for (std::size_t i = 0; i < g.size(); ++i) {
      const Cell c = g.cell_of(i);
      double nearest2 = std::numeric_limits<double>::infinity();
      for (int y = -1; y <= g.height(); ++y) {
        for (int x = -1; x <= g.width(); ++x) {
          if (!world.solid({x, y})) continue;
          nearest2 = std::min(nearest2,
                              static_cast<double>((x - c.x) * (x - c.x) + (y - c.y) * (y - c.y)));
        }
      }
      const double need = clearance_m / 0.1 + std::numbers::sqrt2;
      // Cells right at the threshold could go either way by rounding; none lies within 1e-9.
      EXPECT_EQ(room[i] != 0, nearest2 >= need * need - 1e-9)
          << "trial " << trial << " cell " << to_string(c);
      if (room[i] == 0) continue;
      for (const Vec2 corner : {Vec2{0, 0}, Vec2{0.1, 0}, Vec2{0, 0.1}, Vec2{0.1, 0.1}}) {
        const Vec2 p = g.origin() + Vec2{c.x * 0.1, c.y * 0.1} + corner;
        EXPECT_GE(world.distance_to_solid(p, 1.0), clearance_m - 1e-12);
      }
    }
  }
}

TEST(RoomForRobot, TheGridEdgeCountsAsAWall) {
  const World open(GridGeometry({0.0, 0.0}, 0.1, 20, 10), std::vector<std::uint8_t>(200, 0));
  const std::vector<std::uint8_t> room = room_for_robot(open, 0.2);
  // Centre distance to the frame must be >= 2 + sqrt(2) = 3.41 cells: cells 3..16 by 3..6.
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 20; ++x) {
      const bool expected = x >= 3 && x <= 16 && y >= 3 && y <= 6;
      EXPECT_EQ(room[open.geometry().index_of({x, y})] != 0, expected) << x << ", " << y;
    }
  }
}

TEST(RandomStartPose, PicksTheLargestComponentAndReportsNoRoom) {
  // Two rooms without a passage: the right one is larger.
  // clang-format off
  const World world = from_ascii({"#################",
                                  "#.....#.........#",
                                  "#.....#.........#",
                                  "#.....#.........#",
                                  "#.....#.........#",
                                  "#################"}, 0.1);
  // clang-format on
  for (std::uint64_t seed = 0; seed < 10; ++seed) {
    Rng rng(seed);
    const Result<Pose2> start = random_start_pose(world, 0.0, rng);
    ASSERT_TRUE(start.ok()) << start.error().message;
    EXPECT_GT(start->x, 0.7);
    EXPECT_GE(start->theta, -std::numbers::pi);
    EXPECT_LT(start->theta, std::numbers::pi);
  }
  Rng rng(1);
  const Result<Pose2> none = random_start_pose(world, 0.2, rng);
  ASSERT_FALSE(none.ok());
  EXPECT_EQ(none.error().kind, ErrorKind::kInput);
  EXPECT_EQ(none.error().message,
            "no room for the robot: no free cell is at least clearance_m = 0.2 m from every wall");
}

TEST(PlanTour, BadStartsAndOptionsAreInputErrorsThatSayWhy) {
  const World office = builtin_world("office", 0.1);
  const auto message = [&](const Pose2& start, const TourOptions& o) {
    const Result<Tour> r = plan_tour(office, start, o);
    EXPECT_FALSE(r.ok());
    if (r.ok()) return std::string();
    EXPECT_EQ(r.error().kind, ErrorKind::kInput);
    return r.error().message;
  };
  EXPECT_EQ(message({-1.0, 3.0, 0.0}, {}), "start (-1, 3) m is outside the map");
  EXPECT_EQ(message({3.3, 2.8, 0.0}, {}), "start (3.3, 2.8) m is inside an obstacle");  // pillar
  EXPECT_EQ(message({3.3, 3.3, 0.0}, {}),
            "start (3.3, 3.3) m is closer than clearance_m = 0.25 m to a wall");
  TourOptions bad;
  bad.waypoint_spacing_m = 0.0;
  EXPECT_THAT(message({2.0, 4.0, 0.0}, bad), HasSubstr("tour: waypoint_spacing_m must be > 0"));
  bad = {};
  bad.clearance_m = -0.1;
  EXPECT_THAT(message({2.0, 4.0, 0.0}, bad), HasSubstr("tour: clearance_m must be >= 0"));
  bad = {};
  bad.max_turn_radius_m = std::nan("");
  EXPECT_THAT(message({2.0, 4.0, 0.0}, bad), HasSubstr("tour: max_turn_radius_m"));
}

// The route is drivable and safe: pieces join up, every point of it keeps the clearance, it starts
// at the start pose and (by default) ends back at the start position.
TEST(PlanTour, RouteIsContinuousKeepsTheClearanceAndReturnsToTheStart) {
  const World office = builtin_world("office", 0.1);
  TourOptions o;
  o.waypoint_spacing_m = 2.0;
  const Pose2 start{2.0, 4.0, 1.0};
  const Result<Tour> tour = plan_tour(office, start, o);
  ASSERT_TRUE(tour.ok()) << tour.error().message;
  const std::vector<RoutePiece>& pieces = tour->pieces;
  ASSERT_GT(pieces.size(), 10u);
  EXPECT_DOUBLE_EQ(pieces.front().start.x, start.x);
  EXPECT_DOUBLE_EQ(pieces.front().start.y, start.y);
  EXPECT_NEAR(pieces.front().start.theta, start.theta, 1e-12);
  EXPECT_NEAR(pieces.back().end().x, start.x, 1e-9);
  EXPECT_NEAR(pieces.back().end().y, start.y, 1e-9);
  bool has_arc = false, has_turn = false;
  double length_m = 0.0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const RoutePiece& p = pieces[k];
    has_arc = has_arc || p.kind == RoutePiece::Kind::kArc;
    has_turn = has_turn || p.kind == RoutePiece::Kind::kTurn;
    length_m += p.length_m;
    EXPECT_GT(p.extent(), 0.0) << "piece " << k;
    if (k + 1 < pieces.size()) {
      const Pose2 a = p.end(), b = pieces[k + 1].start;
      EXPECT_NEAR(a.x, b.x, 1e-9) << "piece " << k;
      EXPECT_NEAR(a.y, b.y, 1e-9) << "piece " << k;
      EXPECT_NEAR(normalize_angle(a.theta - b.theta), 0.0, 1e-9) << "piece " << k;
    }
    const int samples = std::max(1, static_cast<int>(std::ceil(p.length_m / 0.01)));
    for (int s = 0; s <= samples; ++s) {
      const Vec2 q = p.pose_at(p.extent() * s / samples).translation();
      ASSERT_GE(office.distance_to_solid(q, o.clearance_m), o.clearance_m - 1e-9)
          << "piece " << k << " at " << q.x << ", " << q.y;
    }
  }
  EXPECT_TRUE(has_arc);
  EXPECT_TRUE(has_turn);  // the start heading, and dead ends
  EXPECT_NEAR(tour->length_m, length_m, 1e-9);
  EXPECT_DOUBLE_EQ(tour->polyline_m.front().x, start.x);
  EXPECT_DOUBLE_EQ(tour->polyline_m.back().y, start.y);
}

// Every room cell reachable from the start lies in a lattice block whose waypoint the tour passed
// within half a spacing of, so it is within spacing * (sqrt(2) + 1/2) of the polyline.
TEST(PlanTour, PassesNearEveryReachablePlace) {
  const World world = builtin_world("labyrinth", 0.1);
  TourOptions o;
  o.waypoint_spacing_m = 1.5;
  o.return_to_start = false;
  const Result<Tour> tour = plan_tour(world, {1.0, 1.0, 0.0}, o);
  ASSERT_TRUE(tour.ok()) << tour.error().message;
  EXPECT_GT(tour->waypoints_m.size(), 15u);
  const auto distance_to_polyline = [&](Vec2 p) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k + 1 < tour->polyline_m.size(); ++k) {
      const Vec2 a = tour->polyline_m[k], b = tour->polyline_m[k + 1];
      const Vec2 ab = b - a;
      const double t = std::clamp((p - a).dot(ab) / ab.dot(ab), 0.0, 1.0);
      best = std::min(best, (a + ab * t - p).norm());
    }
    return best;
  };
  const std::vector<std::uint8_t> room = room_for_robot(world, o.clearance_m);
  const GridGeometry& g = world.geometry();
  const double bound_m = o.waypoint_spacing_m * (std::numbers::sqrt2 + 0.5);
  std::size_t room_cells = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (room[i] == 0) continue;
    ++room_cells;
    const Vec2 p = g.center_of(g.cell_of(i));
    EXPECT_LE(distance_to_polyline(p), bound_m) << p.x << ", " << p.y;
  }
  EXPECT_GT(room_cells, 1000u);
}

TEST(PlanTour, IsDeterministic) {
  const World office = builtin_world("office", 0.1);
  const Result<Tour> a = plan_tour(office, {14.0, 7.0, -2.0}, TourOptions{});
  const Result<Tour> b = plan_tour(office, {14.0, 7.0, -2.0}, TourOptions{});
  ASSERT_TRUE(a.ok() && b.ok());
  ASSERT_EQ(a->polyline_m.size(), b->polyline_m.size());
  for (std::size_t k = 0; k < a->polyline_m.size(); ++k) {
    EXPECT_EQ(a->polyline_m[k], b->polyline_m[k]);
  }
  EXPECT_EQ(a->length_m, b->length_m);
}

TEST(PlanTour, TurnsInPlaceOnlyWhenNoArcIsAllowed) {
  const World office = builtin_world("office", 0.1);
  TourOptions o;
  o.max_turn_radius_m = 0.0;
  const Result<Tour> tour = plan_tour(office, {2.0, 4.0, 0.0}, o);
  ASSERT_TRUE(tour.ok());
  for (const RoutePiece& p : tour->pieces) EXPECT_NE(p.kind, RoutePiece::Kind::kArc);
}

TEST(PlanTour, NothingToVisitGivesAnEmptyRoute) {
  // clang-format off
  const World closet = from_ascii({"#####",
                                   "#...#",
                                   "#...#",
                                   "#...#",
                                   "#####"}, 0.1);
  // clang-format on
  const Result<Tour> tour = plan_tour(closet, {0.25, 0.25, 0.0}, TourOptions{0.0});
  ASSERT_TRUE(tour.ok()) << tour.error().message;
  EXPECT_TRUE(tour->pieces.empty());
  EXPECT_EQ(tour->length_m, 0.0);
}

}  // namespace
}  // namespace tessera
