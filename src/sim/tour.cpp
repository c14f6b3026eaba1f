#include "tessera/sim/tour.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"
#include "tessera/nav/route_planner.hpp"

namespace tessera {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kSqrt2 = std::numbers::sqrt2;
/// "Infinite" squared distance of the distance transform: finite, so that differences of two of
/// them stay finite (Felzenszwalb & Huttenlocher's envelope subtracts them).
constexpr double kFarCells2 = 1e20;
/// Arcs of a smaller radius are not worth driving (the turn-rate limit makes them a crawl): the
/// corner becomes a turn in place.
constexpr double kMinArcRadiusM = 0.05;
/// Arcs are checked chord by chord; chords are short enough that an arc bulges beyond its chord by
/// at most this much (sagitta c^2 / 8R).
constexpr double kArcSagittaM = 1e-6;
/// Headings and lengths below these are no turn and no segment.
constexpr double kTinyAngleRad = 1e-9;
constexpr double kTinyLengthM = 1e-9;

std::string metres(double v) {
  std::ostringstream out;
  out.precision(3);
  out << v;
  return out.str();
}

std::string point_text(Vec2 p) { return "(" + metres(p.x) + ", " + metres(p.y) + ") m"; }

/// One row of Felzenszwalb & Huttenlocher's squared distance transform (their DT(f), Algorithm 1):
/// d[q] = min_p (q - p)^2 + f[p], the lower envelope of parabolas rooted at (p, f[p]).
/// v and z are workspaces of size n and n + 1.
void distance_transform_1d(const double* f, int n, double* d, std::vector<int>& v,
                           std::vector<double>& z) {
  int k = 0;
  v[0] = 0;
  z[0] = -std::numeric_limits<double>::infinity();
  z[1] = std::numeric_limits<double>::infinity();
  const auto intersection = [&](int q, int p) {
    const double qd = q, pd = p;
    return ((f[q] + qd * qd) - (f[p] + pd * pd)) / (2.0 * qd - 2.0 * pd);
  };
  for (int q = 1; q < n; ++q) {
    double s = intersection(q, v[static_cast<std::size_t>(k)]);
    while (s <= z[static_cast<std::size_t>(k)]) {
      --k;
      s = intersection(q, v[static_cast<std::size_t>(k)]);
    }
    ++k;
    v[static_cast<std::size_t>(k)] = q;
    z[static_cast<std::size_t>(k)] = s;
    z[static_cast<std::size_t>(k) + 1] = std::numeric_limits<double>::infinity();
  }
  k = 0;
  for (int q = 0; q < n; ++q) {
    while (z[static_cast<std::size_t>(k) + 1] < q) ++k;
    const int p = v[static_cast<std::size_t>(k)];
    const double dq = q - p;
    d[q] = dq * dq + f[p];
  }
}

/// Squared distance, in cells, from each cell centre of the geometry to the nearest solid cell
/// centre, the grid's surroundings counting as solid (a one-cell solid frame around it). Exact
/// Euclidean distance transform, separable (Felzenszwalb & Huttenlocher 2012, section 2.1): first
/// along columns, then along rows. Cost: O(cells).
std::vector<double> squared_distance_to_solid_cells(const World& world) {
  const GridGeometry& g = world.geometry();
  const int w = g.width() + 2, h = g.height() + 2;  // padded by the solid frame
  const auto padded = [w](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(w) + static_cast<std::size_t>(x);
  };
  std::vector<double> grid(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      grid[padded(x, y)] = world.solid({x - 1, y - 1}) ? 0.0 : kFarCells2;
    }
  }
  const int n = std::max(w, h);
  std::vector<double> f(static_cast<std::size_t>(n)), d(static_cast<std::size_t>(n));
  std::vector<int> v(static_cast<std::size_t>(n));
  std::vector<double> z(static_cast<std::size_t>(n) + 1);
  for (int x = 0; x < w; ++x) {
    for (int y = 0; y < h; ++y) f[static_cast<std::size_t>(y)] = grid[padded(x, y)];
    distance_transform_1d(f.data(), h, d.data(), v, z);
    for (int y = 0; y < h; ++y) grid[padded(x, y)] = d[static_cast<std::size_t>(y)];
  }
  for (int y = 0; y < h; ++y) {
    distance_transform_1d(&grid[padded(0, y)], w, d.data(), v, z);
    std::copy(d.begin(), d.begin() + w, grid.begin() + static_cast<std::ptrdiff_t>(padded(0, y)));
  }
  std::vector<double> out(g.size());
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) out[g.index_of({x, y})] = grid[padded(x + 1, y + 1)];
  }
  return out;
}

