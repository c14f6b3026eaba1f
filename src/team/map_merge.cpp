// The team's merged map (team/map_merge.hpp).
#include "tessera/team/map_merge.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "tessera/io/tf_tree.hpp"

namespace tessera::team {
namespace {

// The corners of a robot map in the team frame, for the merged grid's extent.
void extend(const OccupancyGridMessage& m, const Pose2& T_team_map, double& min_x, double& min_y,
            double& max_x, double& max_y) {
  const Pose2 T_map_origin = planar_pose(m.origin);
  const double w = m.width * static_cast<double>(m.resolution_m);
  const double h = m.height * static_cast<double>(m.resolution_m);
  for (const Vec2 corner : {Vec2{0, 0}, Vec2{w, 0}, Vec2{0, h}, Vec2{w, h}}) {
    const Vec2 p = T_team_map * (T_map_origin * corner);
    min_x = std::min(min_x, p.x);
    min_y = std::min(min_y, p.y);
    max_x = std::max(max_x, p.x);
    max_y = std::max(max_y, p.y);
  }
}

// A robot map's grid seen from the team frame: T_origin_team takes a team point into it.
struct View {
  const OccupancyGridMessage* map;
  Pose2 T_origin_team;
  double cos_theta, sin_theta;  // of T_origin_team, once per map rather than per point
};

// 0 and 100 percent are a robot's certainty, kept finite: 0.5 % and 99.5 %.
float value_log_odds(std::int8_t value) {
  return log_odds(std::clamp(value / 100.0, 0.005, 0.995));
}

// When every robot's cells are cells of `g` (same size, no rotation, origins a whole number of
// cells apart), as for a robot planning on the union of its team's maps: each robot cell is added
// to its cell of `g` directly, O(robot cells), with the rule of merged(). nullopt otherwise.
std::optional<OccupancyGrid> merged_cell_for_cell(const GridGeometry& g,
                                                  const std::vector<View>& views,
                                                  float kept_occupied) {
  struct Offset {
    long x, y;
  };
  std::vector<Offset> offsets;
  const double r = g.resolution_m();
  for (const View& v : views) {
    // The robot grid's origin in the team frame, in cells of g.
    const Pose2 T_team_origin = v.T_origin_team.inverse();
    const double ox = (T_team_origin.x - g.origin().x) / r;
    const double oy = (T_team_origin.y - g.origin().y) / r;
    const bool aligned = std::abs(v.map->resolution_m - r) <= 1e-6 * r &&
                         std::abs(v.sin_theta) <= 1e-9 && v.cos_theta > 0.0 &&
                         std::abs(ox - std::round(ox)) <= 1e-4 &&
                         std::abs(oy - std::round(oy)) <= 1e-4;
    if (!aligned) return std::nullopt;
    offsets.push_back({std::lround(ox), std::lround(oy)});
  }
  std::vector<float> sum(g.size(), 0.0f);
  std::vector<float> most(g.size(), -std::numeric_limits<float>::max());
  std::vector<std::uint8_t> known(g.size(), 0);
  for (std::size_t k = 0; k < views.size(); ++k) {
    const OccupancyGridMessage& m = *views[k].map;
    for (long y = 0; y < static_cast<long>(m.height); ++y) {
      const long ty = y + offsets[k].y;
      if (ty < 0 || ty >= g.height()) continue;
      for (long x = 0; x < static_cast<long>(m.width); ++x) {
        const long tx = x + offsets[k].x;
        const std::int8_t value =
            m.data[static_cast<std::size_t>(y) * m.width + static_cast<std::size_t>(x)];
        if (tx < 0 || tx >= g.width() || value < 0 || value > 100) continue;
        const std::size_t i = static_cast<std::size_t>(ty) * static_cast<std::size_t>(g.width()) +
                              static_cast<std::size_t>(tx);
        const float l = value_log_odds(value);
        sum[i] += l;
        most[i] = std::max(most[i], l);
        known[i] = 1;
      }
    }
  }
  OccupancyGrid out(g);
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (known[i] == 0) continue;
    const float l = most[i] >= kept_occupied ? std::max(sum[i], most[i]) : sum[i];
    out.add_log_odds(g.cell_of(i), l, -std::numeric_limits<float>::max(),
                     std::numeric_limits<float>::max());
  }
  return out;
}

}  // namespace

MapMerger::MapMerger(double resolution_m) : resolution_m_(resolution_m) {}

