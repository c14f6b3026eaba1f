#include "tessera/sim/builtin_world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

namespace tessera {
namespace {

/// An axis-aligned solid box, metres.
struct Box {
  double x0, y0, x1, y1;
};

World rasterize_boxes(const std::vector<Box>& boxes, double width_m, double height_m,
                      double resolution_m, std::string name) {
  const int w = static_cast<int>(std::ceil(width_m / resolution_m - 1e-9));
  const int h = static_cast<int>(std::ceil(height_m / resolution_m - 1e-9));
  const GridGeometry geometry({0.0, 0.0}, resolution_m, w, h);
  std::vector<std::uint8_t> solid(geometry.size(), 0);
  for (const Box& b : boxes) {
    // A cell is solid when the box overlaps its interior, so walls never get thinner than drawn.
    const int cx0 = static_cast<int>(std::floor(b.x0 / resolution_m + 1e-9));
    const int cy0 = static_cast<int>(std::floor(b.y0 / resolution_m + 1e-9));
    const int cx1 = static_cast<int>(std::ceil(b.x1 / resolution_m - 1e-9));
    const int cy1 = static_cast<int>(std::ceil(b.y1 / resolution_m - 1e-9));
    for (int y = std::max(cy0, 0); y < std::min(cy1, h); ++y) {
      for (int x = std::max(cx0, 0); x < std::min(cx1, w); ++x) {
        solid[geometry.index_of({x, y})] = 1;
      }
    }
  }
  return World(geometry, std::move(solid), std::move(name));
}

World office(double resolution_m) {
  constexpr double kW = 16.0, kH = 12.0, kT = 0.2;  // extent and wall thickness
  const std::vector<Box> walls = {
      // Outer walls.
      {0, 0, kW, kT},
      {0, kH - kT, kW, kH},
      {0, 0, kT, kH},
      {kW - kT, 0, kW, kH},
      // Corridor's north wall at y = 8 with a door into each of the three rooms above.
      {0, 8.0, 2.0, 8.0 + kT},
      {3.0, 8.0, 7.0, 8.0 + kT},
      {8.0, 8.0, 12.0, 8.0 + kT},
      {13.0, 8.0, kW, 8.0 + kT},
      // Walls between the rooms above the corridor.
      {5.0, 8.0, 5.0 + kT, kH},
      {10.5, 8.0, 10.5 + kT, kH},
      // Corridor's south wall at y = 6 with two openings into the hall.
      {0, 6.0, 4.0, 6.0 + kT},
      {5.2, 6.0, 11.0, 6.0 + kT},
      {12.2, 6.0, kW, 6.0 + kT},
      // A store room in the hall's south-east corner, door on its west side.
      {11.0, 0, 11.0 + kT, 1.2},
      {11.0, 2.2, 11.0 + kT, 6.0},
      // A pillar and a long table in the hall.
      {3.0, 2.5, 3.6, 3.1},
      {6.0, 1.5, 9.0, 2.3}};
  return rasterize_boxes(walls, kW, kH, resolution_m, "builtin:office");
}

World labyrinth(double resolution_m) {
  constexpr double kT = 0.2;
  const std::vector<Box> walls = {{0, 0, 8, kT},       {0, 8 - kT, 8, 8},  {0, 0, kT, 8},
                                  {8 - kT, 0, 8, 8},   {2, 0, 2 + kT, 6},  {4, 2, 4 + kT, 8},
                                  {6, 0, 6 + kT, 6},   {2, 6, 3, 6 + kT},  {4, 2, 5, 2 + kT},
                                  {6.5, 4, 8, 4 + kT}, {0.2, 3, 1, 3 + kT}};
  return rasterize_boxes(walls, 8.0, 8.0, resolution_m, "builtin:labyrinth");
}

// BOBMapping 4.2: "a laboratory room ... obstacles simulated using expanded polystyrene barriers",
// mapped on an 11 x 14 grid of 22 cm cells (2.42 x 3.08 m). The paper's figures are not in its
// text, so the barriers are drawn here: an L, a box, a T and a board, every face at least 5 cm
// from the cell lines. Drawn at 0.22 / n m with n >= 20 (1.1 cm or finer), so that the grid's
// cells are whole numbers of the world's. Closed: 3 cm boards on the arena's edge. Open: the same
// barriers on an open floor 0.44 m (two cells) wider all round, to be cropped to the arena
// (--crop 0.44,0.44,2.86,3.52) so that the sensors see open floor beyond the grid's edge.
constexpr double kArenaCellM = 0.22, kArenaW = 11 * kArenaCellM, kArenaH = 14 * kArenaCellM;
constexpr double kBoardT = 0.03, kOpenMarginM = 2 * kArenaCellM;

World bob_arena(double asked_resolution_m, bool closed) {
  const double n = std::max(20.0, std::ceil(kArenaCellM / asked_resolution_m - 1e-9));
  const double resolution_m = kArenaCellM / n;
  std::vector<Box> boxes = {{0.50, 1.85, 0.55, 2.50}, {0.50, 2.48, 1.25, 2.53},
                            {1.60, 2.05, 1.92, 2.35}, {1.15, 0.95, 1.70, 1.00},
                            {1.40, 1.00, 1.45, 1.25}, {0.50, 0.50, 0.80, 0.55}};
  if (closed) {
    boxes.push_back({0, 0, kArenaW, kBoardT});
    boxes.push_back({0, kArenaH - kBoardT, kArenaW, kArenaH});
    boxes.push_back({0, 0, kBoardT, kArenaH});
    boxes.push_back({kArenaW - kBoardT, 0, kArenaW, kArenaH});
    return rasterize_boxes(boxes, kArenaW, kArenaH, resolution_m, "builtin:bob-arena");
  }
  for (Box& b : boxes) b = {b.x0 + kOpenMarginM, b.y0 + kOpenMarginM, b.x1 + kOpenMarginM,
                            b.y1 + kOpenMarginM};
  return rasterize_boxes(boxes, kArenaW + 2 * kOpenMarginM, kArenaH + 2 * kOpenMarginM,
                         resolution_m, "builtin:bob-arena-open");
}

// The lecture's numerical SLAM example ("Numerical example for a SLAM algorithm"): a robot near a
// corner of a room, with a projection of the wall to its left (a supporting pillar); cells of
// 0.3 m, "roughly the same size as the robot itself", walls one cell thick. The slides' figures
// are not in the notes, so this is a room consistent with the text: 12 x 9 cells, the wall ahead
// and the left wall make the corner, the pillar is two cells high, the right side stays open.
constexpr double kLectureCellM = 0.3;

World lecture_corner(double resolution_m) {
  constexpr double c = kLectureCellM;
  const std::vector<Box> walls = {{0, 0, 12 * c, c},          // the wall behind
                                  {0, 8 * c, 12 * c, 9 * c},  // the wall ahead
                                  {0, 0, c, 9 * c},           // the left wall
                                  {c, 5 * c, 2 * c, 7 * c}};  // the pillar
  return rasterize_boxes(walls, 12 * c, 9 * c, resolution_m, "builtin:lecture-corner");
}

}  // namespace

std::vector<std::string> builtin_world_names() {
  return {"office", "labyrinth", "bob-arena", "bob-arena-open", "lecture-corner"};
}

World builtin_world(const std::string& name, double resolution_m) {
  if (name == "office") return office(resolution_m);
  if (name == "labyrinth") return labyrinth(resolution_m);
  if (name == "bob-arena") return bob_arena(resolution_m, true);
  if (name == "bob-arena-open") return bob_arena(resolution_m, false);
  if (name == "lecture-corner") return lecture_corner(resolution_m);
  return World();
}

World walled_room(int width_cells, int height_cells, double resolution_m, std::string name) {
  std::vector<std::uint8_t> solid(static_cast<std::size_t>(width_cells) * height_cells, 0);
  for (int y = 0; y < height_cells; ++y) {
    for (int x = 0; x < width_cells; ++x) {
      if (x == 0 || y == 0 || x == width_cells - 1 || y == height_cells - 1) {
        solid[static_cast<std::size_t>(y) * width_cells + x] = 1;
      }
    }
  }
  return World(GridGeometry({0.0, 0.0}, resolution_m, width_cells, height_cells), solid,
               std::move(name));
}

}  // namespace tessera
