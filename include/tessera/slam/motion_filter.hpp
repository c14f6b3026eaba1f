#pragma once
// Keeps a scan only when the robot has moved or turned enough, or enough time has passed, since
// the last kept one (Cartographer's MotionFilter; Hess et al. 2016 Sec. IV). A standing robot then
// adds no redundant scans to submaps and no nodes to the pose graph.
#include <cmath>
#include <optional>
#include <string>

#include "tessera/core/pose2.hpp"

namespace tessera::slam {

struct MotionFilterOptions {
  double max_time_s = 5.0;
  double max_distance_m = 0.2;
  double max_angle_rad = 0.0175;  // 1 degree
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const MotionFilterOptions& o);

class MotionFilter {
 public:
  explicit MotionFilter(const MotionFilterOptions& options) : options_(options) {}

  /// True when the pose at t_s is close to the last kept one (then it is dropped); false when it
  /// is kept, and it becomes the last kept one. The first pose is always kept. Stamps may go
  /// backwards (real logs jitter); the time test uses |t_s - last|.
  [[nodiscard]] bool is_similar(double t_s, const Pose2& pose) {
    if (has_last_ && std::abs(t_s - last_t_s_) <= options_.max_time_s &&
        std::hypot(pose.x - last_.x, pose.y - last_.y) <= options_.max_distance_m &&
        std::abs(normalize_angle(pose.theta - last_.theta)) <= options_.max_angle_rad) {
      return true;
    }
    has_last_ = true;
    last_ = pose;
    last_t_s_ = t_s;
    return false;
  }

  /// Forgets the last kept pose: the next one is kept (a new trajectory begins).
  void reset() { has_last_ = false; }

 private:
  MotionFilterOptions options_;
  // A flag and a plain pose rather than std::optional<Pose2>: GCC 12 under ASan reports the
  // optional's payload as maybe-uninitialized (a false positive that -Werror turns into a failure).
  bool has_last_ = false;
  Pose2 last_;
  double last_t_s_ = 0.0;
};

[[nodiscard]] inline std::optional<std::string> validate(const MotionFilterOptions& o) {
  if (!(o.max_time_s >= 0.0)) return "max_time_s must be >= 0";
  if (!(o.max_distance_m >= 0.0)) return "max_distance_m must be >= 0";
  if (!(o.max_angle_rad >= 0.0)) return "max_angle_rad must be >= 0";
  return std::nullopt;
}

}  // namespace tessera::slam
