#pragma once
#include <cmath>
#include <numbers>

namespace tessera {

/// Normalises an angle into [-pi, pi).
[[nodiscard]] inline double normalize_angle(double a_rad) {
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  double r = std::fmod(a_rad + std::numbers::pi, kTwoPi);
  if (r < 0.0) r += kTwoPi;
  if (r >= kTwoPi) r -= kTwoPi;  // -tiny + 2pi can round up to 2pi
  return r - std::numbers::pi;
}

/// Degrees to radians; only for values read from CLI or YAML input.
[[nodiscard]] constexpr double deg_to_rad(double deg) { return deg * std::numbers::pi / 180.0; }
[[nodiscard]] constexpr double rad_to_deg(double rad) { return rad * 180.0 / std::numbers::pi; }

}  // namespace tessera
