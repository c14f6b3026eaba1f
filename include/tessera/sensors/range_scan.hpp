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
  /// When each beam was taken, in seconds after the scan's stamp: beam i at first_beam_s + i *
  /// time_increment_s (a spinning lidar sweeps its beams one after the other; a ROS LaserScan's
  /// time_increment, negative once its beams are put in counter-clockwise order). Both 0: every
  /// beam at the stamp (CARMEN logs, drivers that do not say).
  double first_beam_s = 0.0;
  double time_increment_s = 0.0;
};

/// Whether the scan's beams were taken one after the other (a sweep), not all at its stamp.
[[nodiscard]] inline bool has_beam_times(const RangeScan& scan) {
  return scan.first_beam_s != 0.0 || scan.time_increment_s != 0.0;
}

/// When beam i was taken, in seconds after the scan's stamp.
[[nodiscard]] inline double beam_time_s(const RangeScan& scan, std::size_t i) {
  return scan.first_beam_s + static_cast<double>(i) * scan.time_increment_s;
}

/// The same beams in reverse order, each keeping its range and its time (the angles are the
/// caller's: see mirrored()).
inline void reverse_beams(RangeScan& scan) {
  scan.first_beam_s = beam_time_s(scan, scan.ranges_m.empty() ? 0 : scan.ranges_m.size() - 1);
  scan.time_increment_s = 0.0 - scan.time_increment_s;  // never -0
  std::reverse(scan.ranges_m.begin(), scan.ranges_m.end());
}

/// The angle of the scan's last beam (angle_min_rad when it has none): LaserScan's angle_max.
[[nodiscard]] inline double last_angle_rad(const RangeScan& scan) {
  const std::size_t n = scan.ranges_m.size();
  return scan.angle_min_rad + scan.angle_increment_rad * static_cast<double>(n > 0 ? n - 1 : 0);
}

/// The same beams listed the other way round, last first: each keeps its angle, range and time,
/// the angle and time increments change sign (a clockwise driver's scan put counter-clockwise, and
/// back).
[[nodiscard]] inline RangeScan reversed(RangeScan scan) {
  scan.angle_min_rad = last_angle_rad(scan);
  scan.angle_increment_rad = -scan.angle_increment_rad;
  reverse_beams(scan);
  return scan;
}

/// The same scan in the sensor frame mirrored across its x axis (y -> -y), the frame of an
/// upside-down sensor seen from above: beam angles change sign, so the beams come in reverse
/// order from -(last angle). Mirroring twice gives the scan back.
[[nodiscard]] inline RangeScan mirrored(RangeScan scan) {
  scan.angle_min_rad = -last_angle_rad(scan);
  reverse_beams(scan);
  return scan;
}

}  // namespace tessera
