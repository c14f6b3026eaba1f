#pragma once
// The submap grid of the laser SLAM: occupancy probabilities quantised to 15 bits, updated through
// lookup tables, growing as scans reach beyond it (Hess et al. 2016, Sec. IV "Submaps";
// Cartographer's probability_grid.cc and probability_values.cc). A 16-bit cell keeps a submap
// small (2 bytes per cell) and makes an update one table look-up instead of a log/exp.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/grid/grid_geometry.hpp"
#include "tessera/grid/occupancy_grid.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::slam {

/// Probabilities a grid can hold (Cartographer's kMinProbability / kMaxProbability): a cell can
/// always change its mind, and no cell scores more than 0.9 in a match.
inline constexpr double kMinProbability = 0.1;
inline constexpr double kMaxProbability = 0.9;
/// Cell value 0 is "unknown"; 1 ... kMaxCellValue map linearly onto [kMinProbability,
/// kMaxProbability].
inline constexpr std::uint16_t kUnknownCellValue = 0;
inline constexpr std::uint16_t kMaxCellValue = 32767;

/// The cell value nearest to probability p (clamped into [kMinProbability, kMaxProbability]).
[[nodiscard]] std::uint16_t probability_to_value(double p);
/// The probability of a cell value; unknown (0) reads as kMinProbability, the score an
/// unexplored cell gets in a match (Cartographer treats unknown as the highest cost).
[[nodiscard]] float value_to_probability(std::uint16_t value);
/// The table behind value_to_probability, 32768 entries, for hot loops.
[[nodiscard]] const std::vector<float>& value_to_probability_table();

/// An update of one cell by an observation with probability p of "occupied": Bayes in odds form,
/// odds' = odds * p / (1 - p), tabulated over every cell value (Cartographer's
/// ComputeLookupTableToApplyOdds). An unknown cell becomes p. Entries carry an update marker
/// (bit 15) so that a cell is updated once per scan.
struct UpdateTable {
  std::vector<std::uint16_t> after;  // after[value] = new value | marker
};
[[nodiscard]] UpdateTable make_update_table(double p);

/// A growable grid of occupancy probabilities. Cell (0,0) is the lower-left cell
/// (docs/conventions.md); the grid's frame is the frame its owner (a submap) says it is.
class ProbabilityGrid {
 public:
  ProbabilityGrid() = default;
  /// Every cell unknown.
  explicit ProbabilityGrid(const GridGeometry& geometry);

  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  /// Row-major cell values (index = y * width + x); 0 is unknown.
  [[nodiscard]] const std::vector<std::uint16_t>& values() const { return values_; }
  /// Precondition for the per-cell calls: geometry().contains(c).
  [[nodiscard]] std::uint16_t value(Cell c) const { return values_[geometry_.index_of(c)]; }
  [[nodiscard]] bool known(Cell c) const { return value(c) != kUnknownCellValue; }
  /// The cell's probability; kMinProbability for unknown cells and for cells outside the grid.
  [[nodiscard]] float probability(Cell c) const {
    return geometry_.contains(c) ? value_to_probability(values_[geometry_.index_of(c)])
                                 : static_cast<float>(kMinProbability);
  }
  void set_probability(Cell c, double p);

  /// Grows the grid (doubling its size, centred) until p_m lies inside with `margin_cells` to
  /// spare, keeping every cell where it is in space. Invalidates cell indices, not cells.
  void grow_to_include(Vec2 p_m, int margin_cells = 1);

  /// Applies table to cell c unless c was already updated since the last finish_update().
  /// Returns true when the cell was updated. Precondition: geometry().contains(c).
  bool apply(Cell c, const UpdateTable& table);
  /// Ends an update: clears the markers so the next scan can update the same cells again.
  void finish_update();

  /// The smallest box of cells that holds every known cell; nullopt for an empty grid.
  using Box = CellBox;
  [[nodiscard]] std::optional<Box> known_box() const;

  /// The known part as an OccupancyGrid (unknown stays unknown), cropped to known_box() with
  /// `padding_cells` around it; probabilities are the cells' own.
  [[nodiscard]] OccupancyGrid to_occupancy_grid(int padding_cells = 1) const;

 private:
  GridGeometry geometry_;
  std::vector<std::uint16_t> values_;
  std::vector<std::size_t> updated_;  // cells carrying the update marker
};

/// How scan points update a grid (Cartographer's ProbabilityGridRangeDataInserter2D): the cell of
/// each return gets a hit, cells a ray crosses before its end get a miss, rays that saw nothing
/// (ScanPoints::misses_m) miss every cell up to their end. Hit and miss probabilities are
/// Cartographer's 2D defaults: weak evidence per scan, so a submap averages many scans.
struct RangeInsertOptions {
  double hit_probability = 0.55;
  double miss_probability = 0.49;
  bool insert_free_space = true;
  /// A cell gets a miss only when the ray enters it at least this far before its return. Without
  /// it a wall whose surface lies near a cell border is cleared from the near cell by the returns
  /// that land (by noise) in the far one, and the map's walls shift away from the sensor by up to
  /// half a cell (the same range band as ScanInsertOptions::free_margin_m, decision 0003).
  double miss_margin_m = 0.0;
  /// A cell gets a miss only when the ray passes at least this far inside its square: a ray that
  /// runs along a wall's face, or clips a cell's corner, leaves the cell as it was.
  double miss_inset_m = 0.0;
  /// Returns of neighbouring beams closer than this are joined: every cell of the segment between
  /// them gets a hit, so a wall is a continuous line of cells instead of one cell per beam. Without
  /// it a grid built from few viewpoints has its beams' footprints as local optima: matching a scan
  /// turned by a fraction of the beam spacing snaps to the nearest whole spacing (a periodic cost
  /// in the heading, seen in simulation as a 1.5 deg bias when a run starts with a turn in place).
  /// 0: one hit per return (Cartographer's model). On Intel, 0.5 m leaves the relation errors as
  /// they were (0.0187 m / 0.27 deg against 0.0182 m / 0.31 deg) with a seventh of the wrong loop
  /// closures; in simulation it removes the bias (decision 0007).
  double join_returns_within_m = 0.5;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const RangeInsertOptions& o);

/// Inserts scans into grids with tables built once.
class RangeInserter {
 public:
  explicit RangeInserter(const RangeInsertOptions& options = {});

  /// Inserts `points` (robot frame) seen from T_grid_robot, growing the grid as needed. Each cell
  /// is updated at most once per call; a hit wins over a miss in the same cell. Ray traversal is
  /// exact (Amanatides & Woo, grid/ray_cast.hpp). Cost: O(rays * length / resolution).
  void insert(ProbabilityGrid& grid, const Pose2& T_grid_robot, const ScanPoints& points) const;

 private:
  RangeInsertOptions options_;
  UpdateTable hit_;
  UpdateTable miss_;
};

}  // namespace tessera::slam
