// The team's merged map (team/map_merge.hpp).
#include "tessera/team/map_merge.hpp"

#include <algorithm>
#include <array>
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

// 0 and 100 percent are a robot's certainty, kept finite: 0.5 % and 99.5 %. Tabulated: the
// merge looks a value up for every sample of every cell. Precondition: value in [0, 100].
float value_log_odds(std::int8_t value) {
  static const std::array<float, 101> table = [] {
    std::array<float, 101> t{};
    for (std::size_t v = 0; v < t.size(); ++v) {
      t[v] = log_odds(std::clamp(static_cast<double>(v) / 100.0, 0.005, 0.995));
    }
    return t;
  }();
  return table[static_cast<std::size_t>(value)];
}

// The robots' values per cell of the merged grid: their log-odds summed, the most occupied one
// kept where a robot holds the cell occupied (map_merge.hpp).
class Accumulator {
 public:
  explicit Accumulator(const GridGeometry& g)
      : g_(g),
        sum_(g.size(), 0.0f),
        most_(g.size(), -std::numeric_limits<float>::max()),
        known_(g.size(), 0) {}
  void add(std::size_t i, float l) {
    sum_[i] += l;
    most_[i] = std::max(most_[i], l);
    known_[i] = 1;
  }
  [[nodiscard]] OccupancyGrid grid(float kept_occupied) const {
    OccupancyGrid out(g_);
    for (std::size_t i = 0; i < g_.size(); ++i) {
      if (known_[i] == 0) continue;
      const float l = most_[i] >= kept_occupied ? std::max(sum_[i], most_[i]) : sum_[i];
      out.add_log_odds(g_.cell_of(i), l, -std::numeric_limits<float>::max(),
                       std::numeric_limits<float>::max());
    }
    return out;
  }

 private:
  GridGeometry g_;
  std::vector<float> sum_, most_;
  std::vector<std::uint8_t> known_;
};

// A robot's value at a point of its grid's origin frame; nullopt where unknown or outside.
std::optional<float> value_at(const OccupancyGridMessage& m, double inv_r, double x, double y) {
  const auto cx = static_cast<long>(std::floor(x * inv_r));
  const auto cy = static_cast<long>(std::floor(y * inv_r));
  if (cx < 0 || cy < 0 || cx >= m.width || cy >= m.height) return std::nullopt;
  const std::int8_t value =
      m.data[static_cast<std::size_t>(cy) * m.width + static_cast<std::size_t>(cx)];
  if (value < 0 || value > 100) return std::nullopt;  // unknown (-1), or not a probability
  return value_log_odds(value);
}

// When a robot's cells are cells of `g` (same size, no rotation, origins a whole number of cells
// apart), as for a robot planning on the union of its team's maps with known starts: the offset
// of its grid in cells of g.
std::optional<std::array<long, 2>> cell_offset(const GridGeometry& g, const View& v) {
  const double r = g.resolution_m();
  const Pose2 T_team_origin = v.T_origin_team.inverse();
  const double ox = (T_team_origin.x - g.origin().x) / r;
  const double oy = (T_team_origin.y - g.origin().y) / r;
  const bool aligned = std::abs(v.map->resolution_m - r) <= 1e-6 * r &&
                       std::abs(v.sin_theta) <= 1e-9 && v.cos_theta > 0.0 &&
                       std::abs(ox - std::round(ox)) <= 1e-4 &&
                       std::abs(oy - std::round(oy)) <= 1e-4;
  if (!aligned) return std::nullopt;
  return std::array<long, 2>{std::lround(ox), std::lround(oy)};
}

// An aligned robot grid: each of its cells is added to its cell of g, O(robot cells).
void add_cell_for_cell(const GridGeometry& g, const OccupancyGridMessage& m,
                       std::array<long, 2> offset, Accumulator& acc) {
  for (long y = 0; y < static_cast<long>(m.height); ++y) {
    const long ty = y + offset[1];
    if (ty < 0 || ty >= g.height()) continue;
    for (long x = 0; x < static_cast<long>(m.width); ++x) {
      const long tx = x + offset[0];
      const std::int8_t value =
          m.data[static_cast<std::size_t>(y) * m.width + static_cast<std::size_t>(x)];
      if (tx < 0 || tx >= g.width() || value < 0 || value > 100) continue;
      acc.add(static_cast<std::size_t>(ty) * static_cast<std::size_t>(g.width()) +
                  static_cast<std::size_t>(tx),
              value_log_odds(value));
    }
  }
}

