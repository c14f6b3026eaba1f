#pragma once
// Submaps: small probability grids built from a few dozen consecutive scans, rigid once finished,
// so that loop closure moves whole submaps instead of cells (Hess et al. 2016, Sec. IV-B; Konolige
// et al. 2010 do the same with local chains of scans). Two submaps are active at a time and every
// scan goes into both; the older one, which holds twice the newer one's scans, is what the next
// scan is matched against, so matching never runs on a nearly empty grid.
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "tessera/core/pose2.hpp"
#include "tessera/slam/probability_grid.hpp"
#include "tessera/slam/scan_points.hpp"

namespace tessera::slam {

struct SubmapOptions {
  double resolution_m = 0.05;
  /// Scans inserted into the newest submap before the next one starts; each finished submap holds
  /// twice this many (Cartographer's num_range_data).
  int scans_per_submap = 90;
  /// ... or metres travelled since the newest submap started, whichever comes first (0: scans
  /// only). Sizes submaps by the ground they cover, so that a log with a scan every metre does not
  /// build 180-metre submaps whose walls no longer agree: odometry and matching drift grow with
  /// distance, not with the number of scans (decision 0013).
  double travel_per_submap_m = 15.0;
  /// Side of a new submap's grid; it grows as scans reach beyond it.
  double initial_size_m = 16.0;
  RangeInsertOptions insert;
  /// Hits weigh more when scans are far apart. Cartographer's hit probability (insert, 0.55) suits
  /// scans a few centimetres apart, where each wall cell of a submap is hit dozens of times; in a
  /// log with a scan every metre it is hit a few times, stays near 0.55 and gives the matcher
  /// little to hold on to. A scan's hits therefore get the hit log-odds times
  /// clamp(step / hit_evidence_step_m, 1, max_hit_evidence_scale), rounded to a quarter, `step`
  /// the mean distance between the last 20 inserts (a mean, so that the scans of a sparse log
  /// weigh alike whether they were kept for a metre driven or a turn): logs whose nodes are the
  /// motion filter's 0.2 m apart keep 0.55, a scan every 0.7 m or more gets 0.6. Measured on
  /// simulated buildings against their exact poses and on the real logs (decision 0035).
  double hit_evidence_step_m = 0.35;
  double max_hit_evidence_scale = 2.0;
};

/// Empty when usable; otherwise names the field and the rule it breaks.
[[nodiscard]] std::optional<std::string> validate(const SubmapOptions& o);

/// One submap. Its grid lives in the submap frame, whose pose in the local-SLAM frame is
/// local_pose() (the position of the scan that started it, heading 0); the grid is axis-aligned in
/// that frame.
class Submap {
 public:
  Submap(const Pose2& T_local_submap, const SubmapOptions& options);

  [[nodiscard]] const Pose2& local_pose() const { return T_local_submap_; }
  [[nodiscard]] const ProbabilityGrid& grid() const { return grid_; }
  [[nodiscard]] int num_scans() const { return num_scans_; }
  /// Path length of the robot over the scans inserted so far (metres).
  [[nodiscard]] double travel_m() const { return travel_m_; }
  [[nodiscard]] bool finished() const { return finished_; }

  /// Inserts a scan taken at T_local_robot. Precondition: !finished().
  void insert(const ScanPoints& points, const Pose2& T_local_robot, const RangeInserter& inserter);
  void finish() { finished_ = true; }

 private:
  Pose2 T_local_submap_;
  ProbabilityGrid grid_;
  int num_scans_ = 0;
  double travel_m_ = 0.0;
  Vec2 last_position_m_;
  bool finished_ = false;
};

/// Every submap of a run, with the window of the (at most) two active ones. Submap ids are their
/// index in creation order; references stay valid while submaps are added.
class ActiveSubmaps {
 public:
  explicit ActiveSubmaps(const SubmapOptions& options);

  /// What one insert did: the submaps the scan went into (oldest first) and the submap it
  /// finished, if any.
  struct Insertion {
    std::vector<int> inserted_into;
    std::optional<int> finished;
  };
  /// Inserts a scan taken at T_local_robot into the active submaps, starting a new submap first
  /// when the newest is full (scans_per_submap scans or travel_per_submap_m metres) and finishing
  /// the oldest when the newest becomes full: the oldest then holds about twice a full one. Its
  /// hits weigh by the mean step of the recent inserts (SubmapOptions::hit_evidence_step_m; the
  /// first insert after finish_all does not count the step from the one before).
  Insertion insert(const ScanPoints& points, const Pose2& T_local_robot);

  /// Finishes every active submap that is not finished yet and empties the window, so that the
  /// next insert starts a new submap (a trajectory ends); returns the ids it finished.
  std::vector<int> finish_all();
  /// The submap the next scan should be matched against (the oldest active one); nullopt before
  /// the first insert.
  [[nodiscard]] std::optional<int> matching_id() const;
  [[nodiscard]] const Submap& submap(int id) const {
    return submaps_[static_cast<std::size_t>(id)];
  }
  [[nodiscard]] int size() const { return static_cast<int>(submaps_.size()); }
  /// The active submaps, oldest first.
  [[nodiscard]] const std::vector<int>& active_ids() const { return active_; }

 private:
  [[nodiscard]] bool full(const Submap& s) const;

  /// The inserter for a mean step of `step_m` metres between inserts.
  [[nodiscard]] const RangeInserter& inserter_for(double step_m) const;

  SubmapOptions options_;
  /// inserters_[k]: hits at 1 + k / 4 times the hit log-odds of options_.insert.
  std::vector<RangeInserter> inserters_;
  std::deque<Submap> submaps_;
  std::vector<int> active_;
  std::optional<Vec2> last_position_m_;  // of the previous insert; empty after finish_all
  std::deque<double> recent_steps_m_;    // the last steps between inserts
};

}  // namespace tessera::slam
