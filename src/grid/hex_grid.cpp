#include "tessera/grid/hex_grid.hpp"

#include <cmath>
#include <numbers>

namespace tessera {

Vec2 hex_neighbor_offset(int k, double radius_m) {
  TESSERA_ASSERT(0 <= k && k < 6);
  const double d = radius_m;
  const double w = std::sqrt(d * d - (d / 2.0) * (d / 2.0));  // Table 4.3: sqrt(d^2 - (d/2)^2)
  switch (k) {
    case 0:
      return {0.0, d};
    case 1:
      return {-w, d / 2.0};
    case 2:
      return {-w, -d / 2.0};
    case 3:
      return {0.0, -d};
    case 4:
      return {w, -d / 2.0};
    default:
      return {w, d / 2.0};
  }
}

HexCoord HexGrid::cell_at(Vec2 p_m) const {
  // Fractional axial coordinates, then cube rounding (q + r + s = 0): round each and recompute
  // the one with the largest rounding error (Red Blob Games, "Hexagonal Grids", rounding).
  const double fq = (p_m.x - origin_.x) / (kHexColumnStep * d_);
  const double fr = (p_m.y - origin_.y) / d_ - 0.5 * fq;
  const double fs = -fq - fr;
  double q = std::round(fq), r = std::round(fr);
  const double s = std::round(fs);
  const double eq = std::abs(q - fq), er = std::abs(r - fr), es = std::abs(s - fs);
  if (eq > er && eq > es) {
    q = -r - s;
  } else if (er > es) {
    r = -q - s;
  }
  return {static_cast<int>(q), static_cast<int>(r)};
}

std::array<Vec2, 6> HexGrid::corners(Vec2 centre_m, double radius_m) {
  std::array<Vec2, 6> out{};
  const double circumradius = radius_m / std::sqrt(3.0);
  for (std::size_t i = 0; i < 6; ++i) {
    const double a = static_cast<double>(i) * (std::numbers::pi / 3.0);
    out[i] = {centre_m.x + circumradius * std::cos(a), centre_m.y + circumradius * std::sin(a)};
  }
  return out;
}

}  // namespace tessera
