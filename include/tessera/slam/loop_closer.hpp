#pragma once
// Loop closure: finds where a scan sits in an older, finished submap, searching a wide window
// around the current estimate by branch and bound and refining the best pose to sub-cell accuracy
// (Hess et al. 2016, Sec. V "Closing loops"; Olson 2009 for the search; Konolige et al. 2010
// (Karto) for matching new scans against older parts of the map). A match counts only when its
// score reaches a threshold, so places that merely look alike are rejected; the constraints it
// produces still get a robust loss in the pose graph.
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/slam/correlative_scan_matcher.hpp"
#include "tessera/slam/probability_grid.hpp"
#include "tessera/slam/scan_refiner.hpp"

namespace tessera::slam {

struct LoopCloserOptions {
  /// Where to look around the current estimate (metres in x and y, radians of heading). The
  /// default covers the drift local SLAM accumulates between two optimisations on Intel (accepted
  /// corrections: 99% below 0.04 rad); LaserSlamOptions::global_window adds rare wide searches.
  SearchWindow window{2.0, 0.25};
  /// Levels of max-pooled grids: the coarsest cell covers 2^(depth-1) cells.
  int branch_and_bound_depth = 7;
  /// A match must reach this mean probability in the search and again after refinement.
  double min_score = 0.6;
  /// The refinement after the search: weak ties to the searched pose, the grid decides.
  ScanRefinerOptions refiner{1.0, 1.0, 1.0, 20};
  /// The refined pose may not move further than this from the searched one (metres); a refinement
  /// that slides away did not find a sharp optimum.
  double max_refinement_shift_m = 0.1;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const LoopCloserOptions& o);

struct LoopMatch {
  Pose2 T_submap_robot;
  double search_score = 0.0;   // branch-and-bound score (mean probability, cell-quantised pose)
  double refined_score = 0.0;  // mean interpolated probability at the refined pose
  /// The refinement's J^T J of the occupied-space term (scan_refiner.hpp): how sharply the submap
  /// pins each direction of the pose.
  Eigen::Matrix3d hessian = Eigen::Matrix3d::Zero();
};

/// Holds the branch-and-bound grids of every finished submap it was given.
class LoopCloser {
 public:
  explicit LoopCloser(const LoopCloserOptions& options) : options_(options) {}

  /// Precomputes the search grids of a finished submap. Cost: O(depth * cells).
  void add_submap(int submap_id, const ProbabilityGrid& grid);
  [[nodiscard]] bool has_submap(int submap_id) const { return matchers_.count(submap_id) != 0; }
  [[nodiscard]] const LoopCloserOptions& options() const { return options_; }

  /// Searches submap `submap_id` (whose grid is `grid`, the one given to add_submap) for a scan
  /// around T_submap_robot_guess within options().window: branch and bound with search_points (a
  /// sparse subset of the scan, robot frame), then refinement with refine_points (the whole scan).
  /// nullopt when no pose reaches min_score, when the best pose lies on the window's edge (the
  /// true optimum may lie beyond it: a corridor that runs on), or when the refinement slides away.
  /// Precondition: has_submap(submap_id).
  [[nodiscard]] std::optional<LoopMatch> match(int submap_id, const ProbabilityGrid& grid,
                                               const Pose2& T_submap_robot_guess,
                                               const std::vector<Vec2>& search_points,
                                               const std::vector<Vec2>& refine_points) const;

  /// The same with an explicit window and threshold (a wide search wants a stricter one).
  [[nodiscard]] std::optional<LoopMatch> match(int submap_id, const ProbabilityGrid& grid,
                                               const Pose2& T_submap_robot_guess,
                                               const std::vector<Vec2>& search_points,
                                               const std::vector<Vec2>& refine_points,
                                               const SearchWindow& window, double min_score) const;

  /// Bytes held by the search grids.
  [[nodiscard]] std::size_t memory_bytes() const;

 private:
  LoopCloserOptions options_;
  std::map<int, std::unique_ptr<BranchAndBoundMatcher>> matchers_;
};

}  // namespace tessera::slam
