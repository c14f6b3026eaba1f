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
  double range_noise_stddev_m = 0.01;  // Gaussian, added to every return
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const LidarOptions& o);

/// The scan's beam layout (angles, range limits) with no ranges filled in.
[[nodiscard]] RangeScan empty_scan(const LidarOptions& o);

/// How a scan updates an occupancy grid (the inverse sensor model).
struct ScanInsertOptions {
  SensorModelOptions model;
  /// A cell gets a miss only if the beam enters it at least this far before the measured range, so
  /// that range noise cannot mark the wall cell behind a short reading free (errors fall on the safe
  /// side). About 3 sigma of the range noise.
  double free_margin_m = 0.03;
};

/// Ray-cast update of `map` with one scan taken at T_map_sensor: the cell holding each return gets a
/// hit, cells the beam crossed before it get a miss (see free_margin_m); no-return beams only clear
/// up to max range. Cells outside the map are ignored. Every cell whose value changed is appended to
/// `touched` when it is not null (cells may repeat). Cost: O(beams * max_range / resolution).
void insert_scan(OccupancyGrid& map, const Pose2& T_map_sensor, const RangeScan& scan,
                 const ScanInsertOptions& options, std::vector<Cell>* touched);

}  // namespace tessera
