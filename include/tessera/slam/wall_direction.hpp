#pragma once
// The dominant wall direction of one scan, for the Manhattan prior of the pose graph (lecture,
// "mapping using knowledge of the environment"; posegraph/pose_graph.hpp's HeadingPrior; issue
// 18 item 7). Short straight runs of neighbouring returns are fitted with lines (principal
// components of 2k+1 returns of consecutive beams); their directions, folded modulo 90 degrees
// (a wall and the wall across it count alike), vote with their length into a circular histogram;
// the peak, refined by the mean of the votes near it, is the direction. Its strength, the share of
// the votes near the peak, says whether the scan shows walls at right angles at all.
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/vec2.hpp"

namespace tessera::slam {

struct WallDirectionOptions {
  /// A run is 2 * half_window + 1 returns of consecutive beams ...
  int half_window = 3;
  /// ... at most this long end to end ...
  double max_run_m = 1.0;
  /// ... and straight: their spread across the fitted line at most this (standard deviation).
  double max_line_sigma_m = 0.02;
  /// Width of the votes' neighbourhood of the peak (each side).
  double peak_half_width_rad = 0.05;
  /// A direction is reported only when at least this share of the votes falls near the peak ...
  double min_strength = 0.3;
  /// ... from at least this many runs.
  int min_runs = 10;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const WallDirectionOptions& o);

struct WallDirection {
  /// In [-pi/4, pi/4), the frame of the points (the robot's for a scan).
  double angle_rad = 0.0;
  double strength = 0.0;  // share of the votes within peak_half_width_rad of it
  int runs = 0;           // straight runs that voted
};

/// The dominant direction of `points_m` (in beam order) with `beams` their beam indices (same
/// length; a run never spans a dropped beam), or nothing when the scan shows no clear direction.
/// Precondition: validate(options) is empty. Cost: O(n) plus a 90-bin histogram.
[[nodiscard]] std::optional<WallDirection> dominant_wall_direction(
    const std::vector<Vec2>& points_m, const std::vector<int>& beams,
    const WallDirectionOptions& options);

}  // namespace tessera::slam
