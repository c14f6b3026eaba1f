#include "tessera/sim/wall_faces.hpp"

#include <array>
#include <limits>

namespace tessera {
namespace {

/// Per side: the neighbour's offset and the normal of the face (pointing back into the free cell).
struct SideInfo {
  int dx, dy;
  Vec2 normal;
};
constexpr std::array<SideInfo, 4> kSides = {{
    {1, 0, {-1.0, 0.0}},   // kPlusX: solid at +x, the face looks towards -x
    {-1, 0, {1.0, 0.0}},   // kMinusX
    {0, 1, {0.0, -1.0}},   // kPlusY
    {0, -1, {0.0, 1.0}},   // kMinusY
}};

}  // namespace

WallFaces find_wall_faces(const World& world) {
  const GridGeometry& g = world.geometry();
  const double r = g.resolution_m();
  const Vec2 o = g.origin();
  WallFaces out;
  out.face_of_side.assign(4 * g.size(), -1);
  const auto is_face = [&](Cell c, int side) {
    const SideInfo& s = kSides[static_cast<std::size_t>(side)];
    return world.free(c) && world.solid(Cell{c.x + s.dx, c.y + s.dy});
  };
  for (int side = 0; side < 4; ++side) {
    const SideInfo& s = kSides[static_cast<std::size_t>(side)];
    const bool vertical = s.dx != 0;  // the face lies on a grid line x = const, runs along y
    const int lines = vertical ? g.width() : g.height();
    const int positions = vertical ? g.height() : g.width();
    for (int line = 0; line < lines; ++line) {
      int k = 0;
      while (k < positions) {
        const auto cell_at = [&](int pos) { return vertical ? Cell{line, pos} : Cell{pos, line}; };
        if (!is_face(cell_at(k), side)) {
          ++k;
          continue;
        }
        int end = k;
        while (end < positions && is_face(cell_at(end), side)) ++end;
        const int id = static_cast<int>(out.faces.size());
        for (int pos = k; pos < end; ++pos) {
          out.face_of_side[4 * g.index_of(cell_at(pos)) + static_cast<std::size_t>(side)] = id;
        }
        // The face's grid line: the side of the free cell towards the solid neighbour.
        const double line_m = vertical ? o.x + (line + (s.dx > 0 ? 1 : 0)) * r
                                       : o.y + (line + (s.dy > 0 ? 1 : 0)) * r;
        const double lo_m = (vertical ? o.y : o.x) + k * r;
        const double hi_m = (vertical ? o.y : o.x) + end * r;
        const Vec2 a = vertical ? Vec2{line_m, lo_m} : Vec2{lo_m, line_m};
        const Vec2 b = vertical ? Vec2{line_m, hi_m} : Vec2{hi_m, line_m};
        WallFace f;
        f.normal = s.normal;
        // start is the left end for a viewer facing the wall: along() points from start to end.
        const bool a_first = (b - a).dot(f.along()) > 0.0;
        f.start_m = a_first ? a : b;
        f.end_m = a_first ? b : a;
        out.faces.push_back(f);
        k = end;
      }
    }
  }
  return out;
}

int nearest_wall_face(const std::vector<WallFace>& faces, Vec2 p_m) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < faces.size(); ++i) {
    const double d = distance_to_segment(p_m, faces[i].start_m, faces[i].end_m);
    if (d < best_d) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

}  // namespace tessera
