#pragma once
#include <algorithm>
#include <cstddef>
#include <vector>

namespace tessera {

/// One 2D laser scan in the sensor frame: beam i points at angle_min_rad + i * angle_increment_rad
/// (counter-clockwise from the sensor's x axis). A range >= max_range_m means "no return".
struct RangeScan {
  double angle_min_rad = 0.0;
  double angle_increment_rad = 0.0;
  double min_range_m = 0.0;
  double max_range_m = 0.0;
  std::vector<double> ranges_m;
};

/// The angle of the scan's last beam (angle_min_rad when it has none): LaserScan's angle_max.
[[nodiscard]] inline double last_angle_rad(const RangeScan& scan) {
  const std::size_t n = scan.ranges_m.size();
  return scan.angle_min_rad + scan.angle_increment_rad * static_cast<double>(n > 0 ? n - 1 : 0);
}

/// The same scan in the sensor frame mirrored across its x axis (y -> -y), the frame of an
/// upside-down sensor seen from above: beam angles change sign, so the beams come in reverse
/// order from -(last angle). Mirroring twice gives the scan back.
[[nodiscard]] inline RangeScan mirrored(RangeScan scan) {
  scan.angle_min_rad = -last_angle_rad(scan);
  std::reverse(scan.ranges_m.begin(), scan.ranges_m.end());
  return scan;
}

}  // namespace tessera
