#pragma once
// Going round what the sonars remember (sonar_grid.hpp) instead of only turning away from it: when
// an occupied cell lies on the path ahead, a route is planned on a local grid from the robot to a
// point of the path past the obstacle, keeping a clearance from every occupied cell, and the robot
// follows that route and then the rest of its path. The planner is route_planner.hpp's (Dijkstra
// over the free cells, string pulling); the clearances are tried widest first, so the robot goes
// round on the side with room (a box beside a wall is passed on its open side) and squeezes
// through only when nothing wider leads on. Cells no sonar has seen count as free: the sonars see
// the walls beside the robot as it drives, and the path was driven before; a detour stays near the
// old path for that reason. No I/O.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/vec2.hpp"
#include "tessera/nav/sonar_grid.hpp"

namespace tessera {

struct DetourOptions {
  /// The stretch of the path ahead of the robot that is checked for obstacles, from skip_m on:
  /// what is nearer than skip_m a new route cannot avoid any more (the avoidance and the bumpers
  /// deal with it), and a door post beside the robot would otherwise replan it at every step.
  double look_ahead_m = 2.0;
  double skip_m = 0.3;
  /// An occupied cell within this distance of the path blocks it (the body's radius and a margin).
  double block_radius_m = 0.3;
  /// A detour once planned is kept until the robot is back on its old path, unless an occupied
  /// cell comes within this distance of it (the body's radius and 2 cm): sonar arcs that shift a
  /// little with every sweep would otherwise replan it at every update, to and fro between sides.
  double replan_radius_m = 0.27;
  double replan_look_ahead_m = 1.0;
  /// At most one new route per this many seconds unless a bumper is pressed (the caller's rule):
  /// a robot handed a new route at every update keeps turning to face it and never drives.
  double min_replan_interval_s = 1.0;
  /// A robot further than this from its path (pushed off it by the avoidance), or one whose
  /// bumpers are pressed, is routed back to the path round what is remembered (the caller's rule).
  double off_path_m = 0.15;
  /// A robot whose path still ahead (a detour's, or the one from the cells) has not shortened by
  /// 0.1 m in this long is stuck: its path is planned afresh, and a route back to it round what is
  /// remembered from where it stands (the caller's rule). The avoidance can hold a robot short of
  /// a detour's end, at a wall the detour was planned through before the sonars had seen it.
  double give_up_after_s = 5.0;
  /// The detour rejoins the path this far past its last blocked point.
  double rejoin_after_m = 0.5;
  /// The planning grid covers the robot and the path up to the rejoin point, grown by this.
  double window_margin_m = 1.5;
  /// A detour stays within this distance of the old path (or of the robot): cells no sonar has
  /// seen count as free, so a route far from the path would lead through walls not yet seen.
  double corridor_m = 0.9;
  /// Clearances from occupied cells that the detour keeps, tried in turn (widest first). The
  /// last one must be at least the body's radius, and should be the avoidance's strip half-width
  /// (0.35 m on the obstacle course): a gap narrower than that the planner would send the robot
  /// through while the avoidance turned it away from the sides (decision 0031, second addendum).
  std::vector<double> clearances_m = {0.45, 0.35};
  /// Step of the samples along the path.
  double sample_step_m = 0.05;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const DetourOptions& o);

/// The blocked stretch of a path: arc lengths (from the path's start) of the first and the last
/// sample that has an occupied cell within block_radius_m.
struct PathBlockage {
  double first_m = 0.0;
  double last_m = 0.0;
};

/// The blocked stretch of `path` between arc lengths from_m + skip_m and from_m + look_ahead_m,
/// counting only the occupied cells for which `counts` is true (all when it is empty); nullopt when
/// the stretch is clear. Cost: O(samples x occupied cells near the stretch).
[[nodiscard]] std::optional<PathBlockage> find_blockage(
    const std::vector<Vec2>& path, double from_m, const SonarGrid& grid,
    const DetourOptions& options, const std::function<bool(Vec2)>& counts = {});

/// A path round remembered obstacles: `path` runs from the robot round them to the old path and on
/// along it to its end; rejoin_m is the arc length along it of the point where it meets the old
/// path again.
struct Detour {
  std::vector<Vec2> path;
  double rejoin_m = 0.0;
  double rejoin_on_old_path_m = 0.0;  // the same point's arc length along the old path
};

/// A new path for the robot at robot_m: round the occupied cells of `grid` to the path's first
/// free point at least rejoin_after_m past blockage.last_m, then on along `path` to its end.
/// Starts at robot_m, or when the robot stands within the clearance at the nearest cell outside it
/// (a path follower then joins it where it is nearest). The route keeps within corridor_m of
/// `path`, of the robot, or of seen_m (a route driven before, e.g. the taught one, whose
/// surroundings the sonars have swept). nullopt when no clearance in options.clearances_m leads
/// there. Preconditions: path non-empty, !validate(options). Cost: one Dijkstra search per
/// clearance on a grid of the window's size, and a distance to each polyline per window cell.
[[nodiscard]] std::optional<Detour> plan_detour(const std::vector<Vec2>& path, Vec2 robot_m,
                                                const PathBlockage& blockage, const SonarGrid& grid,
                                                const DetourOptions& options,
                                                const std::vector<Vec2>& seen_m = {});

}  // namespace tessera
