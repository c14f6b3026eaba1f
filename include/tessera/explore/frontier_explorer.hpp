#pragma once
// Goal selection for frontier exploration (Ben-Ari & Mondada, lecture Algo 9.1 and "Priority in the
// frontier algorithm"), for one robot or several robots sharing one map.
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "tessera/core/cell.hpp"
#include "tessera/explore/frontier.hpp"
#include "tessera/explore/frontier_set.hpp"
#include "tessera/explore/path_search.hpp"
#include "tessera/grid/occupancy_grid.hpp"

namespace tessera {

/// How a robot picks its next frontier cell.
enum class FrontierStrategy {
  /// The reachable frontier cell with the shortest path (lecture Algo 9.1 line 8).
  kNearest,
  /// The reachable frontier cell with the highest priority p = a / d, a = unknown 4-neighbours,
  /// d = path length in cells (lecture, "Priority in the frontier algorithm").
  kPriority,
};

[[nodiscard]] const char* to_string(FrontierStrategy s);

struct FrontierExplorerOptions {
  FrontierStrategy strategy = FrontierStrategy::kNearest;
  /// Occupancy probability below which a known cell is open (Algo 9.1's `low`). Must equal the
  /// FrontierSet's low.
  double low = kDefaultFrontierLow;
  /// Several robots: frontier cells within this Chebyshev distance of a target claimed by another
  /// robot are chosen only when nothing else is reachable, so that robots spread out over the
  /// frontier. 0 only excludes the claimed cells themselves.
  int spread_radius_cells = 4;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const FrontierExplorerOptions& o);

/// A robot's chosen frontier cell and the way there.
struct FrontierPlan {
  Cell target;
  /// Robot cell first, target last; every cell after the first is known free.
  std::vector<Cell> path;
  int distance_cells = 0;     // d = path.size() - 1
  int unknown_neighbors = 0;  // a
  double priority = 0.0;      // a / max(d, 1)
};

/// A frontier cell that no search of the robots reached, and the map revision
/// (FrontierSet::revision()) at which that was found.
struct UnreachableFrontier {
  Cell cell;
  std::uint64_t revision = 0;
};

/// Chooses frontier targets for a team of robots that share one map and one FrontierSet.
///
/// Several robots (lecture: "can be run in parallel by multiple robots; each robot explores the
/// portion of the frontier closest to its position"): plans are made one robot at a time, and a
/// plan never takes a target claimed by another robot; cells within spread_radius_cells of such a
/// target are taken only as a fallback. plan_all() plans robots in index order.
///
/// Termination guards:
/// - A robot whose search found nothing remembers the map revision and the claims it saw; asked
///   again before either changed, it answers nullopt without searching (no spinning). Once the map
///   changes it searches again, so exploration does not stop while reachable frontier remains.
///   The frontier cells its search could not reach are recorded as UnreachableFrontier.
/// - blacklist(): a target that is still a frontier after the robot stood on it and sensed
///   cannot be resolved; it is never chosen again, so a run cannot loop on it.
///
/// d = 0 (the robot stands on a frontier cell) is handled as d = 1 in the priority, so such a cell
/// has priority a, and the plan's path is the robot cell alone.
///
/// Cost per plan: one BFS (FreeSpaceBfs), stopped at the first eligible cell for kNearest and, for
/// kPriority, as soon as the depth d satisfies 4 / d <= p_best (a <= 4, so no deeper cell can win;
/// ties go to the cell found first). A failed plan visits the robot's whole free component.
class FrontierExplorer {
 public:
  /// Precondition: validate(options) is empty, robots >= 1.
  FrontierExplorer(const FrontierExplorerOptions& options, int robots);

  [[nodiscard]] const FrontierExplorerOptions& options() const { return options_; }
  [[nodiscard]] int robot_count() const { return static_cast<int>(claims_.size()); }

  /// Releases `robot`'s claim and chooses a new target for it standing at `robot_cell`; the target
  /// becomes its claim. nullopt when it can reach no eligible frontier cell.
  /// Precondition: frontier.low() == options().low and frontier is up to date with `map`.
  [[nodiscard]] std::optional<FrontierPlan> plan(const OccupancyGrid& map,
                                                 const FrontierSet& frontier, int robot,
                                                 Cell robot_cell);

  /// Plans every robot, in index order; robot_cells[i] is robot i's cell.
  [[nodiscard]] std::vector<std::optional<FrontierPlan>> plan_all(
      const OccupancyGrid& map, const FrontierSet& frontier, std::span<const Cell> robot_cells);

  /// The robot's current target, if any.
  [[nodiscard]] std::optional<Cell> claim(int robot) const;
  void release(int robot);

  /// Never choose `c` again (see the class comment).
  void blacklist(Cell c);
  [[nodiscard]] bool blacklisted(Cell c) const;
  [[nodiscard]] const std::vector<Cell>& blacklisted_cells() const { return blacklist_list_; }

  /// The frontier cells (not blacklisted) that the most recent failed search could not reach, row-
  /// major, each with the map revision of that search. Kept until the next failed search.
  [[nodiscard]] const std::vector<UnreachableFrontier>& unreachable() const { return unreachable_; }

 private:
  struct Failure {
    std::uint64_t revision = 0;
    std::uint64_t claims_version = 0;
    Cell cell;
  };

  [[nodiscard]] bool claimed_by_other(Cell c, int robot) const;
  [[nodiscard]] bool near_other_claim(Cell c, int robot) const;
  void record_unreachable(const FrontierSet& frontier);

  FrontierExplorerOptions options_;
  FreeSpaceBfs bfs_;
  std::vector<std::optional<Cell>> claims_;
  std::uint64_t claims_version_ = 0;
  std::vector<std::optional<Failure>> failures_;
  std::vector<std::uint8_t> blacklist_;  // per cell, sized on first use
  GridGeometry blacklist_geometry_;
  std::vector<Cell> blacklist_list_;
  std::vector<UnreachableFrontier> unreachable_;
};

}  // namespace tessera
