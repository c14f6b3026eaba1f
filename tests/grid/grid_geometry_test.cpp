#include "tessera/grid/grid_geometry.hpp"

#include <gtest/gtest.h>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

TEST(GridGeometry, CellZeroZeroIsTheLowerLeftCellWithItsCornerAtTheOrigin) {
  const GridGeometry g({2.0, -1.0}, 0.5, 4, 3);
  EXPECT_EQ(g.cell_at({2.0, -1.0}), (Cell{0, 0}));
  EXPECT_EQ(g.cell_at({2.49, -0.51}), (Cell{0, 0}));
  EXPECT_EQ(g.cell_at({2.5, -1.0}), (Cell{1, 0}));  // a point on a border belongs to the upper cell
  EXPECT_EQ(g.cell_at({3.99, 0.49}), (Cell{3, 2}));
  EXPECT_EQ(g.size(), 12u);
}

TEST(GridGeometry, CellAtFloorsNegativeCoordinatesInsteadOfTruncatingTowardZero) {
  const GridGeometry g({0.0, 0.0}, 1.0, 4, 4);
  EXPECT_EQ(g.cell_at_unchecked({-0.5, -0.01}), (Cell{-1, -1}));
  EXPECT_EQ(g.cell_at_unchecked({-1.0, -2.5}), (Cell{-1, -3}));
  EXPECT_FALSE(g.cell_at({-0.5, 0.5}).has_value());
  const GridGeometry shifted({-3.0, -3.0}, 0.25, 24, 24);
  EXPECT_EQ(shifted.cell_at({-0.1, -0.1}), (Cell{11, 11}));
  EXPECT_EQ(shifted.cell_at({0.0, 0.0}), (Cell{12, 12}));
}

TEST(GridGeometry, PointsOnTheUpperAndRightEdgeAreOutside) {
  const GridGeometry g({0.0, 0.0}, 1.0, 4, 3);
  EXPECT_FALSE(g.cell_at({4.0, 1.0}).has_value());
  EXPECT_FALSE(g.cell_at({1.0, 3.0}).has_value());
  EXPECT_TRUE(g.cell_at({3.999, 2.999}).has_value());
  EXPECT_FALSE(g.contains({4, 0}));
  EXPECT_FALSE(g.contains({0, -1}));
}

TEST(GridGeometry, CenterOfIsHalfACellFromTheLowerLeftCorner) {
  const GridGeometry g({1.0, 2.0}, 0.2, 5, 5);
  const Vec2 c = g.center_of({3, 1});
  EXPECT_DOUBLE_EQ(c.x, 1.7);
  EXPECT_DOUBLE_EQ(c.y, 2.3);
  EXPECT_EQ(g.cell_at(c), (Cell{3, 1}));
  // Also defined for cells outside the grid.
  const Vec2 o = g.center_of({-1, -1});
  EXPECT_DOUBLE_EQ(o.x, 0.9);
  EXPECT_DOUBLE_EQ(o.y, 1.9);
}

TEST(GridGeometry, IndexIsRowMajorFromTheBottomRow) {
  const GridGeometry g({0.0, 0.0}, 1.0, 5, 3);
  EXPECT_EQ(g.index_of({0, 0}), 0u);
  EXPECT_EQ(g.index_of({4, 0}), 4u);
  EXPECT_EQ(g.index_of({0, 1}), 5u);
  EXPECT_EQ(g.index_of({4, 2}), 14u);
}

TEST(GridGeometry, IndexOfAndCellOfAreInverses) {
  const GridGeometry g({0.0, 0.0}, 0.1, 7, 11);
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    EXPECT_TRUE(g.contains(c));
    EXPECT_EQ(g.index_of(c), i);
  }
}

TEST(GridGeometry, CellAtOfCenterOfRoundTripsOnRandomGrids) {
  Rng rng(11);
  for (int trial = 0; trial < 1000; ++trial) {
    const GridGeometry g({rng.uniform(-100.0, 100.0), rng.uniform(-100.0, 100.0)},
                         rng.uniform(0.01, 2.0), 50, 50);
    const Cell c{rng.uniform_int(-60, 110), rng.uniform_int(-60, 110)};
    EXPECT_EQ(g.cell_at_unchecked(g.center_of(c)), c) << "trial " << trial;
  }
}

TEST(GridGeometry, EmptyGridContainsNothing) {
  const GridGeometry g({0.0, 0.0}, 1.0, 0, 0);
  EXPECT_EQ(g.size(), 0u);
  EXPECT_FALSE(g.contains({0, 0}));
  EXPECT_FALSE(g.cell_at({0.0, 0.0}).has_value());
}

}  // namespace
}  // namespace tessera
