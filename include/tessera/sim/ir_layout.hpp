#pragma once
#include <array>
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"

namespace tessera {

/// The five IR sensors of BOBMapping Figure 3, in this order.
enum class IrSensorId { kI, kK, kL, kM, kJ };

/// Where one IR sensor sits on the robot. Robot frame: origin at the body's centre, x forward,
/// y to the left, metres and radians; the beam leaves the sensor along its own +x.
struct IrMount {
  IrSensorId id = IrSensorId::kL;
  Pose2 T_robot_sensor;
  bool front = true;  // front sensors use the 10-80 cm part, lateral ones the 3-35 cm part
  double needed_range_m = 0.0;  // farthest distance this beam must read, robot centred in its cell
};

/// The robot and grid that fix the layout; defaults are BOBMapping 4.1's (16 x 15 cm robot, 22 cm
/// cells).
struct SnowplowLayoutOptions {
  double cell_m = 0.22;
  double robot_length_m = 0.16;  // along x, the direction of travel
  double robot_width_m = 0.15;
};

/// Empty when usable: the robot must fit in a cell (BOBMapping 3.1 sizes the cell to the robot).
[[nodiscard]] std::optional<std::string> validate(const SnowplowLayoutOptions& o);

/// The "snowplow" layout of BOBMapping 3.2 / Figure 3, computed from the geometry (L = robot
/// length, W = width, c = cell side; the robot centred in cell C1, heading +x, so C2 spans
/// x in [c/2, 3c/2] and C3, the second cell ahead, x in [3c/2, 5c/2]):
///  - i and j at the front corners (L/2, +-W/2), facing +-90 deg: moving C1 -> C2 they sweep the
///    lateral cells B2 and D2 like a scanner; needed range 3c/2 - W/2 (0.255 m, the paper's 25 cm).
///  - k and m at the front centre (L/2, 0), each aimed at a far vertex of C3, (5c/2, +-c/2):
///    angle +-atan2(c/2, 5c/2 - L/2) = +-0.2299 rad (13.2 deg); needed range
///    hypot(5c/2 - L/2, c/2) = 0.483 m (the paper's 48 cm).
///  - l at the front centre facing straight ahead: it covers the thin triangle of C3 around the
///    centre line that k and m leave (Figure 3c); needed range 5c/2 - L/2 = 0.47 m.
/// Order: i, k, l, m, j. Precondition: validate(o) is empty.
[[nodiscard]] std::array<IrMount, 5> snowplow_layout(const SnowplowLayoutOptions& o);

}  // namespace tessera