// Any other robot grid: its value at a cell of g is the most occupied of its values at n x n
// points spread evenly over the cell, so an obstacle in any part of the cell keeps it occupied
// (as World::resampled keeps thin walls), and no point lies on the border of a robot's cell when
// its grid is aligned with g or half a cell off it (a tie that rounding would break). Only the
// cells of g under the robot's grid are visited, a row of points at a time: O(those cells x n^2).
void add_sampled(const GridGeometry& g, const View& v, int n, Accumulator& acc) {
  const OccupancyGridMessage& m = *v.map;
  const double r = g.resolution_m();
  const double inv_r = 1.0 / m.resolution_m;
  // The robot grid's bounding box in the team frame.
  const Pose2 T_team_origin = v.T_origin_team.inverse();
  const double w = m.width * static_cast<double>(m.resolution_m);
  const double h = m.height * static_cast<double>(m.resolution_m);
  double bx0 = std::numeric_limits<double>::infinity(), by0 = bx0, bx1 = -bx0, by1 = -bx0;
  for (const Vec2 corner : {Vec2{0, 0}, Vec2{w, 0}, Vec2{0, h}, Vec2{w, h}}) {
    const Vec2 p = T_team_origin * corner;
    bx0 = std::min(bx0, p.x);
    by0 = std::min(by0, p.y);
    bx1 = std::max(bx1, p.x);
    by1 = std::max(by1, p.y);
  }
  const int x0 = std::max(0, static_cast<int>(std::floor((bx0 - g.origin().x) / r)) - 1);
  const int y0 = std::max(0, static_cast<int>(std::floor((by0 - g.origin().y) / r)) - 1);
  const int x1 =
      std::min(g.width() - 1, static_cast<int>(std::floor((bx1 - g.origin().x) / r)) + 1);
  const int y1 =
      std::min(g.height() - 1, static_cast<int>(std::floor((by1 - g.origin().y) / r)) + 1);
  if (x0 > x1 || y0 > y1) return;
  const double c = v.cos_theta, s = v.sin_theta;
  const Vec2 step{c * r, s * r};  // one cell of g along x, in the robot grid's frame
  std::vector<float> best(static_cast<std::size_t>(x1 - x0 + 1));
  std::vector<std::uint8_t> seen(best.size());
  for (int y = y0; y <= y1; ++y) {
    std::fill(seen.begin(), seen.end(), 0);
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        const Vec2 p_team{g.origin().x + (x0 + (i + 0.5) / n) * r,
                          g.origin().y + (y + (j + 0.5) / n) * r};
        Vec2 p{v.T_origin_team.x + c * p_team.x - s * p_team.y,
               v.T_origin_team.y + s * p_team.x + c * p_team.y};
        for (std::size_t k = 0; k < best.size(); ++k, p = p + step) {
          const std::optional<float> l = value_at(m, inv_r, p.x, p.y);
          if (!l) continue;
          best[k] = seen[k] ? std::max(best[k], *l) : *l;
          seen[k] = 1;
        }
      }
    }
    for (std::size_t k = 0; k < best.size(); ++k) {
      if (seen[k]) {
        acc.add(static_cast<std::size_t>(y) * static_cast<std::size_t>(g.width()) +
                    static_cast<std::size_t>(x0) + k,
                best[k]);
      }
    }
  }
}

}  // namespace

MapMerger::MapMerger(double resolution_m) : resolution_m_(resolution_m) {}

Status MapMerger::check(const std::string& robot, const OccupancyGridMessage& map,
                        const Pose2& T_team_map) const {
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
  return Ok{};
}

Status MapMerger::update(const std::string& robot, const OccupancyGridMessage& map,
                         const Pose2& T_team_map) {
  if (Status s = check(robot, map, T_team_map); !s.ok()) return s;
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
  const int n = 2 * std::max(1, static_cast<int>(std::lround(g.resolution_m() / resolution_m_)));
  Accumulator acc(g);
  for (const auto& [robot, m] : maps_) {
    const Pose2 T = (m.T_team_map * planar_pose(m.map.origin)).inverse();
    const View v{&m.map, T, std::cos(T.theta), std::sin(T.theta)};
    if (const auto offset = cell_offset(g, v)) {
      add_cell_for_cell(g, m.map, *offset, acc);
    } else {
      add_sampled(g, v, n, acc);
    }
  }
  return acc.grid(log_odds(kKeptOccupied));
}

}  // namespace tessera::team
