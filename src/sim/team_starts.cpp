// Where a team starts (sim/team_starts.hpp).
#include "tessera/sim/team_starts.hpp"

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "tessera/core/assert.hpp"
#include "tessera/sim/tour.hpp"

namespace tessera {

Result<std::vector<Pose2>> team_starts(const World& world, int robots, double clearance_m,
                                       double spacing_m, double lattice_m) {
  const GridGeometry& g = world.geometry();
  TESSERA_ASSERT(lattice_m > 0.0);
  const std::vector<std::uint8_t> room = room_for_robot(world, clearance_m);
  // The centre of the lattice cell holding the world cell's centre, if that lies in a cell with
  // room (a lattice coarser than the world's cells can reach into the next cell); else the world
  // cell's centre.
  const auto on_lattice = [&](Cell c) {
    const Vec2 p = g.center_of(c);
    const auto snap = [&](double v, double o) {
      return o + (std::floor((v - o) / lattice_m + 1e-9) + 0.5) * lattice_m;
    };
    const Vec2 q{snap(p.x, g.origin().x), snap(p.y, g.origin().y)};
    const std::optional<Cell> in = g.cell_at(q);
    return in && room[g.index_of(*in)] != 0 ? q : p;
  };
  // The largest 4-connected area with room and its centroid.
  std::vector<std::int32_t> label(g.size(), -1);
  std::vector<Cell> best_cells, queue;
  for (std::size_t i = 0; i < g.size(); ++i) {
    if (room[i] == 0 || label[i] >= 0) continue;
    queue.assign(1, g.cell_of(i));
    label[i] = static_cast<std::int32_t>(i);
    for (std::size_t head = 0; head < queue.size(); ++head) {
      for (const Cell d : kNeighbors4) {
        const Cell n = queue[head] + d;
        if (!g.contains(n) || room[g.index_of(n)] == 0 || label[g.index_of(n)] >= 0) continue;
        label[g.index_of(n)] = static_cast<std::int32_t>(i);
        queue.push_back(n);
      }
    }
    if (queue.size() > best_cells.size()) best_cells = queue;
  }
  if (best_cells.empty()) {
    return input_error("no room for a robot: no free cell is at least " +
                       std::to_string(clearance_m) + " m from every wall");
  }
  double cx = 0.0, cy = 0.0;
  for (const Cell c : best_cells) {
    cx += c.x;
    cy += c.y;
  }
  cx /= static_cast<double>(best_cells.size());
  cy /= static_cast<double>(best_cells.size());
  Cell first = best_cells.front();
  double best_d2 = std::numeric_limits<double>::infinity();
  for (const Cell c : best_cells) {  // row-major ties: the first found
    const double d2 = (c.x - cx) * (c.x - cx) + (c.y - cy) * (c.y - cy);
    if (d2 < best_d2) {
      best_d2 = d2;
      first = c;
    }
  }
  // Breadth-first from the first start over the cells with room.
  std::vector<Pose2> starts;
  std::vector<std::uint8_t> seen(g.size(), 0);
  queue.assign(1, first);
  seen[g.index_of(first)] = 1;
  for (std::size_t head = 0; head < queue.size() && static_cast<int>(starts.size()) < robots;
       ++head) {
    const Vec2 p = on_lattice(queue[head]);
    bool apart = true;
    for (const Pose2& s : starts) apart = apart && std::hypot(s.x - p.x, s.y - p.y) >= spacing_m;
    if (apart) starts.push_back({p.x, p.y, 0.0});
    for (const Cell d : kNeighbors4) {
      const Cell n = queue[head] + d;
      if (!g.contains(n) || room[g.index_of(n)] == 0 || seen[g.index_of(n)] != 0) continue;
      seen[g.index_of(n)] = 1;
      queue.push_back(n);
    }
  }
  if (static_cast<int>(starts.size()) < robots) {
    return input_error("room for only " + std::to_string(starts.size()) + " robots " +
                       std::to_string(spacing_m) + " m apart around the start, " +
                       std::to_string(robots) + " asked");
  }
  return starts;
}

}  // namespace tessera