/// Cells 4-connected to `start` through cells with mask 1 (1 = reached). Cost: O(cells).
std::vector<std::uint8_t> component_of(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                                       Cell start) {
  std::vector<std::uint8_t> reached(g.size(), 0);
  if (!g.contains(start) || mask[g.index_of(start)] == 0) return reached;
  std::vector<Cell> queue{start};
  reached[g.index_of(start)] = 1;
  for (std::size_t head = 0; head < queue.size(); ++head) {
    for (const Cell d : kNeighbors4) {
      const Cell n = queue[head] + d;
      if (!g.contains(n)) continue;
      const std::size_t i = g.index_of(n);
      if (mask[i] == 0 || reached[i] != 0) continue;
      reached[i] = 1;
      queue.push_back(n);
    }
  }
  return reached;
}

/// Step 2's lattice: blocks of `block` cells a side, and in each the waypoint (the reachable cell
/// nearest the block's centre; ties: first in row-major order).
struct WaypointLattice {
  int block = 1;
  int blocks_x = 0;
  int blocks_y = 0;
  std::vector<Cell> waypoints;
  /// waypoint_of_block[b]: the waypoint's index in `waypoints`, -1 for a block without one.
  std::vector<std::int64_t> waypoint_of_block;

  [[nodiscard]] std::size_t block_index(Cell c) const {
    return static_cast<std::size_t>(c.y / block) * static_cast<std::size_t>(blocks_x) +
           static_cast<std::size_t>(c.x / block);
  }
};

WaypointLattice lattice_waypoints(const GridGeometry& g, const std::vector<std::uint8_t>& reachable,
                                  double spacing_m) {
  WaypointLattice l;
  l.block = std::max(1, static_cast<int>(std::lround(spacing_m / g.resolution_m())));
  const int block = l.block;
  l.blocks_x = (g.width() + block - 1) / block;
  l.blocks_y = (g.height() + block - 1) / block;
  const std::size_t block_count =
      static_cast<std::size_t>(l.blocks_x) * static_cast<std::size_t>(l.blocks_y);
  std::vector<std::int64_t> best_cell(block_count, -1);
  std::vector<double> best_d2(block_count, std::numeric_limits<double>::infinity());
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (reachable[i] == 0) continue;
    const Cell c = g.cell_of(i);
    const double cx = (c.x / block) * block + 0.5 * block - 0.5;  // block centre, in cells
    const double cy = (c.y / block) * block + 0.5 * block - 0.5;
    const double d2 = (c.x - cx) * (c.x - cx) + (c.y - cy) * (c.y - cy);
    const std::size_t b = l.block_index(c);
    if (d2 < best_d2[b]) {
      best_d2[b] = d2;
      best_cell[b] = static_cast<std::int64_t>(i);
    }
  }
  l.waypoint_of_block.assign(block_count, -1);
  for (std::size_t b = 0; b < block_count; ++b) {
    if (best_cell[b] < 0) continue;
    l.waypoint_of_block[b] = static_cast<std::int64_t>(l.waypoints.size());
    l.waypoints.push_back(g.cell_of(static_cast<std::size_t>(best_cell[b])));
  }
  return l;
}

double heading_of(Vec2 d) { return std::atan2(d.y, d.x); }

/// True when the arc piece stays in mask cells: checked along chords short enough that the arc
/// leaves its chord by at most kArcSagittaM.
bool arc_in_mask(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                 const RoutePiece& arc) {
  const double radius = 1.0 / std::abs(arc.curvature_1_per_m);
  const double chord = std::sqrt(8.0 * radius * kArcSagittaM);
  const int n = std::max(1, static_cast<int>(std::ceil(arc.length_m / chord)));
  Vec2 prev = arc.start.translation();
  for (int k = 1; k <= n; ++k) {
    const Vec2 next = arc.pose_at(arc.length_m * k / n).translation();
    if (!segment_in_mask(g, mask, prev, next)) return false;
    prev = next;
  }
  return true;
}

