#pragma once
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

}  // namespace tessera
