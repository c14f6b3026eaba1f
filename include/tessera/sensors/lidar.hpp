#pragma once
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera {

/// A 2D lidar: beams spread evenly over the field of view, centred on the sensor's x axis.
struct LidarOptions {
  int beams = 360;
  double fov_rad = 2.0 * std::numbers::pi;
  double min_range_m = 0.0;
  double max_range_m = 8.0;
  double range_noise_stddev_m = 0.01;  // Gaussian truncated at 3 sigma, added to every return
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const LidarOptions& o);

/// The scan's beam layout (angles, range limits) with every range set to max_range_m ("no return"),
/// ranges_m.size() == beams. A full circle (fov_rad >= 2 pi) spaces the beams fov / beams apart,
/// starting at -fov / 2, so the first and last beams do not coincide; a narrower field of view puts
/// the first and last beam on its edges (spacing fov / (beams - 1)). One beam points along +x.
/// Precondition: validate(o) is empty.
[[nodiscard]] RangeScan empty_scan(const LidarOptions& o);

/// How a scan updates an occupancy grid (the inverse sensor model).
struct ScanInsertOptions {
  SensorModelOptions model;
  /// The range uncertainty band. A cell gets a miss only if the beam enters it at least this far
  /// before the measured range, so that a long reading cannot clear the wall cell it ran into; the
  /// hit goes to the cell holding the point this far beyond the range, so that a short reading
  /// does not darken the free cell in front of the wall. The simulator truncates range noise at
  /// 3 sigma, so a margin above 3 sigma makes the first impossible (errors fall on the safe side);
  /// the default suits the default 0.01 m noise.
  double free_margin_m = 0.0301;
};

/// Ray-cast update of `map` with one scan taken at T_map_sensor: the cell holding each return gets
/// a hit, cells the beam crossed before it get a miss (see free_margin_m); no-return beams only
/// clear up to max range (cells entered at least free_margin_m before it, since a wall just beyond
/// the range could read as "no return" with noise). The hit cell is the one containing the point
/// free_margin_m (plus 1e-9 m) beyond the range, so a return exactly on a cell border lands in the
/// wall cell behind it. Ranges below min_range_m, and NaN, are invalid and skipped. Cells outside
/// the map are ignored. Every cell whose value changed or that became known is appended to
/// `touched` when it is not null (cells may repeat). Traversal is exact (Amanatides & Woo,
/// grid/ray_cast.hpp); log-odds deltas are computed once per call. Cost: O(beams * max_range /
/// resolution).
void insert_scan(OccupancyGrid& map, const Pose2& T_map_sensor, const RangeScan& scan,
                 const ScanInsertOptions& options, std::vector<Cell>* touched);

}  // namespace tessera
