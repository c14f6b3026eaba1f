#pragma once
#include <cmath>

namespace tessera {

/// A point or direction in the plane, metres.
struct Vec2 {
  double x = 0.0;
  double y = 0.0;

  [[nodiscard]] constexpr Vec2 operator+(Vec2 o) const { return {x + o.x, y + o.y}; }
  [[nodiscard]] constexpr Vec2 operator-(Vec2 o) const { return {x - o.x, y - o.y}; }
  [[nodiscard]] constexpr Vec2 operator*(double s) const { return {x * s, y * s}; }
  [[nodiscard]] constexpr bool operator==(const Vec2&) const = default;
  [[nodiscard]] constexpr double dot(Vec2 o) const { return x * o.x + y * o.y; }
  /// z of the 3D cross product: > 0 when o is counter-clockwise of *this.
  [[nodiscard]] constexpr double cross(Vec2 o) const { return x * o.y - y * o.x; }
  [[nodiscard]] double norm() const { return std::hypot(x, y); }
};

}  // namespace tessera
