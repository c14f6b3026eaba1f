#include "tessera/eval/bob_table.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <string>
#include <vector>

#include "support/text_world.hpp"

namespace tessera {
namespace {

TruthGrid truth_of(const World& w) { return TruthGrid(w.geometry(), w.solid_cells()); }

/// Rows top first, '#' solid; one cell per character, `cell_m` wide.
// A 4 x 4 grid: a 2 x 2 room inside a wall. The map is the truth except one wall cell read free
// and one free cell read occupied; one corner is not sensed.
TEST(BobTable, CountsErrorsPathAndTheSmartDfsBoundOfAKnownMap) {
  const World truth = support::text_world({"####", "#..#", "#..#", "####"}, 0.22);
  const GridGeometry& g = truth.geometry();
  std::vector<std::uint8_t> sensed(g.size(), 1);
  std::vector<std::uint8_t> occupied(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) occupied[i] = truth.solid(g.cell_of(i)) ? 1 : 0;
  sensed[g.index_of({3, 3})] = 0;    // unsensed: not compared
  occupied[g.index_of({0, 1})] = 0;  // a wall read empty
  occupied[g.index_of({2, 2})] = 1;  // a free cell read occupied
  const std::vector<Cell> route{{1, 1}, {1, 2}, {2, 2}, {2, 1}, {1, 1}};
  BobRunCells run{sensed, occupied, route, /*moves=*/4, /*turns=*/3, /*resensed=*/2,
                  /*ignored_readings=*/0};
  // The fine world is the grid itself. The band forgives the free cell read occupied: walls lie
  // within 3 cm of its edges (every cell of a 2 x 2 room touches a wall); the wall read empty is
  // solid right through and counts either way.
  const BobTableRow row = score_bob_table(run, truth_of(truth), truth_of(truth), 0.03);
  EXPECT_EQ(row.cells, 16);
  EXPECT_EQ(row.sensed_cells, 15);
  EXPECT_EQ(row.empty_as_occupied_strict, 1);
  EXPECT_EQ(row.occupied_as_empty_strict, 1);
  EXPECT_EQ(row.empty_as_occupied, 0);
  EXPECT_EQ(row.occupied_as_empty, 1);
  EXPECT_DOUBLE_EQ(row.success_rate_strict, 14.0 / 16.0);
  EXPECT_DOUBLE_EQ(row.success_rate, 15.0 / 16.0);
  EXPECT_EQ(row.path_cells, 4);
  EXPECT_EQ(row.turns, 3);
  EXPECT_EQ(row.resensed, 2);
  EXPECT_EQ(row.visited_cells, 4);
  EXPECT_DOUBLE_EQ(row.path_share, 4.0 / 16.0);
  EXPECT_DOUBLE_EQ(row.visited_share, 4.0 / 16.0);
  EXPECT_EQ(row.free_reachable, 4);  // C
  EXPECT_EQ(row.boundary_edges, 8);  // E
  EXPECT_DOUBLE_EQ(row.path_per_c, 1.0);
  EXPECT_DOUBLE_EQ(row.path_per_smartdfs, 4.0 / (4.0 + 4.0 - 3.0));
}

// A wall 1 cm inside a free cell's edge: strictly the cell is occupied, so reading it empty is an
// error; the 3 cm band forgives it.
TEST(BobTable, TheBandForgivesAnObstacleNearACellEdge) {
  const double cell_m = 0.2;
  // Fine world at 1 cm: free, with one solid column at x in [0.19, 0.20) (inside cell 0).
  const GridGeometry fine({0.0, 0.0}, 0.01, 40, 20);
  std::vector<std::uint8_t> solid(fine.size(), 0);
  for (int y = 0; y < 20; ++y) solid[fine.index_of({19, y})] = 1;
  const World world(fine, std::move(solid), "fine");
  const World truth = world.resampled(cell_m);
  ASSERT_EQ(truth.geometry().size(), 2u);
  ASSERT_TRUE(truth.solid({0, 0}));
  const std::vector<std::uint8_t> sensed{1, 1};
  const std::vector<std::uint8_t> occupied{0, 0};
  const std::vector<Cell> route{{1, 0}};
  const BobTableRow row = score_bob_table({sensed, occupied, route, 0, 0, 0, 0}, truth_of(world),
                                          truth_of(truth), 0.03);
  EXPECT_EQ(row.occupied_as_empty_strict, 1);
  EXPECT_EQ(row.occupied_as_empty, 0);
}

}  // namespace
}  // namespace tessera
