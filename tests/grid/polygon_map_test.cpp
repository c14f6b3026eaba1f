#include "tessera/grid/polygon_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <ostream>
#include <vector>

#include "support/cell_print.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/grid/bit_grid.hpp"

namespace tessera {

namespace {

using ::testing::UnorderedElementsAreArray;

// The lecture's continuous map: the triangle A = (6,3), B = (3,7), C = (6,7) on its 8 x 8 grid.
PolygonMap lecture_triangle() {
  PolygonMap map;
  map.add(Polygon{{{6.0, 3.0}, {3.0, 7.0}, {6.0, 7.0}}});
  return map;
}

const GridGeometry kLectureGrid({0.0, 0.0}, 1.0, 8, 8);

std::vector<Cell> occupied_cells(const OccupancyGrid& grid, double threshold = 0.5) {
  std::vector<Cell> cells;
  const GridGeometry& g = grid.geometry();
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (grid.state(g.cell_of(i), threshold) == CellState::kOccupied) cells.push_back(g.cell_of(i));
  }
  return cells;
}

TEST(PolygonMap, PointInTriangleCountsTheBoundaryAsInside) {
  const PolygonMap map = lecture_triangle();
  EXPECT_TRUE(map.inside_any({5.5, 6.0}));
  EXPECT_TRUE(map.inside_any({6.0, 3.0}));  // vertex A
  EXPECT_TRUE(map.inside_any({6.0, 5.0}));  // on edge CA
  EXPECT_TRUE(map.inside_any({4.5, 5.0}));  // on the hypotenuse AB: x = 6 - 3 (y - 3) / 4
  EXPECT_FALSE(map.inside_any({4.4, 5.0}));
  EXPECT_FALSE(map.inside_any({6.01, 5.0}));
  EXPECT_FALSE(map.inside_any({5.0, 7.01}));
  EXPECT_TRUE(map.occupied({5.5, 6.0}));
  EXPECT_FALSE(map.occupied({1.0, 1.0}));
}

TEST(PolygonMap, FreeSpaceMeaningMakesEverythingOutsideThePolygonsOccupied) {
  PolygonMap room(PolygonMap::Meaning::kFreeSpace);
  room.add(Polygon{{{0.0, 0.0}, {4.0, 0.0}, {4.0, 3.0}, {0.0, 3.0}}});
  EXPECT_FALSE(room.occupied({2.0, 1.0}));
  EXPECT_FALSE(room.occupied({4.0, 1.0}));  // the wall's surface is still free space
  EXPECT_TRUE(room.occupied({4.5, 1.0}));
  EXPECT_TRUE(room.occupied({-1.0, -1.0}));
}

TEST(PolygonMap, BoundsSpanAllCornersOfAllPolygons) {
  PolygonMap map = lecture_triangle();
  map.add(Polygon{{{-1.0, 8.0}, {0.0, 8.0}, {0.0, 9.5}}});
  const auto [lo, hi] = map.bounds();
  EXPECT_EQ(lo, (Vec2{-1.0, 3.0}));
  EXPECT_EQ(hi, (Vec2{6.0, 9.5}));
}

// Which cells the triangle occupies. Cell (x, y) is the square [x, x+1] x [y, y+1]. The hypotenuse
// AB runs x = 6 - 3 (y - 3) / 4, the triangle is right of it, left of x = 6 and below y = 7. The
// share of each cell it covers:
//   (5,5) (5,6) (4,6): all;  (5,4): 0.96;  (4,5): 0.83;  (3,6): 0.63;  (5,3): 0.38;
//   (4,4): 0.17 (AB cuts its upper-right corner from (4.5, 5) to (5, 4.33));
//   (3,5): 0.04 (from (3.75, 6) to (4, 5.67)).
// The lecture's discrete map lists the first seven, (5,3),(5,4),(5,5),(4,5),(5,6),(4,6),(3,6): the
// cells the object visibly covers. Our rule is the one the lecture states for the grid map -- a
// cell that any part of the object overlaps is occupied -- so (4,4) and (3,5) are occupied as well:
// the grid errs on the safe side and makes the object bigger. Cells that only touch the triangle
// along x = 6 or y = 7, or at a corner, share no area with it and stay free.
TEST(PolygonMap, RasterizedLectureTriangleOccupiesTheNineCellsItOverlaps) {
  const OccupancyGrid grid = lecture_triangle().rasterize(kLectureGrid);
  EXPECT_EQ(grid.known_count(), 64u);
  const std::vector<Cell> lecture = {{5, 3}, {5, 4}, {5, 5}, {4, 5}, {5, 6}, {4, 6}, {3, 6}};
  std::vector<Cell> expected = lecture;
  expected.push_back({4, 4});
  expected.push_back({3, 5});
  EXPECT_THAT(occupied_cells(grid), UnorderedElementsAreArray(expected));
  EXPECT_NEAR(*grid.probability_at({5, 3}), 1.0 - 1e-4, 1e-7);
  EXPECT_NEAR(*grid.probability_at({6, 3}), 1e-4, 1e-7);
}

TEST(PolygonMap, TriangleOnAFinerGridStillCoversOnlyCellsItOverlaps) {
  // 16 x 16 cells of 0.5 (the lecture's "finer grid"): the same rule, checked cell by cell
  // against the exact area in the property test below; here the count and the corner cells.
  const OccupancyGrid grid = lecture_triangle().rasterize(GridGeometry({0.0, 0.0}, 0.5, 16, 16));
  const std::vector<Cell> cells = occupied_cells(grid);
  EXPECT_EQ(std::count(cells.begin(), cells.end(), Cell{11, 6}), 1);   // just inside A
  EXPECT_EQ(std::count(cells.begin(), cells.end(), Cell{6, 13}), 1);   // just inside B
  EXPECT_EQ(std::count(cells.begin(), cells.end(), Cell{11, 13}), 1);  // just inside C
  EXPECT_EQ(std::count(cells.begin(), cells.end(), Cell{12, 13}), 0);  // right of C, touching
  EXPECT_EQ(std::count(cells.begin(), cells.end(), Cell{11, 14}), 0);  // above C, touching
}

// The lecture's example: 32 objects of size 1, none touching each other. The discrete map lists 32
// cells; the continuous map must store the four corners of each object. Here they sit on every
// other cell of a 16 x 8 grid.
TEST(PolygonMap, ThirtyTwoUnitObjectsNeed128CornersButOnly32GridCells) {
  PolygonMap map;
  std::vector<Cell> expected;
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 8; ++i) {
      const double x = 2.0 * i, y = 2.0 * j;
      map.add(Polygon{{{x, y}, {x + 1, y}, {x + 1, y + 1}, {x, y + 1}}});
      expected.push_back({2 * i, 2 * j});
    }
  }
  EXPECT_EQ(map.corner_count(), 128u);
  EXPECT_EQ(map.memory_bytes(), 128u * 16u);  // two doubles per corner

  const GridGeometry geometry({0.0, 0.0}, 1.0, 16, 8);
  const OccupancyGrid grid = map.rasterize(geometry);
  EXPECT_THAT(occupied_cells(grid), UnorderedElementsAreArray(expected));
  EXPECT_EQ(grid.memory_bytes(), 128u * 5u);  // float log-odds + known byte per cell

  // The same map as the lecture's one bit per cell: 16 cells = 2 bytes per row, 8 rows.
  constexpr std::size_t kBytes = BitGrid::bytes_needed(16, 8, 1);
  static_assert(kBytes == 16);
  std::array<std::uint8_t, kBytes> buffer{};
  BitGrid bits(buffer, 16, 8, 1);
  for (const Cell c : occupied_cells(grid)) bits.set(c, 1);
  int set = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 16; ++x) set += bits.get({x, y});
  }
  EXPECT_EQ(set, 32);
  EXPECT_EQ(bits.memory_bytes(), 16u);
}

