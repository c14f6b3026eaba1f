#include "tessera/sim/ir_layout.hpp"

#include <cmath>
#include <numbers>

#include "tessera/core/assert.hpp"

namespace tessera {

std::optional<std::string> validate(const SnowplowLayoutOptions& o) {
  if (!(o.robot_length_m > 0.0) || !(o.robot_width_m > 0.0)) {
    return "robot_length_m, robot_width_m: must be > 0";
  }
  if (!(o.cell_m >= o.robot_length_m && o.cell_m >= o.robot_width_m)) {
    return "cell_m: the robot must fit in one cell";
  }
  return std::nullopt;
}

std::array<IrMount, 5> snowplow_layout(const SnowplowLayoutOptions& o) {
  TESSERA_ASSERT(!validate(o).has_value());
  constexpr double kHalfPi = 0.5 * std::numbers::pi;
  const double front_x = 0.5 * o.robot_length_m;
  const double half_w = 0.5 * o.robot_width_m;
  const double c = o.cell_m;
  const double to_far_edge = 2.5 * c - front_x;  // sensor to C3's far edge, along x
  const double km_angle = std::atan2(0.5 * c, to_far_edge);
  const double lateral_range = 1.5 * c - half_w;
  const double km_range = std::hypot(to_far_edge, 0.5 * c);
  return {{
      {IrSensorId::kI, {front_x, half_w, kHalfPi}, false, lateral_range},
      {IrSensorId::kK, {front_x, 0.0, km_angle}, true, km_range},
      {IrSensorId::kL, {front_x, 0.0, 0.0}, true, to_far_edge},
      {IrSensorId::kM, {front_x, 0.0, -km_angle}, true, km_range},
      {IrSensorId::kJ, {front_x, -half_w, -kHalfPi}, false, lateral_range},
  }};
}

}  // namespace tessera
