#include "tessera/slam/correlative_scan_matcher.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "laser_test_world.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/slam/scan_refiner.hpp"

namespace tessera::slam {
namespace {

using testing::furnished_room;
using testing::grid_from_scans;
using testing::ideal_scan;
using testing::kT_grid_world;

struct Scene {
  World room = furnished_room();
  ProbabilityGrid grid =
      grid_from_scans(room, {{2.0, 3.0, 0.0}, {4.5, 4.0, 1.0}, {8.0, 3.0, -2.0}, {10.5, 6.0, 0.5}});
  Pose2 truth_world{4.0, 3.2, 0.4};
  Pose2 truth = kT_grid_world * truth_world;  // in the grid's frame
  std::vector<Vec2> points =
      scan_to_points(ideal_scan(room, truth_world), {}, ScanPointsOptions{}).returns_m;
};

TEST(AngularSearchStep, MovesTheFarthestPointByAboutOneCell) {
  const double step = angular_search_step_rad(0.05, 10.0);
  EXPECT_NEAR(step * 10.0, 0.05, 1e-4);
  EXPECT_GT(angular_search_step_rad(0.05, 0.01), 0.0);  // no division by zero near the sensor
}

// Olson 2009: the exhaustive search lands within a cell and an angle step of the truth from a
// prior 7 cm and 4.6 degrees off; refinement then reaches sub-cell accuracy.
TEST(MatchRealTime, RecoversAKnownOffset) {
  const Scene s;
  const Pose2 prior{s.truth.x + 0.07, s.truth.y - 0.06, s.truth.theta + 0.08};
  RealTimeMatcherOptions o;
  o.linear_window_m = 0.15;
  o.angular_window_rad = 0.15;
  const ScanMatch m = match_real_time(s.grid, prior, s.points, o);
  EXPECT_NEAR(m.T_grid_robot.x, s.truth.x, 0.05);
  EXPECT_NEAR(m.T_grid_robot.y, s.truth.y, 0.05);
  EXPECT_NEAR(m.T_grid_robot.theta, s.truth.theta, 0.01);
  EXPECT_GT(m.score, 0.4);  // four scans at p_hit 0.55: walls near 0.6
  const RefinedPose r = refine_scan(s.grid, m.T_grid_robot, m.T_grid_robot, s.points,
                                    ScanRefinerOptions{1.0, 0.0, 0.0, 20});
  EXPECT_NEAR(r.T_grid_robot.x, s.truth.x, 0.01);
  EXPECT_NEAR(r.T_grid_robot.y, s.truth.y, 0.01);
  EXPECT_NEAR(r.T_grid_robot.theta, s.truth.theta, 0.003);
}

// Hess et al. 2016 Algorithm 3 is exact: branch and bound returns the score of exhaustive search
// over the same candidates, for random priors and several depths.
TEST(BranchAndBoundMatcher, ReturnsTheSameBestAsExhaustiveSearch) {
  const Scene s;
  Rng rng(11);
  for (const int depth : {1, 3, 5}) {
    const BranchAndBoundMatcher matcher(s.grid, depth);
    ASSERT_EQ(matcher.depth(), depth);
    for (int trial = 0; trial < 4; ++trial) {
      const Pose2 prior{s.truth.x + rng.uniform(-0.3, 0.3), s.truth.y + rng.uniform(-0.3, 0.3),
                        s.truth.theta + rng.uniform(-0.1, 0.1)};
      const SearchWindow window{0.4, 0.12};
      const std::optional<ScanMatch> fast = matcher.match(prior, s.points, window, 0.3);
      const std::optional<ScanMatch> slow = matcher.match_exhaustive(prior, s.points, window, 0.3);
      ASSERT_TRUE(fast && slow) << "depth " << depth << " trial " << trial;
      EXPECT_DOUBLE_EQ(fast->score, slow->score) << "depth " << depth << " trial " << trial;
      EXPECT_NEAR(fast->T_grid_robot.x, slow->T_grid_robot.x, 0.051);
      EXPECT_NEAR(fast->T_grid_robot.y, slow->T_grid_robot.y, 0.051);
    }
  }
}

/// Priors 0.5 m inside each edge of the grid, which put part of the scan off it and part on it.
std::vector<Pose2> priors_over_the_edge(const Scene& s) {
  const GridGeometry& g = s.grid.geometry();
  const Vec2 lo = g.origin() + Vec2{0.5, 0.5};
  const Vec2 hi =
      g.origin() + Vec2{g.width() * g.resolution_m() - 0.5, g.height() * g.resolution_m() - 0.5};
  std::vector<Pose2> out;
  for (const Vec2 at : {Vec2{lo.x, s.truth.y}, Vec2{hi.x, s.truth.y}, Vec2{s.truth.x, lo.y},
                        Vec2{s.truth.x, hi.y}}) {
    const Pose2 prior{at.x, at.y, s.truth.theta};
    int off = 0;
    for (const Vec2& p : s.points) off += g.cell_at(prior * p).has_value() ? 0 : 1;
    EXPECT_GT(off, 0) << "prior " << at.x << ", " << at.y;
    EXPECT_LT(off, static_cast<int>(s.points.size()));
    out.push_back(prior);
  }
  return out;
}

/// The scene's grid grown by 6 m of unknown cells on every side: no prior of
/// priors_over_the_edge puts a point off it.
ProbabilityGrid grown(const Scene& s) {
  ProbabilityGrid out = s.grid;
  const GridGeometry& g = s.grid.geometry();
  out.grow_to_include(g.origin() - Vec2{6.0, 6.0});
  out.grow_to_include(
      g.origin() + Vec2{g.width() * g.resolution_m() + 6.0, g.height() * g.resolution_m() + 6.0});
  return out;
}

// Points off the grid score as free, like unknown cells: the matcher's sums over a scan that
// reaches past the grid's edge (checked point by point) equal its sums on a grid grown to hold
// the whole window (taken without checks).
TEST(MatchRealTime, ScoresPointsOffTheGridAsUnknownCells) {
  const Scene s;
  const ProbabilityGrid big = grown(s);
  for (const Pose2& prior : priors_over_the_edge(s)) {
    const ScanMatch edge = match_real_time(s.grid, prior, s.points, RealTimeMatcherOptions{});
    const ScanMatch inside = match_real_time(big, prior, s.points, RealTimeMatcherOptions{});
    EXPECT_DOUBLE_EQ(edge.score, inside.score);
    EXPECT_DOUBLE_EQ(edge.T_grid_robot.x, inside.T_grid_robot.x);
    EXPECT_DOUBLE_EQ(edge.T_grid_robot.y, inside.T_grid_robot.y);
    EXPECT_DOUBLE_EQ(edge.T_grid_robot.theta, inside.T_grid_robot.theta);
  }
}

// The same for branch and bound, whose coarse levels reach past the grid: over the edge it still
// returns exhaustive search's best, and the same best as on the grown grid.
TEST(BranchAndBoundMatcher, ReturnsTheExhaustiveBestOverTheGridsEdge) {
  const Scene s;
  const ProbabilityGrid big = grown(s);
  const BranchAndBoundMatcher matcher(s.grid, 5);
  const BranchAndBoundMatcher big_matcher(big, 5);
  const SearchWindow window{0.4, 0.12};
  for (const Pose2& prior : priors_over_the_edge(s)) {
    const std::optional<ScanMatch> fast = matcher.match(prior, s.points, window, kMinProbability);
    const std::optional<ScanMatch> slow =
        matcher.match_exhaustive(prior, s.points, window, kMinProbability);
    const std::optional<ScanMatch> on_big =
        big_matcher.match(prior, s.points, window, kMinProbability);
    ASSERT_TRUE(fast && slow && on_big);
    EXPECT_DOUBLE_EQ(fast->score, slow->score);
    EXPECT_DOUBLE_EQ(fast->score, on_big->score);
  }
}

// A wide window and a full turn: found from a prior 0.8 m and 2.5 rad off.
TEST(BranchAndBoundMatcher, FindsThePoseInAFullTurn) {
  const Scene s;
  const BranchAndBoundMatcher matcher(s.grid, 6);
  const Pose2 prior{s.truth.x - 0.8, s.truth.y + 0.5, s.truth.theta + 2.5};
  const std::optional<ScanMatch> m =
      matcher.match(prior, s.points, SearchWindow{1.0, std::numbers::pi}, 0.4);
  ASSERT_TRUE(m.has_value());
  EXPECT_NEAR(m->T_grid_robot.x, s.truth.x, 0.05);
  EXPECT_NEAR(m->T_grid_robot.y, s.truth.y, 0.05);
  EXPECT_NEAR(normalize_angle(m->T_grid_robot.theta - s.truth.theta), 0.0, 0.01);
  EXPECT_GT(m->score, 0.45);
}

// The runner-up of a global relocalization: with the best pose's neighbourhood excluded, the
// search returns the best pose outside it, which scores less; excluding nothing changes nothing.
TEST(BranchAndBoundMatcher, ExcludedPosesAreNeverReturned) {
  const Scene s;
  const BranchAndBoundMatcher matcher(s.grid, 6);
  const SearchWindow window{1.0, std::numbers::pi};
  const std::optional<ScanMatch> best = matcher.match(s.truth, s.points, window, 0.3);
  ASSERT_TRUE(best.has_value());
  const ExcludedPoses around_best{{best->T_grid_robot}, 0.3, 0.2};
  const std::optional<ScanMatch> other = matcher.match(s.truth, s.points, window, 0.2, around_best);
  ASSERT_TRUE(other.has_value());
  const bool outside =
      std::hypot(other->T_grid_robot.x - best->T_grid_robot.x,
                 other->T_grid_robot.y - best->T_grid_robot.y) > 0.3 ||
      std::abs(normalize_angle(other->T_grid_robot.theta - best->T_grid_robot.theta)) > 0.2;
  EXPECT_TRUE(outside);
  EXPECT_LT(other->score, best->score);
  // Excluding the runner-up too finds a third place, no better than the runner-up.
  ExcludedPoses both = around_best;
  both.around.push_back(other->T_grid_robot);
  const std::optional<ScanMatch> third = matcher.match(s.truth, s.points, window, 0.1, both);
  ASSERT_TRUE(third.has_value());
  for (const Pose2& p : both.around) {
    EXPECT_TRUE(std::hypot(third->T_grid_robot.x - p.x, third->T_grid_robot.y - p.y) > 0.3 ||
                std::abs(normalize_angle(third->T_grid_robot.theta - p.theta)) > 0.2);
  }
  EXPECT_LE(third->score, other->score);
  const ExcludedPoses far_away{{{50.0, 50.0, 0.0}}, 0.3, 0.2};
  const std::optional<ScanMatch> same = matcher.match(s.truth, s.points, window, 0.3, far_away);
  ASSERT_TRUE(same.has_value());
  EXPECT_DOUBLE_EQ(same->score, best->score);
}

bool same_pose(const Pose2& a, const Pose2& b) {
  return a.x == b.x && a.y == b.y && a.theta == b.theta;
}

// match_ranked is one search standing in for several: its best is match()'s, and for each of the
// places asked for, the first contender the places before it leave is what match() with them
// excluded and the rival score finds, pose and score (the localizer's runner-ups). The furnished
// room in a full turn has many places that fit the scan partly (14 and 12 above the rival score).
// Depth 7, the localizer's: coarse bounds that send the first descents astray, so with min_score
// at the best's own score the rivals (all below it) lie among the candidates passed over before
// the best was found (without searching those after, this fails).
TEST(BranchAndBoundMatcher, RankedMatchesAreTheSearchesTheyStandFor) {
  const Scene s;
  const BranchAndBoundMatcher matcher(s.grid, 7);
  const SearchWindow window{3.0, std::numbers::pi};
  for (const int places : {2, 6}) {
    const Rivals rivals{kMinProbability, 0.8, {{}, 0.5, 0.3}, places};
    for (const Pose2& prior : {Pose2{6.0, 4.0, 0.0}, Pose2{3.0, 5.0, 1.0}}) {
      const std::optional<ScanMatch> found = matcher.match(prior, s.points, window, 0.4);
      ASSERT_TRUE(found.has_value());
      for (const double min_score : {0.4, found->score}) {
        const std::optional<ScanMatch> best = matcher.match(prior, s.points, window, min_score);
        const std::optional<RankedMatches> ranked =
            matcher.match_ranked(prior, s.points, window, min_score, rivals);
        ASSERT_TRUE(best && ranked);
        EXPECT_TRUE(same_pose(ranked->best.T_grid_robot, best->T_grid_robot));
        EXPECT_EQ(ranked->best.score, best->score);
        ASSERT_FALSE(ranked->contenders.empty());
        EXPECT_EQ(ranked->contenders.front().score, best->score);
        const double rival_score = rivals.score(best->score);
        ExcludedPoses seen = rivals.distinct;
        seen.around = {best->T_grid_robot};
        for (int place = 2; place <= places; ++place) {
          const std::optional<ScanMatch> searched =
              matcher.match(prior, s.points, window, rival_score, seen);
          ASSERT_TRUE(searched.has_value()) << "the scene has rival places; place " << place;
          const auto first =
              std::find_if(ranked->contenders.begin(), ranked->contenders.end(),
                           [&seen](const ScanMatch& m) { return !seen.contains(m.T_grid_robot); });
          ASSERT_NE(first, ranked->contenders.end()) << "place " << place;
          EXPECT_TRUE(same_pose(first->T_grid_robot, searched->T_grid_robot)) << "place " << place;
          EXPECT_EQ(first->score, searched->score) << "place " << place;
          EXPECT_GE(first->score, rival_score);
          seen.around.push_back(searched->T_grid_robot);
        }
        for (std::size_t i = 1; i < ranked->contenders.size(); ++i) {
          EXPECT_LE(ranked->contenders[i].score, ranked->contenders[i - 1].score);
        }
      }
    }
  }
}

TEST(BranchAndBoundMatcher, FindsNothingBelowTheMinimumScore) {
  const Scene s;
  const BranchAndBoundMatcher matcher(s.grid, 4);
  EXPECT_FALSE(matcher.match(s.truth, s.points, SearchWindow{0.2, 0.05}, 0.89).has_value());
  EXPECT_FALSE(matcher.match(s.truth, {}, SearchWindow{0.2, 0.05}, 0.2).has_value());
}

TEST(RealTimeMatcherOptions, BrokenFieldsAreNamed) {
  EXPECT_FALSE(validate(RealTimeMatcherOptions{}).has_value());
  RealTimeMatcherOptions o;
  o.angular_window_rad = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("angular_window_rad"));
}

}  // namespace
}  // namespace tessera::slam
