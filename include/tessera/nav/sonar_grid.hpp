#pragma once
// A memory of what the sonars have seen: an occupancy grid of sonar cones in log-odds (Moravec and
// Elfes, "High Resolution Maps from Wide Angle Sonar", ICRA 1985; the lecture's occupancy
// probabilities in their log-odds form). A reading of range r along a cone marks the cells of the
// cone nearer than r free and the arc at r occupied; an echo-less reading clears its cone. A wall
// seen aslant, which one cone places too near along its axis, is cleared again by the cones that
// see past that place, so what stays occupied is where echoes agree.
//
// The reactive avoidance (reactive_avoidance.hpp) forgets an obstacle as soon as it is out of its
// sonars' view; this grid is what lets a planner (detour_planner.hpp) go round it instead. Sparse:
// only cells a cone has touched are stored. No I/O.
#include <cstdint>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/core/vec2.hpp"
#include "tessera/nav/reactive_avoidance.hpp"

namespace tessera {

struct SonarGridOptions {
  double resolution_m = 0.05;
  /// Half the cone's opening (a Polaroid 6500's main lobe is about 15 degrees wide).
  double half_cone_rad = 0.13;
  /// Readings are used up to this range (sonar grows vague with range); an echo beyond it, or no
  /// echo, clears the cone up to it.
  double max_range_m = 2.0;
  /// Sonars sit on the body's edge this far from the centre; ranges are measured from there.
  double sensor_radius_m = 0.2;
  /// The occupied arc: cells within this of the echo's range.
  double arc_half_thickness_m = 0.05;
  /// Log-odds added per reading on the cone's axis: an echo on the arc, free space inside it
  /// (less off the axis). Clamped to +-clamp.
  double hit_log_odds = 0.85;
  double free_log_odds = -0.4;
  double clamp_log_odds = 4.0;
  /// A cell counts as occupied above this log-odds: on the axis, two echoes that nothing has
  /// cleared.
  double occupied_log_odds = 1.2;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const SonarGridOptions& o);

class SonarGrid {
 public:
  /// Precondition: !validate(options).
  explicit SonarGrid(SonarGridOptions options = {});

  /// Adds one sonar sweep taken at T_map_robot (bearings in the robot frame; a range that is not
  /// finite and positive is "no echo"). Cost: O(readings x cone cells).
  void insert(const Pose2& T_map_robot, const std::vector<ObstacleRange>& sonar);

  /// Log-odds of the cell under p_m (0: never seen).
  [[nodiscard]] double log_odds(Vec2 p_m) const;
  [[nodiscard]] bool occupied(Vec2 p_m) const;
  /// Centres of the occupied cells within radius_m of p_m. Cost: O(stored cells).
  [[nodiscard]] std::vector<Vec2> occupied_within(Vec2 p_m, double radius_m) const;

  [[nodiscard]] const SonarGridOptions& options() const { return options_; }
  [[nodiscard]] std::size_t stored_cells() const { return cells_.size(); }

 private:
  [[nodiscard]] static std::uint64_t key(int x, int y);
  void add(int x, int y, double log_odds);

  SonarGridOptions options_;
  std::unordered_map<std::uint64_t, float> cells_;
};

}  // namespace tessera
