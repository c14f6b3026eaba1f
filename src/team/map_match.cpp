// Map matching between teammates' maps (team/map_match.hpp).
#include "tessera/team/map_match.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "tessera/slam/correlative_scan_matcher.hpp"
#include "tessera/slam/probability_grid.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::team {
namespace {

// Branch-and-bound levels: the coarsest scores 2^(depth-1) search cells at once.
constexpr int kSearchDepth = 7;
// A pose "above chance" scores more than the unknown cells' kMinProbability by this.
constexpr double kMinScoreAboveChance = 0.05;
// Probability of a cell next to an obstacle in the matching grids: a point one cell off a wall
// still scores, so the coarse optimum is not missed between two search cells.
constexpr double kNextToObstacle = 0.5;

struct Views {
  float occupied;
  float free;
};

bool occupied_near(const OccupancyGrid& g, Cell c, float occupied) {
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const Cell n{c.x + dx, c.y + dy};
      if (g.geometry().contains(n) && g.known(n) && g.log_odds_at(n) >= occupied) return true;
    }
  }
  return false;
}

// `fixed` as a matching grid of cell size `resolution_m`: obstacles kMaxProbability, free space
// kMinProbability, the cells around an obstacle kNextToObstacle; a coarse cell takes its most
// occupied fine cell.
slam::ProbabilityGrid matching_grid(const OccupancyGrid& fixed, double resolution_m,
                                    const Views& v) {
  const GridGeometry& f = fixed.geometry();
  const double ratio = f.resolution_m() / resolution_m;
  const GridGeometry g(f.origin(), resolution_m,
                       std::max(1, static_cast<int>(std::ceil(f.width() * ratio - 1e-9))),
                       std::max(1, static_cast<int>(std::ceil(f.height() * ratio - 1e-9))));
  slam::ProbabilityGrid out(g);
  std::vector<Cell> obstacles;
  for (std::size_t i = 0; i < f.size(); ++i) {
    const Cell c = f.cell_of(i);
    if (!fixed.known(c)) continue;
    const Cell to = g.cell_at_unchecked(f.center_of(c));
    if (!g.contains(to)) continue;
    if (fixed.log_odds_at(c) >= v.occupied) {
      out.set_probability(to, slam::kMaxProbability);
      obstacles.push_back(to);
    } else if (!out.known(to)) {
      out.set_probability(to, slam::kMinProbability);
    }
  }
  for (const Cell c : obstacles) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const Cell n{c.x + dx, c.y + dy};
        if (g.contains(n) && out.probability(n) < kNextToObstacle) {
          out.set_probability(n, kNextToObstacle);
        }
      }
    }
  }
  return out;
}

std::vector<Vec2> obstacle_points(const OccupancyGrid& map, float occupied) {
  std::vector<Vec2> out;
  const GridGeometry& g = map.geometry();
  for (std::size_t i = 0; i < g.size(); ++i) {
    const Cell c = g.cell_of(i);
    if (map.known(c) && map.log_odds_at(c) >= occupied) out.push_back(g.center_of(c));
  }
  return out;
}

}  // namespace

std::optional<std::string> validate(const MapMatchOptions& o) {
  if (!(o.search_resolution_m > 0.0) || !std::isfinite(o.search_resolution_m)) {
    return "search_resolution_m must be > 0";
  }
  if (!(0.0 < o.free_below && o.free_below < o.occupied_from && o.occupied_from < 1.0)) {
    return "need 0 < free_below < occupied_from < 1";
  }
  if (!(o.min_overlap_m2 >= 0.0) || !std::isfinite(o.min_overlap_m2)) {
    return "min_overlap_m2 must be >= 0";
  }
  if (!(o.max_conflict >= 0.0 && o.max_conflict <= 1.0)) return "max_conflict must be in [0, 1]";
  if (!(o.min_wall_agreement >= 0.0 && o.min_wall_agreement <= 1.0)) {
    return "min_wall_agreement must be in [0, 1]";
  }
  return std::nullopt;
}

