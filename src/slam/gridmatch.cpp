#include "tessera/slam/gridmatch.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

#include "tessera/core/assert.hpp"

namespace tessera::slam {
namespace {

[[nodiscard]] bool is_probability(double p) { return p > 0.0 && p < 1.0; }

/// Distance of a position offset from the odometry position, in the ring order of
/// candidate_offsets().
[[nodiscard]] int ring_of(int dx, int dy, bool square) {
  return square ? std::max(std::abs(dx), std::abs(dy)) : std::abs(dx) + std::abs(dy);
}

}  // namespace

std::optional<std::string> validate(const GridMatchOptions& o) {
  if (o.position_radius_steps < 0) {
    return "position_radius_steps must be >= 0, got " + std::to_string(o.position_radius_steps);
  }
  if (!(o.position_step_cells > 0.0) || !std::isfinite(o.position_step_cells)) {
    return "position_step_cells must be > 0, got " + std::to_string(o.position_step_cells);
  }
  if (o.heading_radius_steps < 0) {
    return "heading_radius_steps must be >= 0, got " + std::to_string(o.heading_radius_steps);
  }
  if (!(o.heading_step_rad > 0.0) || !std::isfinite(o.heading_step_rad)) {
    return "heading_step_rad must be > 0, got " + std::to_string(o.heading_step_rad);
  }
  // More than half a turn each way would try some headings twice.
  if (o.heading_radius_steps * o.heading_step_rad > std::numbers::pi) {
    return "heading_radius_steps * heading_step_rad must be <= pi, got " +
           std::to_string(o.heading_radius_steps * o.heading_step_rad);
  }
  if (!is_probability(o.occupied_threshold)) {
    return "occupied_threshold must be in (0, 1), got " + std::to_string(o.occupied_threshold);
  }
  return std::nullopt;
}

std::vector<CandidateOffset> candidate_offsets(const GridMatchOptions& o) {
  TESSERA_ASSERT(!validate(o).has_value());
  const int r = o.position_radius_steps;
  std::vector<CandidateOffset> offsets;
  for (int ring = 0; ring <= r; ++ring) {
    // Reading order: top row (largest dy) first, each row left to right.
    for (int dy = ring; dy >= -ring; --dy) {
      for (int dx = -ring; dx <= ring; ++dx) {
        if (ring_of(dx, dy, o.square_positions) != ring) continue;
        offsets.push_back({dx, dy, 0});
        for (int k = 1; k <= o.heading_radius_steps; ++k) {
          offsets.push_back({dx, dy, -k});  // clockwise first, as the lecture's table lists them
          offsets.push_back({dx, dy, k});
        }
      }
    }
  }
  return offsets;
}

Pose2 candidate_pose(const GridGeometry& map_geometry, const Pose2& T_map_odometry,
                     const CandidateOffset& offset, const GridMatchOptions& o) {
  const double step_m = o.position_step_cells * map_geometry.resolution_m();
  const Vec2 centre =
      o.snap_to_cell_centre
          ? map_geometry.center_of(map_geometry.cell_at_unchecked(T_map_odometry.translation()))
          : T_map_odometry.translation();
  return {centre.x + offset.dx_steps * step_m, centre.y + offset.dy_steps * step_m,
          normalize_angle(T_map_odometry.theta + offset.dheading_steps * o.heading_step_rad)};
}

Similarity similarity(const TernaryGrid& perception, const TernaryGrid& expected) {
  TESSERA_ASSERT(perception.geometry() == expected.geometry());
  Similarity s;
  const std::vector<std::int8_t>& p = perception.values();
  const std::vector<std::int8_t>& e = expected.values();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const int product = p[i] * e[i];  // S(i,j) = m(i,j) p(i,j)
    s.score += product;
    if (product != 0) ++s.overlap_cells;
    if (product > 0) ++s.agree_cells;
  }
  return s;
}

TernaryGrid similarity_cells(const TernaryGrid& perception, const TernaryGrid& expected) {
  TESSERA_ASSERT(perception.geometry() == expected.geometry());
  const GridGeometry& g = perception.geometry();
  TernaryGrid c(g);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      c.set({x, y}, static_cast<std::int8_t>(perception.at({x, y}) * expected.at({x, y})));
    }
  }
  return c;
}