TEST(PolygonMap, FreeSpaceRoomAlignedToCellsFreesExactlyTheCellsInside) {
  PolygonMap room(PolygonMap::Meaning::kFreeSpace);
  room.add(Polygon{{{1.0, 1.0}, {5.0, 1.0}, {5.0, 4.0}, {1.0, 4.0}}});
  const GridGeometry geometry({0.0, 0.0}, 1.0, 7, 6);
  const OccupancyGrid grid = room.rasterize(geometry);
  for (std::size_t i = 0; i < geometry.size(); ++i) {
    const Cell c = geometry.cell_of(i);
    const bool inside = 1 <= c.x && c.x <= 4 && 1 <= c.y && c.y <= 3;
    EXPECT_EQ(grid.state(c), inside ? CellState::kFree : CellState::kOccupied)
        << "(" << c.x << ", " << c.y << ")";
  }
}

TEST(PolygonMap, FreeSpaceCellPartlyOutsideTheFreePolygonIsOccupied) {
  PolygonMap room(PolygonMap::Meaning::kFreeSpace);
  room.add(Polygon{{{0.5, 0.5}, {3.5, 0.5}, {3.5, 2.5}, {0.5, 2.5}}});
  const OccupancyGrid grid = room.rasterize(GridGeometry({0.0, 0.0}, 1.0, 4, 3));
  EXPECT_EQ(grid.state({1, 1}), CellState::kFree);
  EXPECT_EQ(grid.state({2, 1}), CellState::kFree);
  EXPECT_EQ(grid.state({0, 1}), CellState::kOccupied);  // half outside
  EXPECT_EQ(grid.state({1, 0}), CellState::kOccupied);
  EXPECT_EQ(grid.state({3, 2}), CellState::kOccupied);
}

TEST(PolygonMap, ObstacleBeyondTheGridOnlyMarksTheCellsInside) {
  PolygonMap map;
  map.add(Polygon{{{-5.0, -5.0}, {1.5, -5.0}, {1.5, 1.5}, {-5.0, 1.5}}});
  const OccupancyGrid grid = map.rasterize(GridGeometry({0.0, 0.0}, 1.0, 3, 3));
  EXPECT_THAT(occupied_cells(grid),
              UnorderedElementsAreArray(std::vector<Cell>{{0, 0}, {1, 0}, {0, 1}, {1, 1}}));
}

