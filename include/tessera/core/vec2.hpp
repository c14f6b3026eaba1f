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

/// The point of the segment [a, b] nearest to p (a itself when the segment has no length).
[[nodiscard]] inline Vec2 nearest_on_segment(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 ab = b - a;
  const double len2 = ab.dot(ab);
  const double t = len2 > 0.0 ? (p - a).dot(ab) / len2 : 0.0;
  const double t01 = t < 0.0 ? 0.0 : (t > 1.0 ? 1.0 : t);
  return a + ab * t01;
}

/// Distance from p to the segment [a, b] (to a itself when the segment has no length).
[[nodiscard]] inline double distance_to_segment(Vec2 p, Vec2 a, Vec2 b) {
  return (p - nearest_on_segment(p, a, b)).norm();
}

}  // namespace tessera
