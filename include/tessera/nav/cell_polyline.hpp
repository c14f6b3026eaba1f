#pragma once
// The way the robot drives a planned cell path without zigzagging (thesis section 6.2 item 3).
// The thesis' robot re-decided its target at every cell border and headed for the next cell's
// centre, so it turned at every border and, between two cells of equal value, ping-ponged
// (section 6.1). Here the whole cell sequence is committed to once, and the polyline through its
// centres is shortened by line of sight: a straight segment replaces a run of centres when every
// point of it lies in one of the cells of that run (it stays inside the corridor of cells the robot
// has already driven through), so straight corridors of hexagons become straight lines. (The
// hexagon test uses the unrotated Table 4.3 axes; after a drift correction that turned the cells a
// little, points near a border may be judged by the nearest-centre rule alone.)
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/grid/cell_graph.hpp"

namespace tessera {

struct CellPolylineOptions {
  /// The cells' d (fusion::HexCellMapOptions::cell_radius_m): a point is in a cell when it lies in
  /// the flat-topped hexagon with neighbouring centres this far apart around the cell's centre.
  double cell_radius_m = 0.3;
  /// Spacing of the points tested along a candidate shortcut, metres.
  double sample_step_m = 0.01;
  /// Slack for points on a border: a point counts as inside the run when it is inside a run
  /// cell's hexagon grown by this much, and at most this much farther from the run's nearest
  /// centre than from the nearest centre of the whole map.
  double border_tolerance_m = 1e-6;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const CellPolylineOptions& o);

/// The shortened polyline from start_m through the cells of `cell_path` (cell_path[0] is the cell
/// the robot is in) to goal_m (in the last cell: its centre, or the pose of an image node).
/// Greedy: from each vertex, extend to later vertices while the line of sight holds. A path of one
/// cell gives {start_m, goal_m}. Preconditions: cell_path non-empty, ids < graph.size(), options
/// valid. Cost: O(tested samples * (path + cells)); about (path length / sample_step_m) samples
/// per kept segment.
[[nodiscard]] std::vector<Vec2> cell_path_polyline(const CellGraph& graph,
                                                   const std::vector<std::size_t>& cell_path,
                                                   Vec2 start_m, Vec2 goal_m,
                                                   const CellPolylineOptions& options = {});

/// Length of a polyline, metres.
[[nodiscard]] double polyline_length_m(const std::vector<Vec2>& points_m);

/// The point at arc length s_m along a polyline (clamped to its ends). Precondition: non-empty.
[[nodiscard]] Vec2 polyline_point_at(const std::vector<Vec2>& points_m, double s_m);

/// Distance from p to a polyline, metres (to its one point when it has one; infinity when empty).
[[nodiscard]] double distance_to_polyline(Vec2 p, const std::vector<Vec2>& points_m);

/// The point of the polyline nearest to p; its only point when it has one. points_m must not be
/// empty.
[[nodiscard]] Vec2 nearest_on_polyline(Vec2 p, const std::vector<Vec2>& points_m);

}  // namespace tessera
