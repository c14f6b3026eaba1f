#include "tessera/grid/hex_grid.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "tessera/core/rng.hpp"

namespace tessera {
namespace {

// Thesis Table 4.3, typed in from the table: neighbour k of a cell centred at O, radius d.
Vec2 table_4_3(int k, Vec2 O, double d) {
  const double w = std::sqrt(d * d - (d / 2) * (d / 2));
  switch (k) {
    case 0:
      return {O.x, O.y + d};
    case 1:
      return {O.x - w, O.y + d / 2};
    case 2:
      return {O.x - w, O.y - d / 2};
    case 3:
      return {O.x, O.y - d};
    case 4:
      return {O.x + w, O.y - d / 2};
    default:
      return {O.x + w, O.y + d / 2};
  }
}

TEST(HexGrid, NeighbourCentresAreExactlyThoseOfThesisTable4_3) {
  const HexGrid grid(0.3, {1.0, -2.0});
  for (const HexCoord c : {HexCoord{0, 0}, HexCoord{3, -2}, HexCoord{-5, 7}}) {
    const Vec2 O = grid.center_of(c);
    for (int k = 0; k < 6; ++k) {
      const Vec2 expected = table_4_3(k, O, 0.3);
      const Vec2 got = grid.center_of(HexGrid::neighbor(c, k));
      EXPECT_NEAR(got.x, expected.x, 1e-12) << "cell " << to_string(c) << " neighbour " << k;
      EXPECT_NEAR(got.y, expected.y, 1e-12) << "cell " << to_string(c) << " neighbour " << k;
      const Vec2 offset = hex_neighbor_offset(k, 0.3);
      EXPECT_NEAR(O.x + offset.x, expected.x, 1e-12);
      EXPECT_NEAR(O.y + offset.y, expected.y, 1e-12);
    }
  }
}

TEST(HexGrid, NeighbourZeroIsStraightUpSoTheHexagonsAreFlatTopped) {
  const HexGrid grid(0.3);
  EXPECT_DOUBLE_EQ(grid.apothem_m(), 0.15);
  EXPECT_NEAR(grid.circumradius_m(), 0.3 / std::sqrt(3.0), 1e-15);
  // The top edge is flat: two corners at y = +apothem, none above it.
  const auto corners = HexGrid::corners({0, 0}, 0.3);
  int on_top = 0;
  for (const Vec2& v : corners) {
    EXPECT_LE(v.y, 0.15 + 1e-12);
    if (std::abs(v.y - 0.15) < 1e-12) ++on_top;
  }
  EXPECT_EQ(on_top, 2);
  // Just inside the top edge is still cell (0, 0), just outside is neighbour 0.
  EXPECT_EQ(grid.cell_at({0.0, 0.149}), (HexCoord{0, 0}));
  EXPECT_EQ(grid.cell_at({0.0, 0.151}), kHexNeighbors[0]);
  // A corner at angle 0 is 0.173 m out along x: the cell reaches that far.
  EXPECT_EQ(grid.cell_at({0.17, 0.0}), (HexCoord{0, 0}));
}

TEST(HexGrid, CellAtReturnsTheCellWithTheNearestCentre) {
  const HexGrid grid(0.3, {0.4, 0.7});
  Rng rng(5);
  for (int trial = 0; trial < 2000; ++trial) {
    const Vec2 p{rng.uniform(-5.0, 5.0), rng.uniform(-5.0, 5.0)};
    const HexCoord c = grid.cell_at(p);
    const double d = (p - grid.center_of(c)).norm();
    EXPECT_LE(d, grid.circumradius_m() + 1e-12) << "trial " << trial;
    for (int k = 0; k < 6; ++k) {
      EXPECT_LE(d, (p - grid.center_of(HexGrid::neighbor(c, k))).norm() + 1e-12)
          << "trial " << trial << " neighbour " << k;
    }
  }
}

TEST(HexGrid, CentresRoundTripAndHexDistanceCountsSteps) {
  const HexGrid grid(0.5, {-3.0, 2.0});
  for (int q = -6; q <= 6; ++q) {
    for (int r = -6; r <= 6; ++r) EXPECT_EQ(grid.cell_at(grid.center_of({q, r})), (HexCoord{q, r}));
  }
  EXPECT_EQ(hex_distance({0, 0}, {0, 0}), 0);
  for (int k = 0; k < 6; ++k) EXPECT_EQ(hex_distance({0, 0}, kHexNeighbors[k]), 1);
  EXPECT_EQ(hex_distance({0, 0}, {3, -1}), 3);
  EXPECT_EQ(hex_distance({-2, 2}, {2, -2}), 4);
}

}  // namespace
}  // namespace tessera
