#include "tessera/eval/relation_metric.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "tessera/core/pose_interpolation.hpp"

namespace tessera {
namespace {

struct MeanStd {
  double mean = 0.0;
  double std = 0.0;  // sample standard deviation (divides by n - 1); 0 for a single value
};

/// Two passes (mean, then squared deviations): no cancellation for values far from zero.
MeanStd mean_and_sample_std(const std::vector<double>& values) {
  TESSERA_ASSERT(!values.empty());
  const double n = static_cast<double>(values.size());
  MeanStd r;
  for (double v : values) r.mean += v;
  r.mean /= n;
  if (values.size() < 2) return r;
  double sum_sq = 0.0;
  for (double v : values) sum_sq += (v - r.mean) * (v - r.mean);
  r.std = std::sqrt(sum_sq / (n - 1.0));
  return r;
}

std::string seconds(double t_s) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.6f", t_s);
  return text;
}

/// nearest_pose's scan, as an index into `sorted`.
std::optional<std::size_t> nearest_index(const std::vector<StampedPose2>& sorted, double t_s,
                                         double max_offset_s) {
  if (sorted.empty()) return std::nullopt;
  const auto hi = std::lower_bound(sorted.begin(), sorted.end(), t_s,
                                   [](const StampedPose2& p, double t) { return p.t_s < t; });
  auto best = hi;
  if (hi == sorted.end() || (hi != sorted.begin() && t_s - std::prev(hi)->t_s <= hi->t_s - t_s)) {
    best = std::prev(hi);
  }
  if (!(std::abs(best->t_s - t_s) <= max_offset_s)) return std::nullopt;
  return static_cast<std::size_t>(best - sorted.begin());
}

}  // namespace

std::optional<Pose2> interpolate_pose(const std::vector<StampedPose2>& sorted, double t_s,
                                      double max_gap_s) {
  if (sorted.empty() || !(t_s >= sorted.front().t_s) || !(t_s <= sorted.back().t_s)) {
    return std::nullopt;
  }
  // First pose stamped at or after t_s; it exists because t_s <= the last stamp.
  const auto hi = std::lower_bound(sorted.begin(), sorted.end(), t_s,
                                   [](const StampedPose2& p, double t) { return p.t_s < t; });
  if (hi->t_s == t_s) return hi->pose;
  // Here sorted.front().t_s < t_s < hi->t_s, so hi has a predecessor and the interval is not empty.
  const auto lo = std::prev(hi);
  if (hi->t_s - lo->t_s > max_gap_s) return std::nullopt;
  return interpolate(lo->pose, hi->pose, (t_s - lo->t_s) / (hi->t_s - lo->t_s));
}

std::optional<Pose2> nearest_pose(const std::vector<StampedPose2>& sorted, double t_s,
                                  double max_offset_s) {
  const std::optional<std::size_t> i = nearest_index(sorted, t_s, max_offset_s);
  if (!i) return std::nullopt;
  return sorted[*i].pose;
}

