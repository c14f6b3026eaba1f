#include "tessera/sim/wall_faces.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace tessera {
namespace {

/// A room of width x height cells with a one-cell wall all round, resolution 0.1 m.
World room(int width, int height) {
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(width * height), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      if (x == 0 || y == 0 || x == width - 1 || y == height - 1) solid[y * width + x] = 1;
    }
  }
  return World(GridGeometry({0.0, 0.0}, 0.1, width, height), solid);
}

TEST(WallFaces, ARectangularRoomHasFourFacesFacingInwards) {
  const World w = room(12, 8);  // free inside: x in [0.1, 1.1], y in [0.1, 0.7]
  const WallFaces f = find_wall_faces(w);
  ASSERT_EQ(f.faces.size(), 4u);
  int found = 0;
  for (const WallFace& face : f.faces) {
    const Vec2 mid = (face.start_m + face.end_m) * 0.5;
    const Vec2 inside = mid + face.normal * 0.05;
    EXPECT_TRUE(w.free(w.geometry().cell_at_unchecked(inside))) << mid.x << " " << mid.y;
    EXPECT_TRUE(w.solid(w.geometry().cell_at_unchecked(mid - face.normal * 0.05)));
    if (face.normal.x == -1.0) {  // the east wall, seen looking east: left is north
      EXPECT_NEAR(face.start_m.x, 1.1, 1e-12);
      EXPECT_NEAR(face.start_m.y, 0.7, 1e-12);
      EXPECT_NEAR(face.end_m.y, 0.1, 1e-12);
      ++found;
    }
    const double expected = face.normal.x != 0.0 ? 0.6 : 1.0;
    EXPECT_NEAR(face.length_m(), expected, 1e-12);
  }
  EXPECT_EQ(found, 1);
}

TEST(WallFaces, EveryFreeCellSideAgainstAWallKnowsItsFace) {
  const World w = room(12, 8);
  const WallFaces f = find_wall_faces(w);
  const GridGeometry& g = w.geometry();
  const int east = nearest_wall_face(f.faces, {1.1, 0.4});
  ASSERT_GE(east, 0);
  for (int y = 1; y < 7; ++y) {
    const std::size_t i = g.index_of({10, y});
    EXPECT_EQ(f.face_of_side[4 * i + static_cast<std::size_t>(FaceSide::kPlusX)], east);
    EXPECT_EQ(f.face_of_side[4 * i + static_cast<std::size_t>(FaceSide::kMinusX)], -1);
  }
  // A solid cell has no faces.
  for (int s = 0; s < 4; ++s) EXPECT_EQ(f.face_of_side[4 * g.index_of({0, 0}) + s], -1);
}

TEST(WallFaces, APillarSplitsNothingButAddsItsOwnFourFaces) {
  std::vector<std::uint8_t> solid(100, 0);
  solid[5 * 10 + 5] = 1;  // one solid cell in an open 10 x 10 grid (the edge is solid beyond it)
  const World w(GridGeometry({0.0, 0.0}, 0.1, 10, 10), solid);
  const WallFaces f = find_wall_faces(w);
  EXPECT_EQ(f.faces.size(), 8u);  // four sides of the grid edge, four of the pillar
  const int pillar_west = nearest_wall_face(f.faces, {0.5, 0.55});
  EXPECT_NEAR(f.faces[pillar_west].length_m(), 0.1, 1e-12);
  EXPECT_EQ(f.faces[pillar_west].normal, (Vec2{-1.0, 0.0}));
}

TEST(WallFaces, NearestFaceOfNoFacesIsMinusOne) {
  EXPECT_EQ(nearest_wall_face({}, {0.0, 0.0}), -1);
}

}  // namespace
}  // namespace tessera