/// Lines, arcs and turns in place along the polyline, from `start` (whose heading may differ from
/// the first segment's: the route begins with a turn in place). Each corner gets the largest arc up
/// to max_radius_m that is tangent to both segments, uses at most half of each, and stays in the
/// mask; otherwise a turn in place.
std::vector<RoutePiece> smooth(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                               const std::vector<Vec2>& polyline, double start_heading_rad,
                               double max_radius_m) {
  std::vector<RoutePiece> pieces;
  const std::size_t m = polyline.size();
  if (m < 2) return pieces;
  std::vector<Vec2> dir(m - 1);
  std::vector<double> len(m - 1);
  for (std::size_t k = 0; k + 1 < m; ++k) {
    const Vec2 d = polyline[k + 1] - polyline[k];
    len[k] = d.norm();
    dir[k] = d * (1.0 / len[k]);
  }
  const auto turn_piece = [](Vec2 at, double heading, double turn) {
    RoutePiece p;
    p.kind = RoutePiece::Kind::kTurn;
    p.start = Pose2{at.x, at.y, normalize_angle(heading)};
    p.turn_rad = turn;
    return p;
  };

  // At each interior vertex k: the tangent distance d[k] of its arc (0: a turn in place).
  std::vector<double> tangent(m, 0.0);
  std::vector<std::optional<RoutePiece>> corner(m);
  for (std::size_t k = 1; k + 1 < m; ++k) {
    const double h_in = heading_of(dir[k - 1]);
    const double turn = normalize_angle(heading_of(dir[k]) - h_in);
    if (std::abs(turn) < kTinyAngleRad) continue;
    const double half_tan = std::tan(0.5 * std::abs(turn));
    double radius = std::min(max_radius_m, 0.5 * std::min(len[k - 1], len[k]) / half_tan);
    bool placed = false;
    while (radius >= kMinArcRadiusM) {
      const double d = radius * half_tan;
      RoutePiece arc;
      arc.kind = RoutePiece::Kind::kArc;
      const Vec2 from = polyline[k] - dir[k - 1] * d;
      arc.start = Pose2{from.x, from.y, normalize_angle(h_in)};
      arc.curvature_1_per_m = (turn > 0.0 ? 1.0 : -1.0) / radius;
      arc.length_m = radius * std::abs(turn);
      if (arc_in_mask(g, mask, arc)) {
        tangent[k] = d;
        corner[k] = arc;
        placed = true;
        break;
      }
      radius *= 0.5;
    }
    if (!placed) corner[k] = turn_piece(polyline[k], h_in, turn);
  }

  const double first_turn = normalize_angle(heading_of(dir[0]) - start_heading_rad);
  if (std::abs(first_turn) >= kTinyAngleRad) {
    pieces.push_back(turn_piece(polyline[0], start_heading_rad, first_turn));
  }
  for (std::size_t k = 0; k + 1 < m; ++k) {
    if (k > 0 && corner[k].has_value()) pieces.push_back(*corner[k]);
    const double line_m = len[k] - tangent[k] - tangent[k + 1];
    if (line_m > kTinyLengthM) {
      RoutePiece line;
      line.kind = RoutePiece::Kind::kLine;
      const Vec2 from = polyline[k] + dir[k] * tangent[k];
      line.start = Pose2{from.x, from.y, normalize_angle(heading_of(dir[k]))};
      line.length_m = line_m;
      pieces.push_back(line);
    }
  }
  return pieces;
}

}  // namespace

std::optional<std::string> validate(const TourOptions& o) {
  if (!(o.clearance_m >= 0.0) || !std::isfinite(o.clearance_m)) {
    return "clearance_m must be >= 0, got " + std::to_string(o.clearance_m);
  }
  if (!(o.waypoint_spacing_m > 0.0) || !std::isfinite(o.waypoint_spacing_m)) {
    return "waypoint_spacing_m must be > 0, got " + std::to_string(o.waypoint_spacing_m);
  }
  if (!(o.max_turn_radius_m >= 0.0) || !std::isfinite(o.max_turn_radius_m)) {
    return "max_turn_radius_m must be >= 0, got " + std::to_string(o.max_turn_radius_m);
  }
  return std::nullopt;
}

double RoutePiece::extent() const { return kind == Kind::kTurn ? std::abs(turn_rad) : length_m; }

