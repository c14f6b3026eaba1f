#pragma once
#include <cmath>

#include "tessera/core/angle.hpp"
#include "tessera/core/vec2.hpp"

namespace tessera {

/// Rigid motion in the plane, metres and radians. T_a_b maps points in frame b into frame a.
struct Pose2 {
  double x = 0.0;
  double y = 0.0;
  double theta = 0.0;  // invariant: in [-pi, pi)

  [[nodiscard]] Vec2 translation() const { return {x, y}; }
  [[nodiscard]] Vec2 operator*(Vec2 p) const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {x + c * p.x - s * p.y, y + s * p.x + c * p.y};
  }
  [[nodiscard]] Pose2 operator*(const Pose2& b) const {
    const Vec2 t = (*this) * Vec2{b.x, b.y};
    return {t.x, t.y, normalize_angle(theta + b.theta)};
  }
  [[nodiscard]] Pose2 inverse() const {
    const double c = std::cos(theta), s = std::sin(theta);
    return {-c * x - s * y, s * x - c * y, normalize_angle(-theta)};
  }
};

/// Motion from a to b expressed in a: between(T_w_a, T_w_b) == T_a_b.
[[nodiscard]] inline Pose2 between(const Pose2& T_w_a, const Pose2& T_w_b) {
  return T_w_a.inverse() * T_w_b;
}

}  // namespace tessera