GridMatchResult match(const OccupancyGrid& map, const TernaryGrid& perception,
                      const Pose2& T_map_odometry, const GridMatchOptions& o) {
  TESSERA_ASSERT(!validate(o).has_value());
  GridMatchResult result;
  result.T_map_odometry = T_map_odometry;
  for (const CandidateOffset& offset : candidate_offsets(o)) {
    GridMatchCandidate c;
    c.offset = offset;
    c.T_map_robot = candidate_pose(map.geometry(), T_map_odometry, offset, o);
    const TernaryGrid e =
        expected_map(map, perception.geometry(), c.T_map_robot, o.occupied_threshold);
    c.similarity = similarity(perception, e);
    result.candidates.push_back(c);
  }
  // Line 07: b changes only when a test pose is strictly better, so ties keep the earlier one.
  int runner_up = std::numeric_limits<int>::min();
  for (std::size_t k = 1; k < result.candidates.size(); ++k) {
    const int s = result.candidates[k].similarity.score;
    const int best = result.candidates[result.best].similarity.score;
    if (s > best) {
      runner_up = best;
      result.best = k;
    } else {
      runner_up = std::max(runner_up, s);
    }
  }
  if (result.candidates.size() > 1) {
    result.margin = result.candidates[result.best].similarity.score - runner_up;
  }
  return result;
}

std::optional<std::string> validate(const MapUpdateOptions& o) {
  if (!is_probability(o.p_free)) {
    return "p_free must be in (0, 1), got " + std::to_string(o.p_free);
  }
  if (!is_probability(o.p_occupied)) {
    return "p_occupied must be in (0, 1), got " + std::to_string(o.p_occupied);
  }
  if (!(o.p_free < o.p_occupied)) {
    return "p_free must be < p_occupied, got " + std::to_string(o.p_free) +
           " >= " + std::to_string(o.p_occupied);
  }
  if (auto problem = validate(o.model)) return "model: " + *problem;
  return std::nullopt;
}

MapUpdateStats update_map(OccupancyGrid& map, const TernaryGrid& perception,
                          const Pose2& T_map_robot, const MapUpdateOptions& o,
                          double occupied_threshold) {
  TESSERA_ASSERT(!validate(o).has_value());
  const GridGeometry& map_geometry = map.geometry();
  const GridGeometry& window = perception.geometry();
  MapUpdateStats stats;

  // The map cells the window can reach: the bounding box of its four corners in the map frame.
  const Vec2 lo = window.origin();
  const Vec2 hi{lo.x + window.width() * window.resolution_m(),
                lo.y + window.height() * window.resolution_m()};
  const Vec2 corners[4] = {T_map_robot * lo, T_map_robot * Vec2{hi.x, lo.y}, T_map_robot * hi,
                           T_map_robot * Vec2{lo.x, hi.y}};
  Cell min_cell = map_geometry.cell_at_unchecked(corners[0]);
  Cell max_cell = min_cell;
  for (const Vec2& p : corners) {
    const Cell c = map_geometry.cell_at_unchecked(p);
    min_cell = {std::min(min_cell.x, c.x), std::min(min_cell.y, c.y)};
    max_cell = {std::max(max_cell.x, c.x), std::max(max_cell.y, c.y)};
  }
  min_cell = {std::max(min_cell.x, 0), std::max(min_cell.y, 0)};
  max_cell = {std::min(max_cell.x, map_geometry.width() - 1),
              std::min(max_cell.y, map_geometry.height() - 1)};

  const Pose2 T_robot_map = T_map_robot.inverse();
  const float hit = log_odds(o.model.p_hit);
  const float miss = log_odds(o.model.p_miss);
  const float clamp_min = log_odds(o.model.p_clamp_min);
  const float clamp_max = log_odds(o.model.p_clamp_max);
  for (int y = min_cell.y; y <= max_cell.y; ++y) {
    for (int x = min_cell.x; x <= max_cell.x; ++x) {
      const Cell c{x, y};
      const std::optional<Cell> w = window.cell_at(T_robot_map * map_geometry.center_of(c));
      if (!w) continue;
      const std::int8_t seen = perception.at(*w);
      if (seen == kTernaryUnknown) continue;
      const std::int8_t before = ternary_value(map, c, occupied_threshold);
      if (o.rule == MapUpdateRule::kAddUnknown && before != kTernaryUnknown) continue;
      if (o.rule != MapUpdateRule::kLogOdds) {
        map.set_probability(c, seen == kTernaryOccupied ? o.p_occupied : o.p_free);
      } else {
        map.add_log_odds(c, seen == kTernaryOccupied ? hit : miss, clamp_min, clamp_max);
      }
      ++stats.written_cells;
      if (before == kTernaryUnknown) {
        ++stats.newly_known_cells;
      } else if (ternary_value(map, c, occupied_threshold) != before) {
        ++stats.flipped_cells;
      }
    }
  }
  return stats;
}

GridMatchStep match_and_update(OccupancyGrid& map, const TernaryGrid& perception,
                               const Pose2& T_map_odometry, const GridMatchOptions& match_options,
                               const MapUpdateOptions& update_options) {
  GridMatchStep step;
  step.match = match(map, perception, T_map_odometry, match_options);
  step.update = update_map(map, perception, step.match.T_map_robot(), update_options,
                           match_options.occupied_threshold);
  return step;
}

}  // namespace tessera::slam
