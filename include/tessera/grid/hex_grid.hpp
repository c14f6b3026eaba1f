#pragma once
// The hexagonal lattice of the Fusion SLAM thesis (section 4.3.2, Table 4.3, Figure 4.6).
//
// Table 4.3 gives the six neighbours of a cell centred at O for the grid cell "radius" d:
//   0: (O_x,                 O_y + d)      north
//   1: (O_x - sqrt(3)/2 d,   O_y + d/2)    north-west
//   2: (O_x - sqrt(3)/2 d,   O_y - d/2)    south-west
//   3: (O_x,                 O_y - d)      south
//   4: (O_x + sqrt(3)/2 d,   O_y - d/2)    south-east
//   5: (O_x + sqrt(3)/2 d,   O_y + d/2)    north-east
// (sqrt(d^2 - (d/2)^2) = sqrt(3)/2 d.) Every neighbour centre is d from O, so the thesis' d is the
// distance between neighbouring centres. A cell is the region closer to its centre than to any
// other ("the robot enters ... the closest cell", section 4.3.2): a regular hexagon with apothem
// d/2 and circumradius d/sqrt(3). Because a neighbour lies straight above (neighbour 0), the shared
// edge is horizontal: the hexagons are FLAT-TOPPED (vertices at 0, 60, ..., 300 degrees, flat edges
// at the top and bottom). The thesis' d = 0.3 m gives hexagons 0.3 m from flat edge to flat edge.
//
// Axial coordinates (q, r) (Red Blob Games' "flat-top axial"): q counts columns along +x, r counts
// cells along +y within a column, and the centre of (q, r) is
//   origin + (sqrt(3)/2 d * q,  d * (r + q/2)).
// The directions kHexNeighbors[k] are the thesis' neighbour numbers k = 0..5.
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include "tessera/core/assert.hpp"
#include "tessera/core/vec2.hpp"

namespace tessera {

/// sqrt(3)/2: the x distance between neighbouring columns, in units of d.
inline constexpr double kHexColumnStep = 0.86602540378443864676;

/// A cell of the hexagonal lattice in axial coordinates (see the file comment).
struct HexCoord {
  int q = 0;
  int r = 0;

  [[nodiscard]] constexpr HexCoord operator+(HexCoord o) const { return {q + o.q, r + o.r}; }
  [[nodiscard]] constexpr HexCoord operator-(HexCoord o) const { return {q - o.q, r - o.r}; }
  [[nodiscard]] constexpr bool operator==(const HexCoord&) const = default;
};

/// The axial step to the thesis' neighbour number k (Table 4.3): N, NW, SW, S, SE, NE,
/// counter-clockwise from north.
inline constexpr std::array<HexCoord, 6> kHexNeighbors{
    {{0, 1}, {-1, 1}, {-1, 0}, {0, -1}, {1, -1}, {1, 0}}};

/// Steps between two lattice cells (hex distance).
[[nodiscard]] constexpr int hex_distance(HexCoord a, HexCoord b) {
  const int dq = a.q - b.q, dr = a.r - b.r, ds = -dq - dr;
  const int aq = dq < 0 ? -dq : dq, ar = dr < 0 ? -dr : dr, as = ds < 0 ? -ds : ds;
  return (aq + ar + as) / 2;
}

struct HexCoordHash {
  [[nodiscard]] std::size_t operator()(HexCoord c) const noexcept {
    return std::hash<std::uint64_t>{}(
        (static_cast<std::uint64_t>(static_cast<std::uint32_t>(c.q)) << 32) |
        static_cast<std::uint32_t>(c.r));
  }
};

/// "(q, r)", for messages.
[[nodiscard]] inline std::string to_string(HexCoord c) {
  return "(" + std::to_string(c.q) + ", " + std::to_string(c.r) + ")";
}

/// The offset from a cell centre to the centre of its neighbour number k (0..5), exactly the
/// formulas of thesis Table 4.3. Precondition: 0 <= k < 6.
[[nodiscard]] Vec2 hex_neighbor_offset(int k, double radius_m);

/// A flat-topped hexagonal lattice with neighbouring centres radius_m apart (thesis section 4.3.2:
/// d = 0.3 m), cell (0, 0) centred at origin_m. Pure geometry: all queries are O(1).
class HexGrid {
 public:
  /// Precondition: radius_m > 0 and finite.
  explicit HexGrid(double radius_m = 0.3, Vec2 origin_m = {}) : d_(radius_m), origin_(origin_m) {
    TESSERA_ASSERT(radius_m > 0.0 && std::isfinite(radius_m));
  }

  /// The thesis' d: the distance between neighbouring centres, metres.
  [[nodiscard]] double radius_m() const { return d_; }
  [[nodiscard]] Vec2 origin_m() const { return origin_; }
  /// Centre to flat edge: d/2.
  [[nodiscard]] double apothem_m() const { return d_ / 2.0; }
  /// Centre to vertex: d/sqrt(3).
  [[nodiscard]] double circumradius_m() const { return d_ / std::sqrt(3.0); }

  /// Centre of cell c in the map frame.
  [[nodiscard]] Vec2 center_of(HexCoord c) const {
    return {origin_.x + kHexColumnStep * d_ * c.q, origin_.y + d_ * (c.r + 0.5 * c.q)};
  }

  /// The cell whose centre is nearest to p_m (its hexagon contains p_m). A point exactly on a
  /// border goes to one of the two cells, deterministically.
  [[nodiscard]] HexCoord cell_at(Vec2 p_m) const;

  /// The neighbour number k (0..5, Table 4.3) of c. Precondition: 0 <= k < 6.
  [[nodiscard]] static HexCoord neighbor(HexCoord c, int k) {
    TESSERA_ASSERT(0 <= k && k < 6);
    return c + kHexNeighbors[static_cast<std::size_t>(k)];
  }

  /// The six vertices of a flat-topped hexagon with neighbouring centres radius_m apart, centred
  /// at centre_m, counter-clockwise from the one at angle 0 (for drawing).
  [[nodiscard]] static std::array<Vec2, 6> corners(Vec2 centre_m, double radius_m);

 private:
  double d_;
  Vec2 origin_;
};

}  // namespace tessera
