#pragma once
// Correlative scan matching: score every pose of a discretised search window by how occupied the
// grid is where the scan's points land (Olson 2009, "Real-time correlative scan matching").
//  - match_real_time: exhaustive at full resolution over a small window, with a penalty for moving
//    away from the prior (Hess et al. 2016, Sec. V; Cartographer's RealTimeCorrelativeScanMatcher).
//  - BranchAndBoundMatcher: a wide window (metres, a full turn) searched by branch and bound over
//    precomputed max-pooled grids, whose scores bound every finer pose below them (Olson 2009
//    Sec. III-D "multi-resolution"; Hess et al. 2016 Sec. V-B and Algorithm 3). Returns the same
//    best pose as exhaustive search at the finest level, much faster.
// Scores are mean probabilities of the points' cells (unknown and outside cells count as
// kMinProbability), so they lie in [kMinProbability, kMaxProbability].
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/slam/probability_grid.hpp"

namespace tessera::slam {

/// A scan's pose in a grid's frame and its score.
struct ScanMatch {
  Pose2 T_grid_robot;
  double score = 0.0;
};

/// The angle step at which the farthest point moves by at most one cell (Hess et al. 2016, eq. 7):
/// acos(1 - r^2 / (2 d_max^2)).
[[nodiscard]] double angular_search_step_rad(double resolution_m, double max_point_range_m);

struct RealTimeMatcherOptions {
  double linear_window_m = 0.1;     // +- around the prior, in x and in y
  double angular_window_rad = 0.2;  // +- around the prior
  /// The score is multiplied by exp(-(w_t * |dt| + w_r * |dtheta|)^2), so that among poses that
  /// fit about equally the one nearest the prior wins (Cartographer's delta cost weights).
  double translation_delta_cost_weight = 0.1;  // per metre
  double rotation_delta_cost_weight = 0.1;     // per radian
  /// The angle step is the one that moves a point at this range (or at the farthest point, if
  /// nearer) by one cell: returns beyond it move further per step, which the refinement after the
  /// search takes up. Stepping for a 20 m return would cost 2.5x the angles of an 8 m one.
  double angular_step_range_m = 10.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const RealTimeMatcherOptions& o);

/// Exhaustive search over the window around T_grid_robot_prior at the grid's resolution and
/// angular_search_step_rad. points_robot: the scan in the robot frame. The returned score is the
/// weighted one. Cost: O(angles * cells of the window * points).
[[nodiscard]] ScanMatch match_real_time(const ProbabilityGrid& grid,
                                        const Pose2& T_grid_robot_prior,
                                        const std::vector<Vec2>& points_robot,
                                        const RealTimeMatcherOptions& options);

/// A search window around a prior pose: +-linear_m in x and y, +-angular_rad in heading (pi or
/// more: a full turn).
struct SearchWindow {
  double linear_m = 5.0;
  double angular_rad = 3.14159265358979323846;
};

/// Poses a search skips: those within linear_m (in the plane) and angular_rad of any pose in
/// `around`. A search that excludes the best pose's neighbourhood finds the best pose of another
/// place, the runner-up that tells whether the best is clearly best (global relocalization);
/// excluding that one too finds the next.
struct ExcludedPoses {
  std::vector<Pose2> around;
  double linear_m = 1.0;
  double angular_rad = 0.5;