Pose2 RoutePiece::pose_at(double progress) const {
  const double u = std::clamp(progress, 0.0, extent());
  switch (kind) {
    case Kind::kLine:
      return start * Pose2{u, 0.0, 0.0};
    case Kind::kArc: {
      const double a = curvature_1_per_m * u;
      return start * Pose2{std::sin(a) / curvature_1_per_m, (1.0 - std::cos(a)) / curvature_1_per_m,
                           normalize_angle(a)};
    }
    case Kind::kTurn:
      return Pose2{start.x, start.y, normalize_angle(start.theta + std::copysign(u, turn_rad))};
  }
  return start;
}

std::vector<std::uint8_t> room_for_robot(const World& world, double clearance_m) {
  TESSERA_ASSERT(clearance_m >= 0.0);
  const GridGeometry& g = world.geometry();
  const std::vector<double> d2 = squared_distance_to_solid_cells(world);
  // Any point of a cell and any point of a solid cell are at least (centre distance - sqrt(2))
  // cells apart: each lies within half a diagonal of its centre.
  const double need_cells = clearance_m / g.resolution_m() + kSqrt2;
  // The tolerance keeps rounding from deciding a cell right at the threshold (sqrt(2)^2 is not 2).
  const double need2 = need_cells * need_cells - 1e-9;
  std::vector<std::uint8_t> room(g.size(), 0);
  for (std::size_t i = 0; i < g.size(); ++i) room[i] = d2[i] >= need2 ? 1 : 0;
  return room;
}

Result<Pose2> random_start_pose(const World& world, double clearance_m, Rng& rng) {
  if (!(clearance_m >= 0.0) || !std::isfinite(clearance_m)) {
    return input_error("clearance_m must be >= 0, got " + std::to_string(clearance_m));
  }
  const GridGeometry& g = world.geometry();
  const std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
  // The largest component, by a flood fill from each unlabelled room cell in row-major order.
  std::vector<std::int32_t> label(g.size(), -1);
  std::vector<std::size_t> sizes;
  std::vector<Cell> queue;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (room[i] == 0 || label[i] >= 0) continue;
    const auto id = static_cast<std::int32_t>(sizes.size());
    queue.assign(1, g.cell_of(i));
    label[i] = id;
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for (const Cell d : kNeighbors4) {
        const Cell n = queue[head] + d;
        if (!g.contains(n)) continue;
        const std::size_t j = g.index_of(n);
        if (room[j] == 0 || label[j] >= 0) continue;
        label[j] = id;
        queue.push_back(n);
      }
    }
    sizes.push_back(queue.size());
  }
  if (sizes.empty()) {
    return input_error("no room for the robot: no free cell is at least clearance_m = " +
                       metres(clearance_m) + " m from every wall");
  }
  const auto best =
      static_cast<std::int32_t>(std::max_element(sizes.begin(), sizes.end()) - sizes.begin());
  const int pick = rng.uniform_int(0, static_cast<int>(sizes[static_cast<std::size_t>(best)]) - 1);
  int seen = 0;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (label[i] != best) continue;
    if (seen++ == pick) {
      const Vec2 p = g.center_of(g.cell_of(i));
      return Pose2{p.x, p.y, rng.uniform(-kPi, kPi)};
    }
  }
  TESSERA_ASSERT(false);
  return input_error("unreachable");
}

