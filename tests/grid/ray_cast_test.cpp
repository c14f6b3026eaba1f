#include "tessera/grid/ray_cast.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <ostream>
#include <vector>

#include "support/cell_print.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {

namespace {

using ::testing::ElementsAre;

struct Visit {
  Cell cell;
  double t_enter_m;
  double t_exit_m;
};

std::vector<Visit> collect(const GridGeometry& g, Vec2 from, Vec2 to) {
  std::vector<Visit> visits;
  traverse_ray(g, from, to, [&](Cell c, double t0, double t1) { visits.push_back({c, t0, t1}); });
  return visits;
}

std::vector<Cell> cells_of(const std::vector<Visit>& visits) {
  std::vector<Cell> cells;
  for (const Visit& v : visits) cells.push_back(v.cell);
  return cells;
}

const GridGeometry kUnitGrid({0.0, 0.0}, 1.0, 8, 8);

TEST(TraverseRay, HorizontalSegmentVisitsItsRowInOrderWithDistances) {
  const std::vector<Visit> v = collect(kUnitGrid, {0.5, 2.5}, {3.25, 2.5});
  ASSERT_THAT(cells_of(v), ElementsAre(Cell{0, 2}, Cell{1, 2}, Cell{2, 2}, Cell{3, 2}));
  EXPECT_DOUBLE_EQ(v[0].t_enter_m, 0.0);
  EXPECT_DOUBLE_EQ(v[0].t_exit_m, 0.5);
  EXPECT_DOUBLE_EQ(v[1].t_exit_m, 1.5);
  EXPECT_DOUBLE_EQ(v[2].t_exit_m, 2.5);
  EXPECT_DOUBLE_EQ(v[3].t_enter_m, 2.5);
  EXPECT_DOUBLE_EQ(v[3].t_exit_m, 2.75);
}

TEST(TraverseRay, DistancesAreInMetresOnAScaledAndShiftedGrid) {
  const GridGeometry g({-1.0, 2.0}, 0.25, 10, 10);
  // Straight down from the centre of cell (1, 3) to the centre of cell (1, 0).
  const std::vector<Visit> v = collect(g, g.center_of({1, 3}), g.center_of({1, 0}));
  ASSERT_THAT(cells_of(v), ElementsAre(Cell{1, 3}, Cell{1, 2}, Cell{1, 1}, Cell{1, 0}));
  EXPECT_DOUBLE_EQ(v[0].t_exit_m, 0.125);
  EXPECT_DOUBLE_EQ(v[1].t_exit_m, 0.375);
  EXPECT_DOUBLE_EQ(v[3].t_exit_m, 0.75);
}

TEST(TraverseRay, ZeroLengthSegmentVisitsTheCellContainingThePoint) {
  const std::vector<Visit> v = collect(kUnitGrid, {2.0, 3.0}, {2.0, 3.0});
  ASSERT_THAT(cells_of(v), ElementsAre(Cell{2, 3}));  // floor rule: the upper-right cell
  EXPECT_EQ(v[0].t_enter_m, 0.0);
  EXPECT_EQ(v[0].t_exit_m, 0.0);
}

TEST(TraverseRay, ExactCornerCrossingStepsXFirstWithAZeroLengthVisit) {
  // Diagonal through the corners (1,1) and (2,2): 4-connected, the x-neighbour first.
  const std::vector<Visit> up = collect(kUnitGrid, {0.5, 0.5}, {2.5, 2.5});
  EXPECT_THAT(cells_of(up),
              ElementsAre(Cell{0, 0}, Cell{1, 0}, Cell{1, 1}, Cell{2, 1}, Cell{2, 2}));
  EXPECT_EQ(up[1].t_enter_m, up[1].t_exit_m);
  EXPECT_EQ(up[3].t_enter_m, up[3].t_exit_m);
  // The same rule going down-left.
  const std::vector<Visit> down = collect(kUnitGrid, {2.5, 2.5}, {0.5, 0.5});
  EXPECT_THAT(cells_of(down),
              ElementsAre(Cell{2, 2}, Cell{1, 2}, Cell{1, 1}, Cell{0, 1}, Cell{0, 0}));
  // And across the other diagonal.
  const std::vector<Visit> cross = collect(kUnitGrid, {0.5, 2.5}, {2.5, 0.5});
  EXPECT_THAT(cells_of(cross),
              ElementsAre(Cell{0, 2}, Cell{1, 2}, Cell{1, 1}, Cell{2, 1}, Cell{2, 0}));
}

TEST(TraverseRay, SegmentStartingOnABorderGoingDownFirstVisitsTheFloorCell) {
  const std::vector<Visit> v = collect(kUnitGrid, {3.0, 0.5}, {1.5, 0.5});
  ASSERT_THAT(cells_of(v), ElementsAre(Cell{3, 0}, Cell{2, 0}, Cell{1, 0}));
  EXPECT_EQ(v[0].t_exit_m, 0.0);
  EXPECT_DOUBLE_EQ(v[1].t_exit_m, 1.0);
}

TEST(TraverseRay, SegmentEndingOnABorderEndsInTheCellBeyondWithZeroLength) {
  const std::vector<Visit> v = collect(kUnitGrid, {1.5, 0.5}, {3.0, 0.5});
  ASSERT_THAT(cells_of(v), ElementsAre(Cell{1, 0}, Cell{2, 0}, Cell{3, 0}));
  EXPECT_DOUBLE_EQ(v[2].t_enter_m, 1.5);
  EXPECT_DOUBLE_EQ(v[2].t_exit_m, 1.5);
}

TEST(TraverseRay, CellsOutsideTheGridAreVisitedNotClipped) {
  const std::vector<Visit> v = collect(kUnitGrid, {-1.5, 0.5}, {1.5, 0.5});
  EXPECT_THAT(cells_of(v), ElementsAre(Cell{-2, 0}, Cell{-1, 0}, Cell{0, 0}, Cell{1, 0}));
}

TEST(TraverseRay, VisitorReturningFalseStopsTheTraversal) {
  std::vector<Cell> seen;
  traverse_ray(kUnitGrid, {0.5, 0.5}, {7.5, 0.5}, [&](Cell c, double, double) {
    seen.push_back(c);
    return c.x < 2;
  });
  EXPECT_THAT(seen, ElementsAre(Cell{0, 0}, Cell{1, 0}, Cell{2, 0}));
}

// Property: against brute force. Every point of the segment (sampled) lies in a visited cell, at a
// distance inside that cell's [t_enter, t_exit]; the visits are 4-connected, distinct, contiguous
// in t, start in cell_at(from) and end in cell_at(to); a visit of positive length has its midpoint
// in its own cell.
void check_against_sampling(const GridGeometry& g, Vec2 from, Vec2 to, Rng& rng, int trial) {
  const std::vector<Visit> v = collect(g, from, to);
  const double length = (to - from).norm();
  ASSERT_FALSE(v.empty());
  EXPECT_EQ(v.front().cell, g.cell_at_unchecked(from)) << "trial " << trial;
  EXPECT_EQ(v.back().cell, g.cell_at_unchecked(to)) << "trial " << trial;
  EXPECT_EQ(v.front().t_enter_m, 0.0);
  EXPECT_DOUBLE_EQ(v.back().t_exit_m, length);
  const double tol = 1e-9 * std::max(1.0, length);
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_LE(v[i].t_enter_m, v[i].t_exit_m) << "trial " << trial;
    if (i > 0) {
      EXPECT_EQ(manhattan(v[i - 1].cell, v[i].cell), 1) << "trial " << trial << " visit " << i;
      EXPECT_EQ(v[i - 1].t_exit_m, v[i].t_enter_m) << "trial " << trial;
    }
    if (v[i].t_exit_m - v[i].t_enter_m > tol) {
      const double t_mid = 0.5 * (v[i].t_enter_m + v[i].t_exit_m);
      EXPECT_EQ(g.cell_at_unchecked(from + (to - from) * (t_mid / length)), v[i].cell)
          << "trial " << trial << " visit " << i;
    }
  }
  std::vector<Cell> sorted = cells_of(v);
  std::sort(sorted.begin(), sorted.end(),
            [](Cell a, Cell b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  EXPECT_EQ(std::adjacent_find(sorted.begin(), sorted.end()), sorted.end()) << "trial " << trial;
  for (int k = 0; k < 64; ++k) {
    const double s = rng.uniform(0.0, 1.0);
    const Cell c = g.cell_at_unchecked(from + (to - from) * s);
    const auto it = std::find_if(v.begin(), v.end(), [c](const Visit& x) { return x.cell == c; });
    ASSERT_NE(it, v.end()) << "trial " << trial << " missed cell (" << c.x << ", " << c.y << ")";
    EXPECT_GE(s * length, it->t_enter_m - tol) << "trial " << trial;
    EXPECT_LE(s * length, it->t_exit_m + tol) << "trial " << trial;
  }
}

TEST(TraverseRay, AgreesWithBruteForceSamplingOnRandomSegments) {
  Rng rng(20240601);
  for (int trial = 0; trial < 2000; ++trial) {
    const GridGeometry g({rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)}, rng.uniform(0.05, 1.0),
                         20, 20);
    const Vec2 from{rng.uniform(-10.0, 20.0), rng.uniform(-10.0, 20.0)};
    const Vec2 to = trial % 4 == 0 ? from + Vec2{rng.uniform(-0.3, 0.3), rng.uniform(-0.3, 0.3)}
                                   : Vec2{rng.uniform(-10.0, 20.0), rng.uniform(-10.0, 20.0)};
    check_against_sampling(g, from, to, rng, trial);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(TraverseRay, AgreesWithBruteForceSamplingOnSegmentsThroughCornersAndAlongBorders) {
  // Endpoints on the half-cell lattice of a unit grid: exact corners, borders and axis-parallel
  // segments along grid lines, where the tie rules matter.
  Rng rng(77);
  for (int trial = 0; trial < 2000; ++trial) {
    const auto lattice = [&rng] { return 0.5 * rng.uniform_int(-4, 20); };
    const Vec2 from{lattice(), lattice()};
    const Vec2 to{lattice(), lattice()};
    check_against_sampling(kUnitGrid, from, to, rng, trial);
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace tessera