Status MapMerger::update(const std::string& robot, const OccupancyGridMessage& map,
                         const Pose2& T_team_map) {
  const double r = map.resolution_m;
  if (!(std::abs(r - resolution_m_) <= 1e-3 * resolution_m_)) {
    return input_error("map of " + robot + ": resolution " + std::to_string(r) +
                       " m, the team's is " + std::to_string(resolution_m_) + " m");
  }
  if (static_cast<std::uint64_t>(map.width) * map.height != map.data.size()) {
    return input_error("map of " + robot + ": " + std::to_string(map.width) + " x " +
                       std::to_string(map.height) + " cells but " +
                       std::to_string(map.data.size()) + " values");
  }
  for (const double v : {map.origin.x_m, map.origin.y_m, map.origin.qz, map.origin.qw, T_team_map.x,
                         T_team_map.y, T_team_map.theta}) {
    if (!std::isfinite(v)) return input_error("map of " + robot + ": origin is not finite");
  }
  maps_[robot] = {map, T_team_map};
  return Ok{};
}

GridGeometry MapMerger::extent(double margin_m) const {
  double min_x = std::numeric_limits<double>::infinity(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (const auto& [robot, m] : maps_) {
    if (m.map.width > 0 && m.map.height > 0) {
      extend(m.map, m.T_team_map, min_x, min_y, max_x, max_y);
    }
  }
  if (!(min_x < max_x && min_y < max_y)) return GridGeometry{};
  min_x -= margin_m;
  min_y -= margin_m;
  max_x += margin_m;
  max_y += margin_m;
  // A map's extent is a whole number of cells up to rounding (resolutions travel as float32).
  const auto cells = [&](double extent_m) {
    return std::max(1, static_cast<int>(std::ceil(extent_m / resolution_m_ - 1e-4)));
  };
  return GridGeometry({min_x, min_y}, resolution_m_, cells(max_x - min_x), cells(max_y - min_y));
}

OccupancyGrid MapMerger::merged() const {
  const GridGeometry g = extent();
  if (g.size() == 0) return OccupancyGrid{};
  return merged(g);
}

OccupancyGrid MapMerger::merged(const GridGeometry& g) const {
  std::vector<View> views;
  for (const auto& [robot, m] : maps_) {
    const Pose2 T = (m.T_team_map * planar_pose(m.map.origin)).inverse();
    views.push_back({&m.map, T, std::cos(T.theta), std::sin(T.theta)});
  }
  // The robots' summed log-odds at a team point (the most occupied one's where a robot holds it
  // occupied); nullopt where none knows it.
  const float kept_occupied = log_odds(kKeptOccupied);
  const auto at = [&](Vec2 p_team) -> std::optional<float> {
    std::optional<float> sum;
    float most = -std::numeric_limits<float>::max();
    for (const View& v : views) {
      const Vec2 p{v.T_origin_team.x + v.cos_theta * p_team.x - v.sin_theta * p_team.y,
                   v.T_origin_team.y + v.sin_theta * p_team.x + v.cos_theta * p_team.y};
      const double r = v.map->resolution_m;
      const long cx = std::lround(std::floor(p.x / r));
      const long cy = std::lround(std::floor(p.y / r));
      if (cx < 0 || cy < 0 || cx >= v.map->width || cy >= v.map->height) continue;
      const std::int8_t value =
          v.map->data[static_cast<std::size_t>(cy) * v.map->width + static_cast<std::size_t>(cx)];
      if (value < 0 || value > 100) continue;  // unknown (-1), or not a probability
      const float l = value_log_odds(value);
      sum = sum.value_or(0.0f) + l;
      most = std::max(most, l);
    }
    if (sum && most >= kept_occupied) return std::max(*sum, most);
    return sum;
  };
  if (auto exact = merged_cell_for_cell(g, views, kept_occupied)) return std::move(*exact);
  // Each cell takes the most occupied of n x n points spread evenly over it, n twice the ratio of
  // the cell sizes (at least 2): an obstacle in any part of the cell keeps it occupied (as
  // World::resampled keeps thin walls), and no point lies on the border of a robot's cell when
  // the robots' grids are aligned with this one or half a cell off it (a tie between two cells
  // that rounding would break).
  const int n = 2 * std::max(1, static_cast<int>(std::lround(g.resolution_m() / resolution_m_)));
  OccupancyGrid out(g);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      std::optional<float> cell;
      for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
          const Vec2 p{g.origin().x + (x + (i + 0.5) / n) * g.resolution_m(),
                       g.origin().y + (y + (j + 0.5) / n) * g.resolution_m()};
          if (const std::optional<float> v = at(p)) cell = std::max(cell.value_or(*v), *v);
        }
      }
      if (cell) {
        out.add_log_odds({x, y}, *cell, -std::numeric_limits<float>::max(),
                         std::numeric_limits<float>::max());
      }
    }
  }
  return out;
}

}  // namespace tessera::team