Result<Tour> plan_tour(const World& world, const Pose2& start, const TourOptions& o) {
  if (auto problem = validate(o)) return input_error("tour: " + *problem);
  const GridGeometry& g = world.geometry();
  const Vec2 start_m = start.translation();
  if (!std::isfinite(start.x) || !std::isfinite(start.y) || !std::isfinite(start.theta)) {
    return input_error("start pose must be finite");
  }
  const std::optional<Cell> start_cell = g.cell_at(start_m);
  if (!start_cell.has_value()) {
    return input_error("start " + point_text(start_m) + " is outside the map");
  }
  if (world.solid(*start_cell)) {
    return input_error("start " + point_text(start_m) + " is inside an obstacle");
  }
  const std::vector<std::uint8_t> room = room_for_robot(world, o.clearance_m);
  if (room[g.index_of(*start_cell)] == 0) {
    return input_error("start " + point_text(start_m) +
                       " is closer than clearance_m = " + metres(o.clearance_m) + " m to a wall");
  }
  const std::vector<std::uint8_t> reachable = component_of(g, room, *start_cell);

  // Step 2: one waypoint per lattice block.
  const WaypointLattice lattice = lattice_waypoints(g, reachable, o.waypoint_spacing_m);
  const int block = lattice.block, blocks_x = lattice.blocks_x, blocks_y = lattice.blocks_y;
  const auto block_index = [&](Cell c) { return lattice.block_index(c); };
  const std::vector<Cell>& waypoints = lattice.waypoints;
  const std::vector<std::int64_t>& waypoint_of_block = lattice.waypoint_of_block;
  std::vector<std::uint8_t> is_waypoint(g.size(), 0);
  for (const Cell w : waypoints) is_waypoint[g.index_of(w)] = 1;

  // Step 3: greedy nearest unvisited waypoint; passing within half a spacing visits one.
  Tour tour;
  std::vector<std::uint8_t> visited(waypoints.size(), 0);
  const double pass_m = 0.5 * o.waypoint_spacing_m;
  const auto visit_near = [&](Cell c) {
    const Vec2 p = g.center_of(c);
    const int bx = c.x / block, by = c.y / block;
    for (int y = by - 1; y <= by + 1; ++y) {
      for (int x = bx - 1; x <= bx + 1; ++x) {
        if (x < 0 || y < 0 || x >= blocks_x || y >= blocks_y) continue;
        const std::int64_t w =
            waypoint_of_block[static_cast<std::size_t>(y) * static_cast<std::size_t>(blocks_x) +
                              static_cast<std::size_t>(x)];
        if (w < 0 || visited[static_cast<std::size_t>(w)] != 0) continue;
        const Vec2 q = g.center_of(waypoints[static_cast<std::size_t>(w)]);
        if ((q - p).norm() <= pass_m) {
          visited[static_cast<std::size_t>(w)] = 1;
          tour.waypoints_m.push_back(q);
        }
      }
    }
  };
  // The legs of the tour, each a shortest grid path from the end of the previous one.
  std::vector<std::vector<Cell>> legs;
  Cell here = *start_cell;
  visit_near(here);
  MaskDijkstra dijkstra(g, room);
  const auto append_leg = [&](Cell goal) {
    legs.push_back(dijkstra.path_to(goal));
    for (const Cell c : legs.back()) visit_near(c);
    here = goal;
  };
  for (;;) {
    const std::optional<Cell> next = dijkstra.search(here, [&](Cell c) {
      const std::size_t i = g.index_of(c);
      if (is_waypoint[i] == 0) return false;
      const std::int64_t w = waypoint_of_block[block_index(c)];
      return visited[static_cast<std::size_t>(w)] == 0;
    });
    if (!next.has_value()) break;  // every reachable waypoint is visited
    append_leg(*next);
  }
  if (o.return_to_start && !(here == *start_cell)) {
    const std::optional<Cell> home =
        dijkstra.search(here, [&](Cell c) { return c == *start_cell; });
    TESSERA_ASSERT(home.has_value());
    append_leg(*home);
  }

  // Step 4: each leg string-pulled on its own (a leg never doubles back; the tour does), from the
  // start position itself and back to it; then the corners are rounded. The straight segment
  // between consecutive cells of a leg lies in room cells (no corner cutting), and so does the one
  // from the start position in its cell to a neighbour's centre.
  tour.polyline_m.push_back(start_m);
  for (std::size_t k = 0; k < legs.size(); ++k) {
    std::vector<Vec2> points;
    for (const Cell c : legs[k]) points.push_back(g.center_of(c));
    points.front() = tour.polyline_m.back();
    const bool home_leg =
        o.return_to_start && k + 1 == legs.size() && legs[k].back() == *start_cell;
    if (home_leg) points.back() = start_m;
    const std::vector<Vec2> pulled = string_pull(g, room, points);
    for (std::size_t i = 1; i < pulled.size(); ++i) tour.polyline_m.push_back(pulled[i]);
  }
  tour.pieces = smooth(g, room, tour.polyline_m, start.theta, o.max_turn_radius_m);
  for (const RoutePiece& p : tour.pieces) {
    tour.length_m += p.length_m;
    tour.turn_rad += p.kind == RoutePiece::Kind::kTurn ? std::abs(p.turn_rad)
                                                       : std::abs(p.curvature_1_per_m) * p.length_m;
  }
  return tour;
}

}  // namespace tessera
