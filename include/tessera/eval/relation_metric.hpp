#pragma once
// The relation metric of Kummerle et al. 2009 ("On measuring the accuracy of SLAM algorithms",
// Autonomous Robots 27(4):387-407): a SLAM trajectory is scored on the relative motions between
// pairs of stamps that a person has checked, so no alignment of frames is needed. Definition as
// ../shared/data/laser/README.md states it:
//   E = (x(t1)^-1 * x(t2)) * relation^-1,  t = |translation of E| (m),  r = |angle of E|,
// with x(t) the estimated trajectory interpolated linearly in translation and along the shortest
// arc in rotation; mean and sample standard deviation (n - 1) of t, t^2, r and r^2.
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

#include "tessera/core/relation.hpp"
#include "tessera/core/result.hpp"
#include "tessera/core/stamped_pose2.hpp"

namespace tessera {

/// The error of one relation that was scored.
struct RelationError {
  double t1_s = 0.0;  // the relation's stamps
  double t2_s = 0.0;
  double trans_m = 0.0;  // |translation of E|
  double rot_rad = 0.0;  // |angle of E|, in [0, pi]
};

/// The metric over the relations that fall inside the trajectory. Rotations are in radians here;
/// Kummerle et al. and the CLI report degrees (rad_to_deg of each field; the squared fields scale
/// by (180/pi)^2). A standard deviation over a single relation is 0.
struct RelationMetric {
  std::size_t count = 0;    // relations scored: both stamps inside the trajectory's time span
  std::size_t skipped = 0;  // relations with a stamp outside it, in a gap, or with no scan near it
  double trans_mean_m = 0.0;
  double trans_std_m = 0.0;
  double trans_sq_mean_m2 = 0.0;
  double trans_sq_std_m2 = 0.0;
  double rot_mean_rad = 0.0;
  double rot_std_rad = 0.0;
  double rot_sq_mean_rad2 = 0.0;
  double rot_sq_std_rad2 = 0.0;
  std::size_t poses = 0;            // poses of the trajectory
  double trajectory_begin_s = 0.0;  // its time span, time offset included
  double trajectory_end_s = 0.0;
  std::vector<RelationError> errors;  // one per relation scored, in the relations' order
};

/// The pose of a trajectory at t_s: linear in translation between the poses on either side, along
/// the shortest arc in heading; a pose stamped exactly t_s is returned as is. nullopt when t_s is
/// outside [first stamp, last stamp], or between two poses more than max_gap_s apart (a stretch
/// the trajectory does not cover). Precondition: `sorted` is sorted by t_s (equal stamps
/// allowed). Cost: O(log n).
[[nodiscard]] std::optional<Pose2> interpolate_pose(
    const std::vector<StampedPose2>& sorted, double t_s,
    double max_gap_s = std::numeric_limits<double>::infinity());

/// The pose of the trajectory's pose nearest in time to t_s, when it is stamped within
/// max_offset_s of t_s; nullopt otherwise (on a tie, the earlier pose). Precondition: `sorted` is
/// sorted by t_s. Cost: O(log n).
[[nodiscard]] std::optional<Pose2> nearest_pose(const std::vector<StampedPose2>& sorted, double t_s,
                                                double max_offset_s);

/// Scores `trajectory` (any order: stamps may go backwards, as in real CARMEN logs; a sorted copy
/// is used) against `relations`. `time_offset_s` is added to every trajectory stamp to bring it
/// into the relations' time base (Intel: logger-relative stamps + 976052857.337284 s). Relations
/// with a stamp outside the trajectory's span, or in a gap between two of its poses longer than
/// both 5 s and 20 times its median step, are skipped and counted: such a gap is a stretch the
/// trajectory does not cover (a resumed session that left part of a log out, a localizer's lost
/// spell), across which interpolating would score a guess. A trajectory of one pose per scan
/// (0.2 s apart) skips gaps over 5 s; one of keyframes seconds apart keeps its ordinary gaps.
/// With `snap_s` > 0 nothing is interpolated: each relation stamp takes the pose of the
/// trajectory's scan nearest in time, and a relation with a stamp farther than snap_s from every
/// pose, or with both stamps nearest to one scan, is skipped. Kummerle's relations join two scans;
/// where a log's stamps are on another clock that jitters against the relations' (FR079's corrected
/// log: logger stamps 1211.43-1211.50 s behind the relations' IPC stamps), interpolating at the
/// offset stamp would score the jitter times the robot's speed, while the nearest scan is the one
/// the relation was measured on as long as the jitter stays under half the scans' spacing. Input
/// error when the trajectory or the relations are empty, or when no relation falls inside the span.
/// Precondition: time_offset_s is finite, snap_s >= 0. Cost: O((n + m) log n) for n poses and m
/// relations.
[[nodiscard]] Result<RelationMetric> relation_metric(const std::vector<StampedPose2>& trajectory,
                                                     const std::vector<Relation>& relations,
                                                     double time_offset_s = 0.0,
                                                     double snap_s = 0.0);

/// How many scored relations are off by more than max_trans_m or max_rot_rad. With a SLAM's loop
/// closures as the relations and the true trajectory as the one scored, the wrong closures: the
/// defaults are 20 times the image-node matcher's accuracy on the real TUM pairs (about 1 cm and
/// 0.5 degrees, docs/fusion-results.md), while a photo matched to its copy elsewhere is metres
/// off. Cost: O(m.count).
[[nodiscard]] std::size_t relations_off_by_more_than(const RelationMetric& m,
                                                     double max_trans_m = 0.2,
                                                     double max_rot_rad = 0.1);

}  // namespace tessera