MapMatch judge_map_match(const OccupancyGrid& fixed, const OccupancyGrid& moving,
                         const Pose2& T_fixed_moving, const MapMatchOptions& options) {
  const float occupied = log_odds(options.occupied_from);
  const float free = log_odds(options.free_below);
  const GridGeometry& mg = moving.geometry();
  const GridGeometry& fg = fixed.geometry();
  std::size_t overlap = 0, conflicts = 0, walls_inside = 0, walls_on_walls = 0;
  for (std::size_t i = 0; i < mg.size(); ++i) {
    const Cell m = mg.cell_of(i);
    if (!moving.known(m)) continue;
    const Cell f = fg.cell_at_unchecked(T_fixed_moving * mg.center_of(m));
    if (!fg.contains(f) || !fixed.known(f)) continue;
    ++overlap;
    const float lm = moving.log_odds_at(m);
    const float lf = fixed.log_odds_at(f);
    if (lm >= occupied) {
      ++walls_inside;
      if (occupied_near(fixed, f, occupied)) {
        ++walls_on_walls;
      } else if (lf <= free) {
        ++conflicts;
      }
    } else if (lm <= free && lf >= occupied && !occupied_near(moving, m, occupied)) {
      ++conflicts;
    }
  }
  MapMatch out;
  out.T_fixed_moving = T_fixed_moving;
  out.overlap_m2 = static_cast<double>(overlap) * mg.resolution_m() * mg.resolution_m();
  out.conflict = overlap > 0 ? static_cast<double>(conflicts) / static_cast<double>(overlap) : 1.0;
  out.wall_agreement = walls_inside > 0
                           ? static_cast<double>(walls_on_walls) / static_cast<double>(walls_inside)
                           : 0.0;
  out.accepted = out.overlap_m2 >= options.min_overlap_m2 && out.conflict <= options.max_conflict &&
                 out.wall_agreement >= options.min_wall_agreement;
  return out;
}

Result<std::optional<MapMatch>> match_maps(const OccupancyGrid& fixed, const OccupancyGrid& moving,
                                           const MapMatchOptions& options) {
  if (auto problem = validate(options)) return input_error("map match: " + *problem);
  const double r = fixed.geometry().resolution_m();
  if (fixed.geometry().size() == 0 || moving.geometry().size() == 0)
    return std::optional<MapMatch>{};
  if (std::abs(moving.geometry().resolution_m() - r) > 1e-3 * r) {
    return input_error("map match: the maps' resolutions differ (" + std::to_string(r) + " and " +
                       std::to_string(moving.geometry().resolution_m()) + " m)");
  }
  const Views views{log_odds(options.occupied_from), log_odds(options.free_below)};
  const std::vector<Vec2> walls_moving = obstacle_points(moving, views.occupied);
  if (walls_moving.empty() || obstacle_points(fixed, views.occupied).empty())
    return std::optional<MapMatch>{};

  // The search turns the teammate's walls about their centroid, so that a turn step moves no
  // point by more than a search cell.
  Vec2 centroid{0.0, 0.0};
  for (const Vec2 p : walls_moving) centroid = centroid + p;
  centroid = centroid * (1.0 / static_cast<double>(walls_moving.size()));
  std::vector<Vec2> centred;
  centred.reserve(walls_moving.size());
  double reach_m = 0.0;
  for (const Vec2 p : walls_moving) {
    centred.push_back(p - centroid);
    reach_m = std::max(reach_m, std::hypot(p.x - centroid.x, p.y - centroid.y));
  }
  const double coarse_m = std::max(options.search_resolution_m, r);

  const slam::ProbabilityGrid coarse = matching_grid(fixed, coarse_m, views);
  const slam::BranchAndBoundMatcher search(coarse, kSearchDepth);
  const GridGeometry& g = fixed.geometry();
  const Pose2 T_prior{g.origin().x + 0.5 * g.width() * r, g.origin().y + 0.5 * g.height() * r, 0.0};
  const slam::SearchWindow window{.linear_m = 0.5 * std::max(g.width(), g.height()) * r + coarse_m,
                                  .angular_rad = M_PI};
  const std::optional<slam::ScanMatch> found =
      search.match(T_prior, slam::voxel_filter(centred, coarse_m), window,
                   slam::kMinProbability + kMinScoreAboveChance);
  if (!found) return std::optional<MapMatch>{};

  // Refinement on the full-resolution grid, within a search cell and a few turn steps.
  const slam::ProbabilityGrid fine = matching_grid(fixed, r, views);
  slam::RealTimeMatcherOptions refine;
  refine.linear_window_m = coarse_m;
  refine.angular_window_rad = 2.0 * slam::angular_search_step_rad(coarse_m, reach_m);
  refine.translation_delta_cost_weight = 0.0;
  refine.rotation_delta_cost_weight = 0.0;
  const slam::ScanMatch refined = slam::match_real_time(fine, found->T_grid_robot, centred, refine);
  const Pose2 T_fixed_moving = refined.T_grid_robot * Pose2{-centroid.x, -centroid.y, 0.0};
  MapMatch out = judge_map_match(fixed, moving, T_fixed_moving, options);
  out.score = refined.score;
  return std::optional<MapMatch>(out);
}

}  // namespace tessera::team
