#include "tessera/sim/world.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "sim/world_fixtures.hpp"
#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

using support::from_ascii;

// A 10 x 8 room of 0.5 m cells with one-cell walls and a 2 x 1 pillar at cells (6..7, 4).
// clang-format off
const World kRoom = from_ascii({"##########",
                                "#........#",
                                "#........#",
                                "#.....##.#",
                                "#........#",
                                "#........#",
                                "#........#",
                                "##########"},
                               0.5);
// clang-format on

TEST(World, CellsOutsideTheGridAreSolid) {
  EXPECT_TRUE(kRoom.solid({-1, 3}));
  EXPECT_TRUE(kRoom.solid({10, 3}));
  EXPECT_TRUE(kRoom.solid({3, 8}));
  EXPECT_TRUE(kRoom.solid({0, 0}));
  EXPECT_TRUE(kRoom.free({1, 1}));
  EXPECT_TRUE(kRoom.solid({6, 4}));
  EXPECT_EQ(kRoom.free_count(), 8u * 6u - 2u);
  EXPECT_EQ(kRoom.name(), "ascii");
}

TEST(World, FromMapTreatsUnknownAndLikelyOccupiedCellsAsSolid) {
  const GridGeometry g({0.0, 0.0}, 1.0, 4, 1);
  OccupancyGrid map(g);
  map.set_probability({0, 0}, 0.2);
  map.set_probability({1, 0}, 0.5);
  map.set_probability({2, 0}, 0.9);
  // (3, 0) stays unknown.
  const World world = World::from_map(map, 0.5, "map");
  EXPECT_TRUE(world.free({0, 0}));
  EXPECT_TRUE(world.solid({1, 0}));
  EXPECT_TRUE(world.solid({2, 0}));
  EXPECT_TRUE(world.solid({3, 0}));
  EXPECT_EQ(World::from_map(map, 0.6).free_count(), 2u);
  EXPECT_EQ(world.name(), "map");
}

TEST(World, CastRayIsExactInAHandMadeRoom) {
  // From the centre of cell (2, 3) = (1.25, 1.75).
  const Vec2 from{1.25, 1.75};
  EXPECT_DOUBLE_EQ(kRoom.cast_ray(from, 0.0, 10.0), 3.25);           // east wall face at x = 4.5
  EXPECT_DOUBLE_EQ(kRoom.cast_ray(from, 0.5 * std::numbers::pi, 10.0),
                   1.75);  // north wall face at y = 3.5
  EXPECT_NEAR(kRoom.cast_ray(from, std::numbers::pi, 10.0), 0.75,
              1e-12);  // west wall face at x = 0.5
  EXPECT_NEAR(kRoom.cast_ray(from, -0.5 * std::numbers::pi, 10.0), 1.25,
              1e-12);  // south face at y = 0.5
  // 45 degrees: reaches y = 3.5 at x = 3.0 (cell (6, 7) of the north wall) after 1.75 * sqrt(2).
  EXPECT_NEAR(kRoom.cast_ray(from, 0.25 * std::numbers::pi, 10.0), 1.75 * std::sqrt(2.0), 1e-12);
  // The pillar (6..7, 4) = [3.0, 4.0] x [2.0, 2.5]: from (2.0, 2.25) east it is 1.0 away.
  EXPECT_DOUBLE_EQ(kRoom.cast_ray({2.0, 2.25}, 0.0, 10.0), 1.0);
  // From (3.5, 0.75) north to the pillar's underside at y = 2.0.
  EXPECT_NEAR(kRoom.cast_ray({3.5, 0.75}, 0.5 * std::numbers::pi, 10.0), 1.25, 1e-12);
}

