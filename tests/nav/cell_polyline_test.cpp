#include "tessera/nav/cell_polyline.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "taught_corridor.hpp"
#include "tessera/fusion/hex_cell_map.hpp"
#include "tessera/nav/wavefront.hpp"

namespace tessera {
namespace {

TEST(CellPathPolyline, AStraightCorridorOfHexagonsBecomesOneStraightSegment) {
  const fusion::HexCellMap map = nav_test::taught_corridor(nav_test::corridor_length_m());
  const CellGraph g = map.graph();
  const std::size_t goal = *map.find(map.lattice().cell_at({nav_test::corridor_length_m(), 0.0}));
  const std::vector<std::size_t> path = wavefront_path(g, wavefront(g, goal), 0);
  ASSERT_GE(path.size(), 10u);
  const std::vector<Vec2> line = cell_path_polyline(g, path, g.centres_m[0], g.centres_m[goal]);
  ASSERT_EQ(line.size(), 2u);
  EXPECT_EQ(line.front(), g.centres_m[0]);
  EXPECT_EQ(line.back(), g.centres_m[goal]);
  // The zigzag through the cell centres is 1/cos(30 deg) longer than the straight line.
  EXPECT_NEAR(cell_path_length_m(g, path) / polyline_length_m(line), 2.0 / std::sqrt(3.0), 1e-9);
}

TEST(CellPathPolyline, AnLShapedCorridorKeepsItsCornerAndStaysInsideTheCells) {
  // Taught east 2 m, then north 2 m: the shortcut across the corner would leave the corridor.
  fusion::HexCellMap map;
  nav_test::teach_line(map, {0.0, 0.0}, {2.0, 0.0});
  nav_test::teach_line(map, {2.0, 0.0}, {2.0, 2.0});
  const CellGraph g = map.graph();
  const std::size_t goal = map.current_cell();
  const std::vector<std::size_t> path = wavefront_path(g, wavefront(g, goal), 0);
  const std::vector<Vec2> line = cell_path_polyline(g, path, {0.0, 0.0}, g.centres_m[goal]);
  EXPECT_GE(line.size(), 3u);
  EXPECT_LE(line.size(), 6u);
  // Every point of the polyline is in a cell of the path (or on its border).
  for (std::size_t i = 1; i < line.size(); ++i) {
    for (int s = 0; s <= 100; ++s) {
      const Vec2 p = line[i - 1] + (line[i] - line[i - 1]) * (s / 100.0);
      double in_path = 1e9;
      for (const std::size_t c : path) in_path = std::min(in_path, (p - g.centres_m[c]).norm());
      EXPECT_LE(in_path, (p - g.centres_m[g.nearest(p)]).norm() + 1e-6)
          << "segment " << i << " sample " << s;
    }
  }
  EXPECT_LT(polyline_length_m(line), cell_path_length_m(g, path));
}

TEST(CellPathPolyline, OneCellGivesStartToGoal) {
  CellGraph g;
  g.centres_m = {{0, 0}};
  g.adjacent = {{}};
  const std::vector<Vec2> line = cell_path_polyline(g, {0}, {0.05, 0.02}, {0.01, -0.03});
  EXPECT_THAT(line, ::testing::ElementsAre(Vec2{0.05, 0.02}, Vec2{0.01, -0.03}));
}

TEST(NearestOnPolyline, FindsTheNearestPointOfTheNearestSegmentOrItsEnds) {
  // An L: (0, 0) -> (2, 0) -> (2, 2).
  const std::vector<Vec2> l = {{0.0, 0.0}, {2.0, 0.0}, {2.0, 2.0}};
  EXPECT_EQ(nearest_on_polyline({1.0, 0.5}, l), (Vec2{1.0, 0.0}));    // inside the first segment
  EXPECT_EQ(nearest_on_polyline({1.5, 1.2}, l), (Vec2{2.0, 1.2}));    // nearer the second one
  EXPECT_EQ(nearest_on_polyline({-1.0, -1.0}, l), (Vec2{0.0, 0.0}));  // before the start
  EXPECT_EQ(nearest_on_polyline({3.0, 3.0}, l), (Vec2{2.0, 2.0}));    // past the end
  EXPECT_DOUBLE_EQ((nearest_on_polyline({1.5, 1.2}, l) - Vec2{1.5, 1.2}).norm(),
                   distance_to_polyline({1.5, 1.2}, l));
  // One point, or a segment of no length, gives that point.
  EXPECT_EQ(nearest_on_polyline({5.0, 5.0}, {{1.0, 1.0}}), (Vec2{1.0, 1.0}));
  EXPECT_EQ(nearest_on_polyline({5.0, 5.0}, {{1.0, 1.0}, {1.0, 1.0}}), (Vec2{1.0, 1.0}));
}

TEST(CellPolylineOptions, ValidateRejectsANonPositiveSampleStep) {
  CellPolylineOptions o;
  EXPECT_FALSE(validate(o).has_value());
  o.sample_step_m = 0.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("sample_step_m"));
}

}  // namespace
}  // namespace tessera
