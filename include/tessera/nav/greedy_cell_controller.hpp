#pragma once
// The thesis' navigation as written (section 4.3.5), kept as the baseline the zigzag fix is
// measured against (docs/fusion-navigation.md): at every control step the robot takes the cell
// whose centre is nearest as its current cell, picks the adjacent cell with the higher wavefront
// value (nav/wavefront.hpp) and steers for that cell's centre. Every border crossing re-decides the
// target, which is what made the thesis' robot zigzag (sections 5.2.1 and 6.1).
#include <cstddef>

#include "tessera/core/pose2.hpp"
#include "tessera/grid/cell_graph.hpp"
#include "tessera/nav/path_follower.hpp"
#include "tessera/nav/velocity_command.hpp"
#include "tessera/nav/wavefront.hpp"

namespace tessera {

struct GreedyCellControllerOptions {
  /// Speed, turn-rate limit, gain and goal tolerance (lookahead_m is unused).
  PathFollowerOptions motion;
  /// The thesis does not give its heading law. true: "face the cell, then drive to it": turn in
  /// place at the full turn rate until the heading error is below aligned_rad, then drive at full
  /// speed with proportional correction. false: PathFollower's smooth law (v ~ cos(error)), to
  /// separate the effect of re-deciding at borders from the effect of the heading law.
  bool turn_then_drive = true;
  double aligned_rad = 0.1;
};

class GreedyCellController {
 public:
  /// Preconditions: goal_cell < graph.size(), !validate(options.motion), aligned_rad > 0.
  GreedyCellController(CellGraph graph, std::size_t goal_cell,
                       GreedyCellControllerOptions options = {});

  /// The command for the robot at T_map_robot. Zero once within goal_tolerance_m of the goal
  /// cell's centre, or when the current cell cannot reach the goal. Cost: O(cells).
  [[nodiscard]] VelocityCommand command(const Pose2& T_map_robot);

  [[nodiscard]] bool arrived() const { return arrived_; }
  /// True when the last command found no neighbour with a higher value (unreachable goal).
  [[nodiscard]] bool stuck() const { return stuck_; }
  /// How many times the target cell changed: one per border decision.
  [[nodiscard]] int target_changes() const { return target_changes_; }
  [[nodiscard]] const WavefrontField& field() const { return field_; }

 private:
  CellGraph graph_;
  WavefrontField field_;
  GreedyCellControllerOptions options_;
  std::size_t target_ = 0;
  bool has_target_ = false;
  int target_changes_ = 0;
  bool arrived_ = false;
  bool stuck_ = false;
};

}  // namespace tessera
