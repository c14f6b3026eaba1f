#pragma once
// The wall faces of a World: maximal straight runs of solid-cell faces that border free space.
// The simulated RGB-D camera (sim/rgbd_camera.hpp) hangs posters on them and tells which face a
// ray hit; a face is a place a poster can go ("this wall face is textured, that one blank").
#include <cstdint>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

/// One wall face, seen from the free side. `start_m` is its LEFT end for a viewer in the room
/// facing the wall, `end_m` its right end; `normal` (unit, axis-aligned) points into the room.
/// A texture's column 0 goes at the left end, as a poster reads for that viewer.
struct WallFace {
  Vec2 start_m;
  Vec2 end_m;
  Vec2 normal;

  [[nodiscard]] double length_m() const { return (end_m - start_m).norm(); }
  /// Unit vector from start_m to end_m (the viewer's right): (-normal.y, normal.x).
  [[nodiscard]] Vec2 along() const { return {-normal.y, normal.x}; }
};

/// Which side of a free cell a solid neighbour lies on; the index of a cell face.
enum class FaceSide : std::uint8_t { kPlusX = 0, kMinusX = 1, kPlusY = 2, kMinusY = 3 };

/// Every wall face of `world` and, for lookups, which face each free cell's four sides belong to.
struct WallFaces {
  std::vector<WallFace> faces;
  /// 4 entries per cell of world.geometry() (index_of(c) * 4 + FaceSide): the face the cell's side
  /// belongs to, -1 when the cell is solid or the neighbour on that side is free.
  std::vector<std::int32_t> face_of_side;
};

/// Finds the faces: a free cell side whose neighbour is solid (cells outside the grid count as
/// solid, World's rule) is one cell face; consecutive cell faces on the same grid line with the
/// same normal join into one WallFace. Deterministic order: faces with normal -x, +x, -y, +y,
/// each by grid line then position. Cost: O(cells).
[[nodiscard]] WallFaces find_wall_faces(const World& world);

/// Index of the face nearest to `p_m` (distance to the segment), -1 when there are no faces.
/// For tests and experiments that name a face by a point on it. Cost: O(faces).
[[nodiscard]] int nearest_wall_face(const std::vector<WallFace>& faces, Vec2 p_m);

}  // namespace tessera
