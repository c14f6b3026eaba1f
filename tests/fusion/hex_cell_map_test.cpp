#include "tessera/fusion/hex_cell_map.hpp"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

namespace tessera::fusion {
namespace {

using ::testing::ElementsAre;

// Drives the robot in a straight line from a to b in steps of step_m (heading along the line),
// feeding every pose to the map.
void drive(HexCellMap& map, Vec2 a, Vec2 b, double step_m = 0.01) {
  const Vec2 d = b - a;
  const double len = d.norm();
  const double theta = std::atan2(d.y, d.x);
  const int n = std::max(1, static_cast<int>(std::ceil(len / step_m)));
  for (int i = 0; i <= n; ++i) {
    const Vec2 p = a + d * (static_cast<double>(i) / n);
    (void)map.update({p.x, p.y, theta});
  }
}

bool traversed_adjacent(const HexCellMap& map, std::size_t a, std::size_t b) {
  const auto& t = map.cell(a).traversed;
  return std::find(t.begin(), t.end(), b) != t.end();
}

TEST(HexCellMap, FirstPoseStartsCellZeroAndPoseNodeZeroCentredOnIt) {
  HexCellMap map;
  EXPECT_TRUE(map.empty());
  EXPECT_FALSE(map.in_firing_field({0, 0}));
  const HexMapUpdate u = map.update({2.0, 1.0, 0.5});
  EXPECT_EQ(map.cell_count(), 1u);
  EXPECT_EQ(u.cell, 0u);
  EXPECT_THAT(u.created_cells, ElementsAre(0u));
  EXPECT_TRUE(u.pose_node_added);
  EXPECT_TRUE(u.in_firing_field);
  EXPECT_EQ(map.cell(0).centre_m, (Vec2{2.0, 1.0}));
  ASSERT_EQ(map.pose_nodes().size(), 1u);
  EXPECT_EQ(map.pose_nodes()[0].cell, 0u);
}

TEST(HexCellMap, LeavingTheCellEntersTheNeighbourOfTable4_3AtTheBorder) {
  HexCellMap map;
  (void)map.update({0.0, 0.0, 1.57});
  // North: the border with neighbour 0 is at y = d/2 = 0.15.
  EXPECT_EQ(map.update({0.0, 0.149, 1.57}).cell, 0u);
  const HexMapUpdate u = map.update({0.0, 0.151, 1.57});
  EXPECT_EQ(u.cell, 1u);
  EXPECT_THAT(u.created_cells, ElementsAre(1u));
  EXPECT_EQ(map.cell(1).coord, kHexNeighbors[0]);
  EXPECT_NEAR(map.cell(1).centre_m.x, 0.0, 1e-12);
  EXPECT_NEAR(map.cell(1).centre_m.y, 0.3, 1e-12);
  EXPECT_TRUE(traversed_adjacent(map, 0, 1));
  EXPECT_TRUE(traversed_adjacent(map, 1, 0));
  // Back into cell 0: no new cell.
  EXPECT_EQ(map.update({0.0, 0.1, -1.57}).cell, 0u);
  EXPECT_EQ(map.cell_count(), 2u);
}

TEST(HexCellMap, FiringFieldIsTheDiscAroundTheCurrentCentre) {
  HexCellMap map;  // firing field 0.1 m
  (void)map.update({0.0, 0.0, 0.0});
  EXPECT_TRUE(map.in_firing_field({0.099, 0.0}));
  EXPECT_FALSE(map.update({0.12, 0.0, 0.0}).in_firing_field);
  // The next cell's field fires only near its centre.
  const Vec2 ne = hex_neighbor_offset(5, 0.3);
  EXPECT_TRUE(map.update({ne.x - 0.05, ne.y, 0.0}).in_firing_field);
  EXPECT_EQ(map.current_cell(), 1u);
}

TEST(HexCellMap, AJumpOfSeveralCellsIsWalkedOneNeighbourAtATime) {
  HexCellMap map;
  (void)map.update({0.0, 0.0, 0.0});
  const HexMapUpdate u = map.update({2.0, 1.3, 0.0});
  ASSERT_GE(u.entered_cells.size(), 7u);
  std::size_t prev = 0;
  for (const std::size_t c : u.entered_cells) {
    EXPECT_EQ(hex_distance(map.cell(prev).coord, map.cell(c).coord), 1);
    EXPECT_TRUE(traversed_adjacent(map, prev, c));
    prev = c;
  }
  EXPECT_EQ(map.cell(u.cell).coord, map.lattice().cell_at({2.0, 1.3}));
}

TEST(HexCellMap, TraversedAdjacencyOnlyLinksCellsTheRobotMovedBetween) {
  // Out along y = 0.05 and back along y = 0.25 (the row above): the two rows are lattice
  // neighbours all along, but the robot only crossed between them at the far end (Figure 4.7).
  HexCellMap map;
  drive(map, {0.0, 0.05}, {2.0, 0.05});
  drive(map, {2.0, 0.05}, {2.0, 0.25});
  drive(map, {2.0, 0.25}, {0.0, 0.25});
  const CellGraph traversed = map.graph(CellAdjacency::kTraversed);
  const CellGraph geometric = map.graph(CellAdjacency::kGeometric);
  ASSERT_EQ(traversed.size(), map.cell_count());
  std::size_t traversed_edges = 0, geometric_edges = 0;
  for (std::size_t i = 0; i < map.cell_count(); ++i) {
    traversed_edges += traversed.adjacent[i].size();
    geometric_edges += geometric.adjacent[i].size();
    for (const std::size_t j : traversed.adjacent[i]) {
      // Every traversed pair is a lattice-neighbour pair.
      EXPECT_EQ(hex_distance(map.cell(i).coord, map.cell(j).coord), 1);
      EXPECT_TRUE(std::is_sorted(traversed.adjacent[i].begin(), traversed.adjacent[i].end()));
    }
  }
  EXPECT_GT(geometric_edges, traversed_edges + 10);
  // The start cell and the first cell of the return row are lattice neighbours, not traversed.
  const std::size_t back = *map.find(map.lattice().cell_at({0.0, 0.25}));
  EXPECT_NE(back, 0u);
  const auto geo0 = map.geometric_neighbors(0);
  EXPECT_NE(std::find(geo0.begin(), geo0.end(), back), geo0.end());
  EXPECT_FALSE(traversed_adjacent(map, 0, back));
}

TEST(HexCellMap, PoseNodesEvery15CentimetresUnlessThePathOverlapsAnExistingNode) {
  HexCellMap map;
  drive(map, {0.0, 0.0}, {3.0, 0.0});
  const std::size_t out = map.pose_nodes().size();
  // 3 m at 1 cm steps: a node at the first step past 0.15 m (0.15 or 0.16 m after rounding).
  EXPECT_GE(out, 1u + 18u);
  EXPECT_LE(out, 1u + 20u);
  for (std::size_t i = 1; i < out; ++i) {
    const double gap = (map.pose_nodes()[i].T_map_robot.translation() -
                        map.pose_nodes()[i - 1].T_map_robot.translation())
                           .norm();
    EXPECT_GT(gap, 0.15);
    EXPECT_LT(gap, 0.17);
  }
  // Driving back over the same path adds nothing.
  drive(map, {3.0, 0.0}, {0.0, 0.05});
  EXPECT_EQ(map.pose_nodes().size(), out);
  // A parallel path 0.5 m away is new path.
  drive(map, {0.0, 0.05}, {0.0, 0.5});
  drive(map, {0.0, 0.5}, {3.0, 0.5});
  EXPECT_GE(map.pose_nodes().size(), out + 18u);
  // Each node remembers the cell it was stored in: the one with the nearest centre (a node on a
  // border may be in either cell).
  for (const PoseNode& n : map.pose_nodes()) {
    const Vec2 p = n.T_map_robot.translation();
    const Vec2 nearest = map.lattice().center_of(map.lattice().cell_at(p));
    EXPECT_NEAR((p - map.cell(n.cell).centre_m).norm(), (p - nearest).norm(), 1e-9);
  }
}

TEST(HexCellMap, ImageNodesAreKeptPerCell) {
  HexCellMap map;
  drive(map, {0.0, 0.0}, {1.0, 0.0});
  map.add_image_node(0, 7);
  map.add_image_node(0, 9);
  map.add_image_node(2, 11);
  EXPECT_THAT(map.cell(0).image_nodes, ElementsAre(7u, 9u));
  EXPECT_THAT(map.cell(2).image_nodes, ElementsAre(11u));
  EXPECT_TRUE(map.cell(1).image_nodes.empty());
}

TEST(HexCellMap, CellsMoveWithTheirAnchorPoseNodesAfterCorrection) {
  HexCellMap map;
  drive(map, {0.0, 0.0}, {2.0, 0.0});
  drive(map, {2.0, 0.0}, {2.0, 1.0});
  const std::size_t cells = map.cell_count();
  std::vector<Vec2> before;
  for (const HexCell& c : map.cells()) before.push_back(c.centre_m);

  // A rigid correction of every node moves every cell rigidly.
  const Pose2 correction{0.3, -0.2, 0.1};
  std::vector<Pose2> corrected;
  for (const PoseNode& n : map.pose_nodes()) corrected.push_back(correction * n.T_map_robot);
  map.move_pose_nodes(corrected);
  for (std::size_t i = 0; i < cells; ++i) {
    const Vec2 expected = correction * before[i];
    EXPECT_NEAR(map.cell(i).centre_m.x, expected.x, 1e-9) << "cell " << i;
    EXPECT_NEAR(map.cell(i).centre_m.y, expected.y, 1e-9) << "cell " << i;
  }
  // The robot, now localised in the corrected frame at the corrected end pose, is still in the
  // same cell and carrying on does not duplicate cells that exist.
  const Vec2 end = correction * Vec2{2.0, 1.0};
  const std::size_t current = map.current_cell();
  EXPECT_EQ(map.update({end.x, end.y, 0.0}).cell, current);
  EXPECT_EQ(map.cell_count(), cells);
  const Vec2 back = correction * Vec2{2.0, 0.0};
  drive(map, end, back);
  EXPECT_EQ(map.cell_count(), cells);

  // Moving one node moves only the cells anchored to it.
  std::vector<Pose2> nudged(map.pose_nodes().size());
  for (std::size_t i = 0; i < nudged.size(); ++i) nudged[i] = map.pose_nodes()[i].T_map_robot;
  const std::size_t last = map.cell(cells - 1).anchor_node;  // anchors at least that cell
  nudged[last].x += 0.05;
  std::vector<Vec2> prior;
  for (const HexCell& c : map.cells()) prior.push_back(c.centre_m);
  map.move_pose_nodes(nudged);
  int moved = 0;
  for (std::size_t i = 0; i < cells; ++i) {
    const double shift = (map.cell(i).centre_m - prior[i]).norm();
    if (map.cell(i).anchor_node == last) {
      EXPECT_NEAR(shift, 0.05, 1e-9);
      ++moved;
    } else {
      EXPECT_NEAR(shift, 0.0, 1e-12);
    }
  }
  EXPECT_GE(moved, 1);
}

TEST(HexCellMapOptions, ValidateNamesTheBadField) {
  EXPECT_FALSE(validate(HexCellMapOptions{}).has_value());
  HexCellMapOptions o;
  o.cell_radius_m = 0.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("cell_radius_m"));
  o = {};
  o.firing_field_radius_m = 0.2;  // beyond the apothem d/2
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("firing_field_radius_m"));
  o = {};
  o.pose_node_spacing_m = -1.0;
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("pose_node_spacing_m"));
  o = {};
  o.pose_node_overlap_m = std::nan("");
  EXPECT_THAT(validate(o).value_or(""), ::testing::HasSubstr("pose_node_overlap_m"));
}

}  // namespace
}  // namespace tessera::fusion
