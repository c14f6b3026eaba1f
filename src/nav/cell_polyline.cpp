#include "tessera/nav/cell_polyline.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tessera/core/assert.hpp"
#include "tessera/grid/hex_grid.hpp"

namespace tessera {
namespace {

// True when offset d from a cell centre lies in its flat-topped hexagon: the projection onto each
// of the three neighbour axes of Table 4.3 (0, 60 and 120 degrees from north) is within d/2.
bool inside_hexagon(Vec2 d, const CellPolylineOptions& o) {
  const double h = o.cell_radius_m / 2.0 + o.border_tolerance_m;
  return std::abs(d.y) <= h && std::abs(kHexColumnStep * d.x + 0.5 * d.y) <= h &&
         std::abs(kHexColumnStep * d.x - 0.5 * d.y) <= h;
}

// True when every sample of segment a-b is inside the cells run[first..last] (see
// CellPolylineOptions::border_tolerance_m).
bool in_corridor(const CellGraph& graph, const std::vector<std::size_t>& run, std::size_t first,
                 std::size_t last, Vec2 a, Vec2 b, const CellPolylineOptions& o) {
  const double len = (b - a).norm();
  const int samples = std::max(1, static_cast<int>(std::ceil(len / o.sample_step_m)));
  for (int i = 0; i <= samples; ++i) {
    const Vec2 p = a + (b - a) * (static_cast<double>(i) / samples);
    double in_run = std::numeric_limits<double>::infinity();
    bool in_hexagon = false;
    for (std::size_t k = first; k <= last; ++k) {
      const Vec2 d = p - graph.centres_m[run[k]];
      in_run = std::min(in_run, d.norm());
      in_hexagon = in_hexagon || inside_hexagon(d, o);
    }
    if (!in_hexagon) return false;
    const double any = (p - graph.centres_m[graph.nearest(p)]).norm();
    if (in_run > any + o.border_tolerance_m) return false;
  }
  return true;
}

}  // namespace

std::optional<std::string> validate(const CellPolylineOptions& o) {
  if (!(std::isfinite(o.cell_radius_m) && o.cell_radius_m > 0.0)) {
    return "cell_radius_m must be > 0, got " + std::to_string(o.cell_radius_m);
  }
  if (!(std::isfinite(o.sample_step_m) && o.sample_step_m > 0.0)) {
    return "sample_step_m must be > 0, got " + std::to_string(o.sample_step_m);
  }
  if (!(std::isfinite(o.border_tolerance_m) && o.border_tolerance_m >= 0.0)) {
    return "border_tolerance_m must be >= 0, got " + std::to_string(o.border_tolerance_m);
  }
  return std::nullopt;
}

std::vector<Vec2> cell_path_polyline(const CellGraph& graph,
                                     const std::vector<std::size_t>& cell_path, Vec2 start_m,
                                     Vec2 goal_m, const CellPolylineOptions& options) {
  TESSERA_ASSERT(!cell_path.empty() && !validate(options));
  for (const std::size_t c : cell_path) TESSERA_ASSERT(c < graph.size());
  // Vertex k lies in cell_path[k]: the start in the first cell, the centres of the cells between,
  // the goal point in the last.
  std::vector<Vec2> vertex;
  vertex.reserve(cell_path.size() + 1);
  vertex.push_back(start_m);
  for (std::size_t k = 1; k + 1 < cell_path.size(); ++k) {
    vertex.push_back(graph.centres_m[cell_path[k]]);
  }
  std::vector<std::size_t> vertex_cell;  // index into cell_path of each vertex
  for (std::size_t k = 0; k + 1 < cell_path.size(); ++k) vertex_cell.push_back(k);
  vertex.push_back(goal_m);
  vertex_cell.push_back(cell_path.size() - 1);

  std::vector<Vec2> out{vertex.front()};
  std::size_t i = 0;
  while (i + 1 < vertex.size()) {
    // The next vertex is always allowed (consecutive cells are adjacent); extend while the line
    // of sight holds. Stopping at the first blocked vertex keeps the cost near linear in the path.
    std::size_t j = i + 1;
    for (std::size_t k = i + 2; k < vertex.size(); ++k) {
      if (!in_corridor(graph, cell_path, vertex_cell[i], vertex_cell[k], vertex[i], vertex[k],
                       options)) {
        break;
      }
      j = k;
    }
    out.push_back(vertex[j]);
    i = j;
  }
  return out;
}

double polyline_length_m(const std::vector<Vec2>& points_m) {
  double len = 0.0;
  for (std::size_t i = 1; i < points_m.size(); ++i) len += (points_m[i] - points_m[i - 1]).norm();
  return len;
}

Vec2 polyline_point_at(const std::vector<Vec2>& points_m, double s_m) {
  TESSERA_ASSERT(!points_m.empty());
  double s = 0.0;
  for (std::size_t i = 1; i < points_m.size(); ++i) {
    const double len = (points_m[i] - points_m[i - 1]).norm();
    if (s + len >= s_m && len > 0.0) {
      const double t = std::clamp((s_m - s) / len, 0.0, 1.0);
      return points_m[i - 1] + (points_m[i] - points_m[i - 1]) * t;
    }
    s += len;
  }
  return s_m <= 0.0 ? points_m.front() : points_m.back();
}

double distance_to_polyline(Vec2 p, const std::vector<Vec2>& points_m) {
  double best =
      points_m.empty() ? std::numeric_limits<double>::infinity() : (p - points_m[0]).norm();
  for (std::size_t i = 1; i < points_m.size(); ++i) {
    best = std::min(best, distance_to_segment(p, points_m[i - 1], points_m[i]));
  }
  return best;
}

Vec2 nearest_on_polyline(Vec2 p, const std::vector<Vec2>& points_m) {
  Vec2 best = points_m.front();
  for (std::size_t i = 1; i < points_m.size(); ++i) {
    const Vec2 q = nearest_on_segment(p, points_m[i - 1], points_m[i]);
    if ((q - p).norm() < (best - p).norm()) best = q;
  }
  return best;
}

}  // namespace tessera