Result<RelationMetric> relation_metric(const std::vector<StampedPose2>& trajectory,
                                       const std::vector<Relation>& relations, double time_offset_s,
                                       double snap_s) {
  TESSERA_ASSERT(std::isfinite(time_offset_s));
  TESSERA_ASSERT(snap_s >= 0.0);
  if (trajectory.empty()) return input_error("the trajectory has no poses");
  if (relations.empty()) return input_error("there are no relations to score");

  std::vector<StampedPose2> sorted = trajectory;
  for (StampedPose2& p : sorted) p.t_s += time_offset_s;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const StampedPose2& a, const StampedPose2& b) { return a.t_s < b.t_s; });

  // The longest gap interpolated across: 5 s, or 20 median steps for a sparse trajectory.
  std::vector<double> steps_s;
  for (std::size_t i = 1; i < sorted.size(); ++i) {
    if (sorted[i].t_s > sorted[i - 1].t_s) steps_s.push_back(sorted[i].t_s - sorted[i - 1].t_s);
  }
  double max_gap_s = 5.0;
  if (!steps_s.empty()) {
    const auto middle = steps_s.begin() + static_cast<std::ptrdiff_t>(steps_s.size() / 2);
    std::nth_element(steps_s.begin(), middle, steps_s.end());
    max_gap_s = std::max(max_gap_s, 20.0 * *middle);
  }

  RelationMetric m;
  m.poses = sorted.size();
  m.trajectory_begin_s = sorted.front().t_s;
  m.trajectory_end_s = sorted.back().t_s;
  std::vector<double> trans_m, trans_sq_m2, rot_rad, rot_sq_rad2;
  for (const Relation& rel : relations) {
    std::optional<Pose2> x1, x2;
    if (snap_s > 0.0) {
      // Both stamps on one scan: the relation joins two scans this trajectory does not tell
      // apart (stamps closer than its spacing), which no pose of it can score.
      const std::optional<std::size_t> i1 = nearest_index(sorted, rel.t1_s, snap_s);
      const std::optional<std::size_t> i2 = nearest_index(sorted, rel.t2_s, snap_s);
      if (i1 && i2 && *i1 != *i2) {
        x1 = sorted[*i1].pose;
        x2 = sorted[*i2].pose;
      }
    } else {
      x1 = interpolate_pose(sorted, rel.t1_s, max_gap_s);
      x2 = interpolate_pose(sorted, rel.t2_s, max_gap_s);
    }
    if (!x1 || !x2) {
      ++m.skipped;
      continue;
    }
    // Kummerle et al. 2009: E = (x(t1)^-1 * x(t2)) * relation^-1.
    const Pose2 E = between(*x1, *x2) * rel.motion.inverse();
    const RelationError e{rel.t1_s, rel.t2_s, std::hypot(E.x, E.y), std::abs(E.theta)};
    m.errors.push_back(e);
    trans_m.push_back(e.trans_m);
    trans_sq_m2.push_back(e.trans_m * e.trans_m);
    rot_rad.push_back(e.rot_rad);
    rot_sq_rad2.push_back(e.rot_rad * e.rot_rad);
  }
  if (m.errors.empty()) {
    double first_s = relations.front().t1_s, last_s = first_s;
    for (const Relation& rel : relations) {
      first_s = std::min({first_s, rel.t1_s, rel.t2_s});
      last_s = std::max({last_s, rel.t1_s, rel.t2_s});
    }
    return input_error("no relation falls within the trajectory's time span [" +
                       seconds(m.trajectory_begin_s) + ", " + seconds(m.trajectory_end_s) +
                       "] s (time offset " + seconds(time_offset_s) + " s); the relations span [" +
                       seconds(first_s) + ", " + seconds(last_s) + "] s");
  }
  m.count = m.errors.size();
  const MeanStd t = mean_and_sample_std(trans_m), t2 = mean_and_sample_std(trans_sq_m2);
  const MeanStd r = mean_and_sample_std(rot_rad), r2 = mean_and_sample_std(rot_sq_rad2);
  m.trans_mean_m = t.mean;
  m.trans_std_m = t.std;
  m.trans_sq_mean_m2 = t2.mean;
  m.trans_sq_std_m2 = t2.std;
  m.rot_mean_rad = r.mean;
  m.rot_std_rad = r.std;
  m.rot_sq_mean_rad2 = r2.mean;
  m.rot_sq_std_rad2 = r2.std;
  return m;
}

std::size_t relations_off_by_more_than(const RelationMetric& m, double max_trans_m,
                                       double max_rot_rad) {
  return static_cast<std::size_t>(std::count_if(
      m.errors.begin(), m.errors.end(),
      [&](const RelationError& e) { return e.trans_m > max_trans_m || e.rot_rad > max_rot_rad; }));
}

}  // namespace tessera
