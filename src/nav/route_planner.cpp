#include "tessera/nav/route_planner.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

#include "tessera/core/assert.hpp"
#include "tessera/grid/ray_cast.hpp"

namespace tessera {
namespace {

/// Vertices closer than this to the last kept one are the same point.
constexpr double kTinyLengthM = 1e-9;

std::string point_text(Vec2 p) {
  std::ostringstream out;
  out.precision(3);
  out << "(" << p.x << ", " << p.y << ") m";
  return out.str();
}

}  // namespace

MaskDijkstra::MaskDijkstra(const GridGeometry& g, const std::vector<std::uint8_t>& mask)
    : g_(g), mask_(mask), cost_(g.size()), parent_(g.size()), stamp_(g.size(), 0) {
  TESSERA_ASSERT(mask.size() == g.size());
}

void MaskDijkstra::discover(std::size_t i, double cost, std::size_t parent) {
  stamp_[i] = generation_;
  cost_[i] = cost;
  parent_[i] = parent;
}

std::optional<Cell> MaskDijkstra::settle_next() {
  while (!open_.empty()) {
    const auto [cost, i] = open_.top();
    open_.pop();
    if (cost > cost_[i]) continue;  // stale entry
    const Cell c = g_.cell_of(i);
    for (const Cell d : kNeighbors8) {
      const Cell n = c + d;
      if (!in_mask(n)) continue;
      const bool diagonal = d.x != 0 && d.y != 0;
      if (diagonal && !(in_mask({c.x + d.x, c.y}) && in_mask({c.x, c.y + d.y}))) continue;
      const double next_cost = cost + (diagonal ? std::numbers::sqrt2 : 1.0);
      const std::size_t j = g_.index_of(n);
      if (stamp_[j] == generation_ && cost_[j] <= next_cost) continue;
      discover(j, next_cost, i);
      open_.push({next_cost, j});
    }
    return c;
  }
  return std::nullopt;
}

std::vector<Cell> MaskDijkstra::path_to(Cell goal) const {
  std::vector<Cell> path;
  std::size_t i = g_.index_of(goal);
  TESSERA_ASSERT(stamp_[i] == generation_);
  for (;;) {
    path.push_back(g_.cell_of(i));
    if (parent_[i] == i) break;
    i = parent_[i];
  }
  std::reverse(path.begin(), path.end());
  return path;
}

double MaskDijkstra::cost_cells(Cell c) const {
  const std::size_t i = g_.index_of(c);
  return stamp_[i] == generation_ ? cost_[i] : std::numeric_limits<double>::infinity();
}

bool segment_in_mask(const GridGeometry& g, const std::vector<std::uint8_t>& mask, Vec2 a, Vec2 b) {
  bool inside = true;
  traverse_ray(g, a, b, [&](Cell c, double, double) {
    inside = g.contains(c) && mask[g.index_of(c)] != 0;
    return inside;
  });
  return inside;
}

std::vector<Vec2> string_pull(const GridGeometry& g, const std::vector<std::uint8_t>& mask,
                              const std::vector<Vec2>& points) {
  std::vector<Vec2> out;
  if (points.empty()) return out;
  out.push_back(points.front());
  std::size_t i = 0;
  while (i + 1 < points.size()) {
    std::size_t j = i + 1;
    while (j + 1 < points.size() && segment_in_mask(g, mask, points[i], points[j + 1])) ++j;
    if ((points[j] - out.back()).norm() > kTinyLengthM) out.push_back(points[j]);
    i = j;
  }
  return out;
}

Result<std::vector<Vec2>> plan_mask_route(const GridGeometry& g,
                                          const std::vector<std::uint8_t>& mask, Vec2 from_m,
                                          Vec2 to_m) {
  const std::optional<Cell> a = g.cell_at(from_m);
  const std::optional<Cell> b = g.cell_at(to_m);
  if (!a || mask[g.index_of(*a)] == 0) {
    return input_error("route: start " + point_text(from_m) +
                       " has no room for the robot (too close to a wall, or outside the map)");
  }
  if (!b || mask[g.index_of(*b)] == 0) {
    return input_error("route: goal " + point_text(to_m) +
                       " has no room for the robot (too close to a wall, or outside the map)");
  }
  MaskDijkstra dijkstra(g, mask);
  if (!dijkstra.search(*a, [&](Cell c) { return c == *b; })) {
    return input_error("route: no path from " + point_text(from_m) + " to " + point_text(to_m) +
                       " keeps the robot's clearance from the walls");
  }
  std::vector<Vec2> points;
  for (const Cell c : dijkstra.path_to(*b)) points.push_back(g.center_of(c));
  points.front() = from_m;
  points.back() = to_m;
  return string_pull(g, mask, points);
}

}  // namespace tessera
