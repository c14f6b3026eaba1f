#pragma once
// Pictures of one step of the lecture's grid-matching SLAM (slam/gridmatch.hpp), drawn as the
// lecture draws them ("Numerical example for a SLAM algorithm"): maps of the robot's window with
// the robot moving up the page, obstacles grey, free cells white, unexplored cells "?"; the
// similarity S(i,j) = m(i,j) p(i,j) cell by cell ("Matrix (c)") and S under each test pose. SVG,
// so that the numbers stay text.
#include <cstddef>
#include <string>
#include <vector>

#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/slam/gridmatch.hpp"
#include "tessera/slam/perception_map.hpp"

namespace tessera {

/// What one step computed: the current map before the update, the perception map of the sensor
/// (robot frame), and every test pose with its S (match() on those two).
struct GridMatchStep {
  const OccupancyGrid* map = nullptr;
  const slam::TernaryGrid* perception = nullptr;
  const slam::GridMatchResult* result = nullptr;
  /// Names of the test poses in candidate order, for captions ("up one cell, 15 deg CW").
  std::vector<std::string> labels;
};

/// One test pose k: its expected map e(m, t), the perception map p, and S(i,j), with S, the
/// overlap and the pose. Precondition: k < result->candidates.size(), pointers set.
[[nodiscard]] std::string gridmatch_candidate_svg(const GridMatchStep& step, std::size_t k);

/// The whole step on one sheet: the current map (north up, the odometry pose marked), the
/// perception map, S(i,j) at the best test pose, then every test pose's expected map with its S in
/// the order tried, three to a row (for the lecture's 5 x 3 poses: a position per row, the
/// headings intended, clockwise, counter-clockwise across), the best one framed.
[[nodiscard]] std::string gridmatch_sheet_svg(const GridMatchStep& step);

}  // namespace tessera