  /// Whether `pose` is within linear_m and angular_rad of a pose in `around`.
  [[nodiscard]] bool contains(const Pose2& pose) const;
};

/// The poses that rival a search's best one (global relocalization's ambiguity test): those
/// scoring at least `ratio` of the best's excess over `floor` (what a view that sees nothing of
/// the map scores). A caller looks at the places they stand at one by one, best first, at most
/// `places` of them, the best's included: place k is the best pose not within `distinct` of
/// places 1 to k - 1.
struct Rivals {
  double floor = 0.5;
  double ratio = 0.85;
  ExcludedPoses distinct;  // its linear_m and angular_rad; `around` is not used
  int places = 5;
  [[nodiscard]] double score(double best_score) const {
    return floor + ratio * (best_score - floor);
  }
};

/// A search's best pose and the poses that rival it.
struct RankedMatches {
  ScanMatch best;
  /// Best first (the best among them) and, among equal scores, in the order the search met them:
  /// every pose scoring at least rivals.score(best.score) that can be one of the first
  /// rivals.places places. So, for places 2 to rivals.places, the first contender not within
  /// `distinct` of the places before it is the pose match() returns with them excluded and
  /// min_score rivals.score(best.score).
  std::vector<ScanMatch> contenders;
};

/// The precomputed grids of branch and bound: level d holds, for every cell (x, y), the highest
/// cell value of the original grid in [x, x + 2^d) x [y, y + 2^d) (quantised to 8 bits: 0 for
/// kMinProbability and unknown, 255 for kMaxProbability). Built once per finished submap.
class BranchAndBoundMatcher {
 public:
  /// depth: number of levels (1 = only the full-resolution one). Unknown cells score as
  /// unknown_probability (a loop closure counts them as free; a relocalization whose view sees
  /// beyond the map may count them as even odds). Cost: O(depth * cells).
  BranchAndBoundMatcher(const ProbabilityGrid& grid, int depth,
                        double unknown_probability = kMinProbability);

  [[nodiscard]] int depth() const { return static_cast<int>(levels_.size()); }
  [[nodiscard]] const GridGeometry& geometry() const { return geometry_; }
  [[nodiscard]] std::size_t memory_bytes() const;

  /// The best pose within `window` around T_grid_robot_prior whose score reaches min_score, by
  /// branch and bound; nullopt if none does. Translations are whole cells from the prior, angles
  /// whole steps of angular_search_step_rad. The poses within 2 cells and 3 angle steps of the
  /// prior are scored first, so that a good estimate prunes the tree early; among equal scores the
  /// first found wins (a pose near the prior, else the one of the most promising branch).
  /// Cost: O(angles * points) to discretise, then typically a small share of the exhaustive
  /// O(angles * window cells * points).
  /// With `excluded`, its poses are never returned (the bounds still hold: they only skip leaves).
  [[nodiscard]] std::optional<ScanMatch> match(
      const Pose2& T_grid_robot_prior, const std::vector<Vec2>& points_robot,
      const SearchWindow& window, double min_score,
      const std::optional<ExcludedPoses>& excluded = std::nullopt) const;

  /// The best pose as match() finds it and, in the same search, the poses that rival it: one
  /// search where match() for the best and then for the best of each other place would run
  /// several (decision 0044). The bound is min_score until a best is found, as match()'s; the
  /// candidates passed over meanwhile that may hold a rival are searched after. From then on it
  /// is the rival score, raised to the lowest score of `places` places met so far that no two
  /// places' exclusions can both hold (twice `distinct` apart).
  [[nodiscard]] std::optional<RankedMatches> match_ranked(const Pose2& T_grid_robot_prior,
                                                          const std::vector<Vec2>& points_robot,
                                                          const SearchWindow& window,
                                                          double min_score,
                                                          const Rivals& rivals) const;

  /// The same search scoring every candidate at full resolution (the reference for tests).
  [[nodiscard]] std::optional<ScanMatch> match_exhaustive(const Pose2& T_grid_robot_prior,
                                                          const std::vector<Vec2>& points_robot,
                                                          const SearchWindow& window,
                                                          double min_score) const;

 private:
  struct Level {
    int width = 0;   // the original width + 2^d - 1: cells x in [-(2^d - 1), original width)
    int height = 0;  // likewise
    int offset = 0;  // 2^d - 1
    std::vector<std::uint8_t> cells;
  };
  struct Search;

  GridGeometry geometry_;
  std::vector<Level> levels_;
};

}  // namespace tessera::slam
