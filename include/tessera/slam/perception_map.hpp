#pragma once
// The maps the lecture's SLAM algorithm compares (Ben-Ari & Mondada, lecture "Numerical example for
// a SLAM algorithm" and "Formalization of the SLAM algorithm"): a small grid of cells around the
// robot, in the robot's frame, each cell encoded as the lecture encodes it before multiplying,
// -1 empty, +1 obstacle, 0 anything else (unknown, or out of the sensor's range).
//
// Two such maps exist for one step of the algorithm:
//  - the *perception map* p, built from the sensor data (line 04, "p <- analyze sensor data");
//  - the *expected map* e for a test pose t, the current map m seen from t (line 06,
//    "e <- expected(m, t)"): "for each small possible error in pose, compute what perception of
//    the current map would be".
// Both live on the same window of cells in the robot frame, so compare(p, e) is a cell-by-cell
// product (gridmatch.hpp).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/assert.hpp"
#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/sensors/cell_sensor.hpp"
#include "tessera/sensors/range_scan.hpp"

namespace tessera::slam {

/// The lecture's cell encoding ("assign values for empty -> -1, obstacle -> +1, other -> 0").
inline constexpr std::int8_t kTernaryFree = -1;
inline constexpr std::int8_t kTernaryUnknown = 0;
inline constexpr std::int8_t kTernaryOccupied = 1;

/// A grid of -1 / 0 / +1 cells: the lecture's "8x5 matrices". The geometry is in whatever frame
/// the caller says; for perception and expected maps it is the robot frame (x forward, y left, the
/// robot at the origin), see robot_window(). Same grid convention as every tessera grid
/// (docs/conventions.md). A new grid is all unknown (0). Memory: one byte per cell.
class TernaryGrid {
 public:
  TernaryGrid() = default;
  explicit TernaryGrid(const GridGeometry& geometry)
      : geometry_(geometry), values_(geometry.size(), kTernaryUnknown) {}

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  /// -1, 0 or +1. Precondition: geometry().contains(c).
  [[nodiscard]] std::int8_t at(Cell c) const { return values_[geometry_.index_of(c)]; }
  /// Precondition: geometry().contains(c) and value is -1, 0 or +1.
  void set(Cell c, std::int8_t value) {
    TESSERA_ASSERT(value >= kTernaryFree && value <= kTernaryOccupied);
    values_[geometry_.index_of(c)] = value;
  }
  /// The cells in storage order (index = y * width + x).
  [[nodiscard]] const std::vector<std::int8_t>& values() const { return values_; }
  /// Cells that are not 0.
  [[nodiscard]] std::size_t known_count() const;
  [[nodiscard]] bool operator==(const TernaryGrid&) const = default;

 private:
  GridGeometry geometry_;
  std::vector<std::int8_t> values_;
};

/// A cell of the current map in the lecture's encoding: 0 when unknown, +1 when the threshold view
/// calls it occupied (p >= occupied_threshold), -1 otherwise. Precondition: map contains c.
[[nodiscard]] std::int8_t ternary_value(const OccupancyGrid& map, Cell c,
                                        double occupied_threshold = 0.5);

/// A window of cells in the robot frame (x forward, y to the left, metres) with the robot at the
/// centre of one cell: `behind_cells` rows of cells behind it, `ahead_cells` ahead, `side_cells`
/// on each side. Width (along x) is behind + 1 + ahead, height (along y) 2 * side + 1, and the
/// robot is in cell (behind_cells, side_cells). The lecture's 8x5 maps of a robot that sees 5 cells
/// ahead are robot_window(cell_m, 2, 5, 2). Preconditions: cell_m > 0, counts >= 0.
[[nodiscard]] GridGeometry robot_window(double cell_m, int behind_cells, int ahead_cells,
                                        int side_cells);

/// The square window that holds everything a sensor of range max_range_m can report:
/// ceil(max_range_m / cell_m) cells on every side of the robot's cell.
/// Preconditions: cell_m > 0, max_range_m >= 0.
[[nodiscard]] GridGeometry robot_window(double cell_m, double max_range_m);

/// How a range scan becomes a perception map.
struct PerceptionOptions {
  /// How deep behind a return a cell still counts as obstacle, in cells of the window (the
  /// lecture's example assumes "any wall is one cell thick").
  double wall_depth_cells = 1.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const PerceptionOptions& o);

/// The perception map of a range scan taken by a sensor at T_robot_sensor (the identity when the
/// sensor sits at the robot's centre, as in the simulator), by the lecture's rule: "the actual
/// position of the wall as seen by the robot overlaid on the cells; a cell is gray if the majority
/// of its area is behind the wall". A cell is judged by its centre, at distance d and bearing phi
/// from the sensor, against the beam nearest phi with range r:
///   d < r                                  -1  (the beam crossed it: free)
///   r <= d < r + wall_depth_cells * cell   +1  (just behind the return: the wall)
///   otherwise                               0  (behind the wall, or beyond max range: unseen)
/// A beam with no return (r >= max_range_m) frees the cells up to max range. Cells whose nearest
/// beam is invalid (NaN or below min_range_m) or outside a partial field of view are 0. Judging by
/// the centre is what expected_map() does too, so at the true pose a perfect sensor's perception
/// and the expected map of a perfect map agree cell for cell (rasterising the returns through the
/// occupancy grid's inverse sensor model would not: a cell the wall crosses gets more misses than
/// hits and turns free, and the true pose loses). Zero-range cells (the sensor's own) are free.
/// Precondition: validate(o) is empty. Cost: O(window cells).
[[nodiscard]] TernaryGrid perception_from_scan(const RangeScan& scan, const GridGeometry& window,
                                               const Pose2& T_robot_sensor = {},
                                               const PerceptionOptions& o = {});

/// The perception map of the lecture's cell sensor (the robot tells for each of its 8 neighbours
/// whether it holds an obstacle): a 3 x 3 window of cell_m cells centred on the robot, the centre
/// free (the robot stands in it), each reported neighbour -1 or +1, unreported ones 0. The reading
/// is given in the map's axes (kNeighbors8), so the window's frame is the map's axes moved to the
/// robot: match it with T_map_robot = {centre of reading.center, theta = 0}. Precondition:
/// cell_m > 0.
[[nodiscard]] TernaryGrid perception_from_cells(const CellReading& reading, double cell_m);

/// The lecture's expected map e = expected(m, t): what the robot would perceive of the current map
/// if it stood at the test pose T_map_robot. Each cell of `window` (robot frame) takes the value of
/// the map cell that contains the window cell's centre, moved into the map frame by T_map_robot
/// (ternary_value with occupied_threshold); window cells whose centre falls outside the map are 0.
/// This is the lecture's direction: the current map is brought into the perception's frame, not the
/// other way round. Cost: O(window cells).
[[nodiscard]] TernaryGrid expected_map(const OccupancyGrid& map, const GridGeometry& window,
                                       const Pose2& T_map_robot, double occupied_threshold = 0.5);

}  // namespace tessera::slam
