#include "tessera/grid/cell_region.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tessera {
namespace {

bool same_range(const CellRange& r, int x0, int y0, int x1, int y1) {
  return r.x0 == x0 && r.y0 == y0 && r.x1 == x1 && r.y1 == y1;
}

TEST(CellsOverlapping, BoxOnCellEdgesTakesOnlyTheCellsInside) {
  // Cells of 0.5 m from (1, -2): the box [1.5, 2.5] x [-1.5, -0.5] covers cells 1..2 each way.
  const GridGeometry g({1.0, -2.0}, 0.5, 4, 4);
  const CellRange r = cells_overlapping(g, {1.5, -1.5}, {2.5, -0.5});
  EXPECT_TRUE(same_range(r, 1, 1, 3, 3)) << r.x0 << " " << r.y0 << " " << r.x1 << " " << r.y1;
}

TEST(CellsOverlapping, RoundingOfEdgesDoesNotTakeInTheNeighbour) {
  // 0.1 m cells from the origin. 0.3 / 0.1 = 2.9999999999999996 (a plain floor would start at
  // cell 2) and (3 * 0.1) / 0.1 = 3.0000000000000004 (a plain ceil would end after cell 3).
  const GridGeometry g({0.0, 0.0}, 0.1, 10, 10);
  const CellRange a = cells_overlapping(g, {0.3, 0.1}, {0.7, 3 * 0.1});
  EXPECT_TRUE(same_range(a, 3, 1, 7, 3)) << a.x0 << " " << a.y0 << " " << a.x1 << " " << a.y1;
  // 6 * 0.1 / 0.1 = 6.000000000000001: the box ends at cell 5.
  const CellRange b = cells_overlapping(g, {0.0, 0.0}, {6 * 0.1, 0.05});
  EXPECT_TRUE(same_range(b, 0, 0, 6, 1)) << b.x0 << " " << b.y0 << " " << b.x1 << " " << b.y1;
}

TEST(CellsOverlapping, ABoxInsideOneCellOrPartlyOverAnEdge) {
  const GridGeometry g({0.0, 0.0}, 1.0, 5, 5);
  EXPECT_TRUE(same_range(cells_overlapping(g, {2.2, 3.1}, {2.8, 3.9}), 2, 3, 3, 4));
  // 0.01 m past an edge is more than a touch: the neighbour is in.
  EXPECT_TRUE(same_range(cells_overlapping(g, {0.99, 1.0}, {2.01, 2.0}), 0, 1, 3, 2));
  // A box of zero width on an edge overlaps nothing.
  const CellRange flat = cells_overlapping(g, {2.0, 1.0}, {2.0, 3.0});
  EXPECT_EQ(flat.x0, flat.x1);
}

TEST(CellsOverlapping, MayReachOutsideTheGrid) {
  const GridGeometry g({0.0, 0.0}, 0.5, 2, 2);
  EXPECT_TRUE(same_range(cells_overlapping(g, {-1.25, -0.5}, {1.25, 0.25}), -3, -1, 3, 1));
}

TEST(AnyCellIn, VisitsExactlyTheOverlappedCells) {
  const GridGeometry g({0.0, 0.0}, 1.0, 6, 6);
  std::set<std::pair<int, int>> visited;
  const bool hit = any_cell_in(g, {1.5, 2.0}, {3.5, 4.0}, [&](Cell c) {
    visited.insert({c.x, c.y});
    return false;
  });
  EXPECT_FALSE(hit);
  const std::set<std::pair<int, int>> expected{{1, 2}, {2, 2}, {3, 2}, {1, 3}, {2, 3}, {3, 3}};
  EXPECT_EQ(visited, expected);
}

TEST(AnyCellIn, TrueOnlyWhenTheBoxOverlapsASolidCell) {
  const GridGeometry g({0.0, 0.0}, 1.0, 6, 6);
  const auto solid = [](Cell c) { return c == Cell{3, 3}; };
  // Touching the solid cell's edge (x = 3) is not overlapping it.
  EXPECT_FALSE(any_cell_in(g, {2.0, 3.2}, {3.0, 3.8}, solid));
  EXPECT_TRUE(any_cell_in(g, {2.0, 3.2}, {3.01, 3.8}, solid));
  // Touching its corner.
  EXPECT_FALSE(any_cell_in(g, {4.0, 4.0}, {5.0, 5.0}, solid));
  EXPECT_TRUE(any_cell_in(g, {3.99, 3.99}, {5.0, 5.0}, solid));
}

// A 5 x 4 world, row y = 3 on top; '#' is solid. The left part and the right part meet only
// diagonally, at (2, 0) and (3, 1).
//   y=3  ..#..
//   y=2  ..#..
//   y=1  ..#..
//   y=0  ...#.
const std::vector<std::string> kRows{"...#.", "..#..", "..#..", "..#.."};  // y = 0 first

struct Walls {
  GridGeometry g{{0.0, 0.0}, 1.0, 5, 4};
  bool operator()(Cell c) const {
    return !g.contains(c) || kRows[static_cast<std::size_t>(c.y)][static_cast<std::size_t>(c.x)] == '#';
  }
};

std::vector<std::uint8_t> from_rows(const std::vector<std::string>& rows) {
  std::vector<std::uint8_t> v;
  for (const std::string& row : rows) {
    for (const char ch : row) v.push_back(ch == '1' ? 1 : 0);
  }
  return v;
}

TEST(Reachable4, FloodsAroundWallsAndNotDiagonally) {
  const Walls walls;
  const std::vector<std::uint8_t> reached = reachable_4(walls.g, {0, 0}, walls);
  // y = 0 first: the two left columns and (2, 0); nothing of the right part.
  EXPECT_EQ(reached, from_rows({"11100", "11000", "11000", "11000"}));
}

TEST(Reachable4, FromTheOtherSide) {
  const Walls walls;
  EXPECT_EQ(reachable_4(walls.g, {4, 3}, walls),
            from_rows({"00001", "00011", "00011", "00011"}));
}

TEST(Reachable4, SolidStartReachesNothing) {
  const Walls walls;
  const std::vector<std::uint8_t> reached = reachable_4(walls.g, {2, 2}, walls);
  ASSERT_EQ(reached.size(), walls.g.size());
  EXPECT_EQ(reached, std::vector<std::uint8_t>(20, 0));
}

TEST(Reachable4, OpenGridIsReachedWholeAndStopsAtItsBorder) {
  const GridGeometry g({0.0, 0.0}, 1.0, 3, 2);
  const auto outside = [&](Cell c) { return !g.contains(c); };
  EXPECT_EQ(reachable_4(g, {1, 1}, outside), std::vector<std::uint8_t>(6, 1));
}

}  // namespace
}  // namespace tessera