// Exact area of a polygon clipped to an axis-aligned box (Sutherland & Hodgman 1974), the
// reference for the property test.
double clipped_area(std::vector<Vec2> poly, Vec2 lo, Vec2 hi) {
  const auto clip = [&poly](auto inside, auto intersect) {
    std::vector<Vec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
      const Vec2 a = poly[i], b = poly[(i + 1) % poly.size()];
      if (inside(b)) {
        if (!inside(a)) out.push_back(intersect(a, b));
        out.push_back(b);
      } else if (inside(a)) {
        out.push_back(intersect(a, b));
      }
    }
    poly = out;
  };
  const auto at_x = [](double x) {
    return [x](Vec2 a, Vec2 b) { return Vec2{x, a.y + (b.y - a.y) * (x - a.x) / (b.x - a.x)}; };
  };
  const auto at_y = [](double y) {
    return [y](Vec2 a, Vec2 b) { return Vec2{a.x + (b.x - a.x) * (y - a.y) / (b.y - a.y), y}; };
  };
  clip([&](Vec2 p) { return p.x >= lo.x; }, at_x(lo.x));
  clip([&](Vec2 p) { return p.x <= hi.x; }, at_x(hi.x));
  clip([&](Vec2 p) { return p.y >= lo.y; }, at_y(lo.y));
  clip([&](Vec2 p) { return p.y <= hi.y; }, at_y(hi.y));
  double twice = 0.0;
  for (std::size_t i = 0; i < poly.size(); ++i) twice += poly[i].cross(poly[(i + 1) % poly.size()]);
  return std::fabs(0.5 * twice);
}

// Every cell of `v` rasterised on `geometry` is occupied when it must be and free when it must be,
// judged by the exact overlap area (cells within rounding of the decision are skipped).
void expect_rasterize_matches_overlap_area(const std::vector<Vec2>& v,
                                           const GridGeometry& geometry, int trial) {
  const double res = geometry.resolution_m();
  const double cell_area = res * res;
  for (const PolygonMap::Meaning meaning :
       {PolygonMap::Meaning::kObstacles, PolygonMap::Meaning::kFreeSpace}) {
    PolygonMap map(meaning);
    map.add(Polygon{v});
    const OccupancyGrid grid = map.rasterize(geometry);
    for (std::size_t i = 0; i < geometry.size(); ++i) {
      const Cell c = geometry.cell_of(i);
      const Vec2 lo{geometry.origin().x + res * c.x, geometry.origin().y + res * c.y};
      const double area = clipped_area(v, lo, lo + Vec2{res, res});
      const bool occupied = grid.state(c) == CellState::kOccupied;
      const bool must_be_occupied =
          meaning == PolygonMap::Meaning::kObstacles ? area > 1e-9 : area < cell_area - 1e-9;
      const bool must_be_free =
          meaning == PolygonMap::Meaning::kObstacles ? area < 1e-12 : area > cell_area - 1e-12;
      if (must_be_occupied) {
        EXPECT_TRUE(occupied) << "trial " << trial << " cell " << c.x << "," << c.y;
      }
      if (must_be_free) {
        EXPECT_FALSE(occupied) << "trial " << trial << " cell " << c.x << "," << c.y;
      }
    }
  }
}

// Many-edged, non-convex plans exercise the scanline's active-edge table: star polygons (random
// radii at sorted angles, so always simple) with up to 40 corners, some rows crossing many edges.
TEST(PolygonMap, RasterizeMatchesExactOverlapAreaOnRandomStarPolygons) {
  Rng rng(7);
  const GridGeometry geometry({-4.0, -4.0}, 0.5, 16, 16);
  for (int trial = 0; trial < 60; ++trial) {
    const int corners = 5 + trial % 36;
    std::vector<double> angles;
    for (int k = 0; k < corners; ++k) angles.push_back(rng.uniform(0.0, 2.0 * M_PI));
    std::sort(angles.begin(), angles.end());
    std::vector<Vec2> v;
    for (const double a : angles) {
      const double r = rng.uniform(0.3, 3.9);
      v.push_back({r * std::cos(a), r * std::sin(a)});
    }
    expect_rasterize_matches_overlap_area(v, geometry, trial);
    if (::testing::Test::HasFailure()) return;
  }
}

TEST(PolygonMap, RasterizeMatchesExactOverlapAreaOnRandomTriangles) {
  Rng rng(31);
  const GridGeometry geometry({-1.0, -1.0}, 0.5, 14, 14);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2> v;
    for (int k = 0; k < 3; ++k) v.push_back({rng.uniform(-2.0, 7.0), rng.uniform(-2.0, 7.0)});
    expect_rasterize_matches_overlap_area(v, geometry, trial);
    if (::testing::Test::HasFailure()) return;
  }
}

}  // namespace
}  // namespace tessera
