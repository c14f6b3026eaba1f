#pragma once
// A drivable tour of a world for a round differential-drive robot: it visits the whole reachable
// free space, passes places more than once (so that a SLAM run meets loop closures) and keeps its
// centre at a clearance from every wall. Used by the simulated laser runs (sim/laser_run.hpp).
//
//  1. Room for the robot: the cells every point of which is at least clearance_m from every solid
//     cell, from an exact Euclidean distance transform (Felzenszwalb & Huttenlocher 2012,
//     "Distance Transforms of Sampled Functions", Theory of Computing 8).
//  2. Waypoints: one per block of a coarse lattice (waypoint_spacing_m), the cell of the start's
//     component nearest the block's centre.
//  3. Order: greedy nearest unvisited waypoint by path length (nav/route_planner.hpp's Dijkstra
//     over the room cells, 8-connected, no corner cutting); a waypoint the path passes within half a spacing of counts
//     as visited. Leaving a dead end retraces its corridor, and the tour ends back at the start, so
//     places are revisited.
//  4. Smoothing: the grid path is shortened by nav/route_planner.hpp's string pulling (a vertex is
//     dropped while the straight segment stays in room cells, checked exactly), then each corner is rounded with a circular arc
//     tangent to both segments (at most max_turn_radius_m, shrunk until the arc stays in room
//     cells); a corner too sharp for an arc is a turn in place.
// The result is lines, arcs and turns in place: a route a differential drive follows exactly.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/rng.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/sim/world.hpp"

namespace tessera {

struct TourOptions {
  /// The robot's centre stays at least this far from every solid cell (robot radius plus margin).
  double clearance_m = 0.25;
  /// Side of the waypoint lattice's blocks. The default suits a lidar of about 10 m range: it
  /// enters rooms of office size and passes every corridor.
  double waypoint_spacing_m = 3.5;
  /// Corners are rounded with arcs of at most this radius; 0 turns in place at every corner.
  double max_turn_radius_m = 0.75;
  /// Drive back to the start after the last waypoint (closes the largest loop).
  bool return_to_start = true;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const TourOptions& o);

/// One piece of a route: drive straight, drive along a circular arc, or turn in place.
struct RoutePiece {
  enum class Kind { kLine, kArc, kTurn };
  Kind kind = Kind::kLine;
  Pose2 start;                     // T_world_robot where the piece begins
  double length_m = 0.0;           // line and arc: distance driven; turn: 0
  double curvature_1_per_m = 0.0;  // arc: signed 1 / radius, counter-clockwise positive
  double turn_rad = 0.0;           // turn: signed angle, counter-clockwise positive

  /// How far the piece goes: metres for a line or arc, |turn_rad| radians for a turn.
  [[nodiscard]] double extent() const;
  /// The pose after `progress` (metres along a line or arc, radians turned of a turn), clamped
  /// to [0, extent()]. Exact, O(1).
  [[nodiscard]] Pose2 pose_at(double progress) const;
  [[nodiscard]] Pose2 end() const { return pose_at(extent()); }
};

struct Tour {
  /// The lattice waypoints in the order the tour reached them (visited by passing included).
  std::vector<Vec2> waypoints_m;
  /// The string-pulled path, the start position first; the route's corners are its vertices.
  std::vector<Vec2> polyline_m;
  /// The drivable route from the start pose; consecutive pieces join (up to rounding).
  std::vector<RoutePiece> pieces;
  double length_m = 0.0;  // distance the route drives
  double turn_rad = 0.0;  // sum of |heading change| along the route
};

/// One byte per cell of world.geometry(), 1 where the robot's centre may be: the free cells all of
/// whose points are at least clearance_m from every solid cell (and from the grid's edge, beyond
/// which everything is solid). Conservative by at most one cell diagonal. Cost: O(cells).
[[nodiscard]] std::vector<std::uint8_t> room_for_robot(const World& world, double clearance_m);

/// A random start: the centre of a cell drawn uniformly from the largest 4-connected component of
/// room_for_robot(world, clearance_m), heading uniform in [-pi, pi). Input error when no cell has
/// room ("no room for the robot: no free cell is at least clearance_m = 0.25 m from every wall").
[[nodiscard]] Result<Pose2> random_start_pose(const World& world, double clearance_m, Rng& rng);

/// The tour from `start` (T_world_robot) over the room cells reachable from it (steps 1-4 above).
/// Input errors: invalid options ("tour: <what is wrong>"), a start outside the map, in a solid
/// cell, or where the robot has no room ("start (x, y) m is closer than clearance_m = 0.25 m to a
/// wall"). When there is nothing to visit (the start's component lies within half a spacing of the
/// start), pieces is empty. Deterministic. Cost: one Dijkstra search per leg, each stopping at the
/// nearest unvisited waypoint: O(legs * cells log cells) at worst.
[[nodiscard]] Result<Tour> plan_tour(const World& world, const Pose2& start,
                                     const TourOptions& options);

}  // namespace tessera