TEST(World, CastRayReturnsMaxRangeWhenNothingIsHitAndZeroInsideASolidCell) {
  EXPECT_EQ(kRoom.cast_ray({1.25, 1.75}, 0.0, 2.0), 2.0);
  EXPECT_EQ(kRoom.cast_ray({1.25, 1.75}, 0.0, 3.25), 3.25);
  EXPECT_EQ(kRoom.cast_ray({0.25, 0.25}, 0.7, 5.0), 0.0);
  EXPECT_EQ(kRoom.cast_ray({-3.0, 1.0}, 0.0, 5.0), 0.0);  // outside the grid is solid
}

TEST(World, CastRayStopsAtTheGridEdgeOfAnOpenWorld) {
  // clang-format off
  const World open = from_ascii({"....",
                                 "....",
                                 "...."},
                                1.0, {-2.0, 1.0});
  // clang-format on
  EXPECT_DOUBLE_EQ(open.cast_ray({-1.5, 1.5}, 0.0, 100.0), 3.5);
  EXPECT_DOUBLE_EQ(open.cast_ray({-1.5, 1.5}, 0.5 * std::numbers::pi, 100.0), 2.5);
}

TEST(World, CastRayAgreesWithSamplingAlongTheRayInRandomWorlds) {
  // Property: every point before the returned distance is in a free cell, the point just beyond
  // it is in a solid one (or the distance is max range).
  Rng rng(99);
  const GridGeometry g({-1.0, 0.5}, 0.25, 30, 20);
  for (int trial = 0; trial < 300; ++trial) {
    std::vector<std::uint8_t> solid(g.size(), 0);
    for (auto& s : solid) s = rng.uniform(0.0, 1.0) < 0.08 ? 1 : 0;
    const World world(g, solid);
    Vec2 from{};
    do {
      from = {rng.uniform(-1.0, 6.5), rng.uniform(0.5, 5.5)};
    } while (world.solid(g.cell_at_unchecked(from)));
    const double angle = rng.uniform(-std::numbers::pi, std::numbers::pi);
    const double max_range = rng.uniform(0.1, 8.0);
    const double d = world.cast_ray(from, angle, max_range);
    const Vec2 dir{std::cos(angle), std::sin(angle)};
    for (int k = 0; k < 50; ++k) {
      const double t = rng.uniform(0.0, d);
      EXPECT_TRUE(world.free(g.cell_at_unchecked(from + dir * t))) << "trial " << trial;
    }
    if (d < max_range) {
      EXPECT_TRUE(world.solid(g.cell_at_unchecked(from + dir * (d + 1e-9)))) << "trial " << trial;
    }
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(World, DistanceToSolidIsExactToWallsPillarAndGridEdge) {
  // kRoom: walls x < 0.5 and y < 0.5, the pillar covers [3, 4] x [2, 2.5].
  EXPECT_DOUBLE_EQ(kRoom.distance_to_solid({1.0, 1.0}, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(kRoom.distance_to_solid({3.5, 1.75}, 0.3), 0.25);  // below the pillar
  EXPECT_NEAR(kRoom.distance_to_solid({2.6, 2.9}, 1.0), std::hypot(0.4, 0.4), 1e-12);  // corner
  EXPECT_EQ(kRoom.distance_to_solid({0.25, 2.0}, 0.5), 0.0);  // in a wall cell
  EXPECT_EQ(kRoom.distance_to_solid({-1.0, 2.0}, 0.5), 0.0);  // outside the grid
}

TEST(World, DistanceToSolidIsInfiniteWhenNothingSolidIsNearAndSeesTheGridEdgeAsSolid) {
  const World open = from_ascii(std::vector<std::string>(9, "........."), 1.0);
  EXPECT_TRUE(std::isinf(open.distance_to_solid({4.5, 4.5}, 1.0)));
  EXPECT_DOUBLE_EQ(open.distance_to_solid({4.5, 4.5}, 4.5), 4.5);
  EXPECT_DOUBLE_EQ(open.distance_to_solid({1.0, 4.5}, 1.0), 1.0);
}

TEST(World, ReachableFromFloodsThe4ConnectedFreeSpaceOnly) {
  // clang-format off
  const World world = from_ascii({"#######",
                                  "#..#..#",
                                  "#..#..#",
                                  "#...#.#",
                                  "#######"},
                                 1.0);
  // clang-format on
  // The left part touches the right only diagonally at (3, 1)-(4, 2)... which is not 4-connected.
  const std::vector<std::uint8_t> left = world.reachable_from({1, 1});
  const GridGeometry& g = world.geometry();
  EXPECT_EQ(left[g.index_of({3, 1})], 1);
  EXPECT_EQ(left[g.index_of({4, 2})], 0);
  EXPECT_EQ(left[g.index_of({5, 3})], 0);
  int n = 0;
  for (const auto r : left) n += r;
  EXPECT_EQ(n, 7);
  const std::vector<std::uint8_t> right = world.reachable_from({5, 1});
  n = 0;
  for (const auto r : right) n += r;
  EXPECT_EQ(n, 5);
}

TEST(World, ReachableFromASolidOrOutsideStartIsEmpty) {
  for (const Cell start : {Cell{0, 0}, Cell{-1, 2}, Cell{6, 4}}) {
    const std::vector<std::uint8_t> r = kRoom.reachable_from(start);
    EXPECT_EQ(r.size(), kRoom.geometry().size());
    for (const auto v : r) EXPECT_EQ(v, 0);
  }
}

TEST(World, ResampledToTheSameResolutionIsTheSameWorld) {
  const World same = kRoom.resampled(0.5);
  EXPECT_EQ(same.geometry(), kRoom.geometry());
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 10; ++x) EXPECT_EQ(same.solid({x, y}), kRoom.solid({x, y}));
  }
}

TEST(World, ResampledKeepsAThinWallClosed) {
  // One-cell walls in fine columns 3 and 5: column 3 falls inside coarse column 1 and column 5
  // inside coarse column 2 at twice the cell size. Any-solid pooling closes both; only coarse
  // (3, 1), covering fine columns 6..7 and rows 2..3, stays free.
  const World fine = from_ascii(
      {"##########", "#..#.#...#", "#..#.#...#", "#..#.#...#", "#..#.#...#", "##########"}, 0.1);
  const World coarse = fine.resampled(0.2);
  EXPECT_EQ(coarse.geometry().width(), 5);
  EXPECT_EQ(coarse.geometry().height(), 3);
  EXPECT_DOUBLE_EQ(coarse.geometry().resolution_m(), 0.2);
  EXPECT_EQ(coarse.geometry().origin(), fine.geometry().origin());
  EXPECT_TRUE(coarse.solid({1, 1}));
  EXPECT_TRUE(coarse.solid({2, 1}));
  EXPECT_TRUE(coarse.free({3, 1}));
  EXPECT_EQ(coarse.free_count(), 1u);

  // clang-format off
  const World wide =
      from_ascii({"################",
                  "#.......#......#",
                  "#.......#......#",
                  "#.......#......#",
                  "#.......#......#",
                  "#.......#......#",
                  "#.......#......#",
                  "################"},
                 0.1);
  // clang-format on
  const World half = wide.resampled(0.2);
  ASSERT_EQ(half.geometry().width(), 8);
  ASSERT_EQ(half.geometry().height(), 4);
  // Fine column 8 is coarse column 4; left room coarse (1..3, 1..2), right room (5..6, 1..2).
  EXPECT_TRUE(half.solid({4, 1}));
  EXPECT_TRUE(half.solid({4, 2}));
  EXPECT_TRUE(half.free({2, 1}));
  EXPECT_TRUE(half.free({5, 2}));
  const std::vector<std::uint8_t> r = half.reachable_from({2, 1});
  EXPECT_EQ(r[half.geometry().index_of({5, 1})], 0);
}

TEST(World, ResampledCoarseCellOverhangingTheEdgeIsSolid) {
  // 5 fine cells of 0.1 m, all free, resampled to 0.2: the third coarse cell covers fine cell 4
  // and the missing fine cell 5, which counts as solid.
  const World fine = from_ascii({".....", "....."}, 0.1);
  const World coarse = fine.resampled(0.2);
  ASSERT_EQ(coarse.geometry().width(), 3);
  ASSERT_EQ(coarse.geometry().height(), 1);
  EXPECT_TRUE(coarse.free({0, 0}));
  EXPECT_TRUE(coarse.free({1, 0}));
  EXPECT_TRUE(coarse.solid({2, 0}));
}

TEST(World, CroppedKeepsTheCellsOfTheRectangle) {
  // kRoom's pillar (6..7, 4) at 0.5 m: the rectangle x 2.6..4.1, y 1.9..2.5 snaps to cells
  // x 5..8, y 3..4 (origin (2.5, 1.5)), so the pillar is at (1..2, 1) of the crop.
  const World crop = kRoom.cropped({2.6, 1.9}, {4.1, 2.5});
  ASSERT_EQ(crop.geometry().width(), 4);
  ASSERT_EQ(crop.geometry().height(), 2);
  EXPECT_EQ(crop.geometry().origin(), (Vec2{2.5, 1.5}));
  EXPECT_DOUBLE_EQ(crop.geometry().resolution_m(), 0.5);
  for (int y = 0; y < 2; ++y) {
    for (int x = 0; x < 4; ++x) EXPECT_EQ(crop.solid({x, y}), kRoom.solid({x + 5, y + 3}));
  }
  EXPECT_TRUE(crop.solid({1, 1}));
  EXPECT_TRUE(crop.free({0, 0}));
}

TEST(World, CroppedBeyondTheGridIsSolidAndAnEmptyRectangleIsEmpty) {
  const World crop = kRoom.cropped({4.0, 3.0}, {6.0, 5.0});  // cells 8..11 x 6..9
  ASSERT_EQ(crop.geometry().width(), 4);
  ASSERT_EQ(crop.geometry().height(), 4);
  EXPECT_TRUE(crop.free({0, 0}));   // (8, 6) is inside the room
  EXPECT_TRUE(crop.solid({2, 0}));  // (10, 6) is past the grid
  EXPECT_EQ(kRoom.cropped({3.0, 3.0}, {3.0, 4.0}).geometry().size(), 0u);
}

TEST(World, ResampledToAFinerGridCopiesEachCell) {
  const World fine = kRoom.resampled(0.25);
  ASSERT_EQ(fine.geometry().width(), 20);
  ASSERT_EQ(fine.geometry().height(), 16);
  for (int y = 0; y < 16; ++y) {
    for (int x = 0; x < 20; ++x) EXPECT_EQ(fine.solid({x, y}), kRoom.solid({x / 2, y / 2}));
  }
}

TEST(World, FreeComponentsAreNumberedInRowMajorOrderOfTheirFirstCell) {
  // Row 0 is the bottom row: the right pocket's first cell (5, 0) comes before the left room's
  // (1, 1); a diagonal contact does not join components.
  const World w = from_ascii({"#####.", "#..#.#", "#..#.#", "####.."}, 1.0);
  const World::FreeComponents c = w.free_components();
  ASSERT_EQ(c.sizes.size(), 3u);
  EXPECT_EQ(c.label[w.geometry().index_of({4, 0})], 0);
  EXPECT_EQ(c.sizes[0], 4u);  // (4, 0), (5, 0), (4, 1), (4, 2)
  EXPECT_EQ(c.label[w.geometry().index_of({1, 1})], 1);
  EXPECT_EQ(c.sizes[1], 4u);
  EXPECT_EQ(c.label[w.geometry().index_of({5, 3})], 2);
  EXPECT_EQ(c.sizes[2], 1u);
  EXPECT_EQ(c.label[w.geometry().index_of({0, 0})], -1);
}

}  // namespace
}  // namespace tessera
