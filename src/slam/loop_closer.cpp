#include "tessera/slam/loop_closer.hpp"

#include <cmath>
#include <numbers>

namespace tessera::slam {
namespace {

/// Poses this close to the angular edge of a window count as on the edge.
constexpr double kEdgeAngleRad = 0.01;

}  // namespace

std::optional<std::string> validate(const LoopCloserOptions& o) {
  if (!(o.window.linear_m >= 0.0)) return "window.linear_m must be >= 0";
  if (!(o.window.angular_rad >= 0.0)) return "window.angular_rad must be >= 0";
  if (o.branch_and_bound_depth < 1 || o.branch_and_bound_depth > 12) {
    return "branch_and_bound_depth must be in [1, 12]";
  }
  if (!(o.min_score > kMinProbability && o.min_score < kMaxProbability)) {
    return "min_score must be in (0.1, 0.9)";
  }
  if (!(o.max_refinement_shift_m > 0.0)) return "max_refinement_shift_m must be > 0";
  if (auto problem = validate(o.refiner)) return "refiner." + *problem;
  return std::nullopt;
}

void LoopCloser::add_submap(int submap_id, const ProbabilityGrid& grid) {
  matchers_[submap_id] =
      std::make_unique<BranchAndBoundMatcher>(grid, options_.branch_and_bound_depth);
}

std::optional<LoopMatch> LoopCloser::match(int submap_id, const ProbabilityGrid& grid,
                                           const Pose2& T_submap_robot_guess,
                                           const std::vector<Vec2>& search_points,
                                           const std::vector<Vec2>& refine_points) const {
  return match(submap_id, grid, T_submap_robot_guess, search_points, refine_points, options_.window,
               options_.min_score);
}

std::optional<LoopMatch> LoopCloser::match(int submap_id, const ProbabilityGrid& grid,
                                           const Pose2& T_submap_robot_guess,
                                           const std::vector<Vec2>& search_points,
                                           const std::vector<Vec2>& refine_points,
                                           const SearchWindow& window, double min_score) const {
  const auto it = matchers_.find(submap_id);
  TESSERA_ASSERT(it != matchers_.end());
  const std::optional<ScanMatch> found =
      it->second->match(T_submap_robot_guess, search_points, window, min_score);
  if (!found) return std::nullopt;
  // A best pose on the window's edge is not a peak of the score: reject it.
  const Pose2 offset = between(T_submap_robot_guess, found->T_grid_robot);
  const double res = grid.geometry().resolution_m();
  const double d_x = std::abs(found->T_grid_robot.x - T_submap_robot_guess.x);
  const double d_y = std::abs(found->T_grid_robot.y - T_submap_robot_guess.y);
  if (d_x > window.linear_m - res || d_y > window.linear_m - res) return std::nullopt;
  if (window.angular_rad < std::numbers::pi &&
      std::abs(offset.theta) > window.angular_rad - kEdgeAngleRad) {
    return std::nullopt;
  }
  const RefinedPose refined =
      refine_scan(grid, found->T_grid_robot, found->T_grid_robot, refine_points, options_.refiner);
  const double shift = std::hypot(refined.T_grid_robot.x - found->T_grid_robot.x,
                                  refined.T_grid_robot.y - found->T_grid_robot.y);
  if (shift > options_.max_refinement_shift_m) return std::nullopt;
  if (refined.mean_probability < min_score) return std::nullopt;
  return LoopMatch{refined.T_grid_robot, found->score, refined.mean_probability, refined.hessian};
}

std::size_t LoopCloser::memory_bytes() const {
  std::size_t n = 0;
  for (const auto& [id, m] : matchers_) n += m->memory_bytes();
  return n;
}

}  // namespace tessera::slam
