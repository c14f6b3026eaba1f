#include "tessera/eval/trajectory_error.hpp"

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <tuple>

namespace tessera {
namespace {

/// The trajectory sorted by stamp with one pose per stamp: the last one in input order, as the TUM
/// tools' dictionaries keep it.
std::vector<StampedPose3> by_unique_stamp(const std::vector<StampedPose3>& poses) {
  std::vector<StampedPose3> sorted = poses;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const StampedPose3& a, const StampedPose3& b) { return a.t_s < b.t_s; });
  std::vector<StampedPose3> unique;
  unique.reserve(sorted.size());
  for (const StampedPose3& p : sorted) {
    if (!unique.empty() && unique.back().t_s == p.t_s) {
      unique.back() = p;
    } else {
      unique.push_back(p);
    }
  }
  return unique;
}

std::vector<double> stamps_of(const std::vector<StampedPose3>& poses) {
  std::vector<double> t;
  t.reserve(poses.size());
  for (const StampedPose3& p : poses) t.push_back(p.t_s);
  return t;
}

/// evaluate_rpe.py find_closest_index, step for step: a binary search that remembers the closest
/// element it visits (it visits both neighbours of t, so this is the closest; on a tie the first
/// visited wins). Precondition: `sorted` is sorted and not empty.
std::size_t closest_index(const std::vector<double>& sorted, double t) {
  std::size_t beginning = 0, end = sorted.size(), best = 0;
  double difference = std::abs(sorted[0] - t);
  while (beginning < end) {
    const std::size_t middle = (beginning + end) / 2;
    if (std::abs(sorted[middle] - t) < difference) {
      difference = std::abs(sorted[middle] - t);
      best = middle;
    }
    if (t == sorted[middle]) return middle;
    if (sorted[middle] > t) {
      end = middle;
    } else {
      beginning = middle + 1;
    }
  }
  return best;
}

/// numpy.median.
double median_of(std::vector<double> v) {
  TESSERA_ASSERT(!v.empty());
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

/// evaluate_rpe.py compute_angle: the rotation angle from the trace ("An invitation to 3-D
/// vision", p. 27), clamped against rounding.
double rotation_angle_rad(const Eigen::Matrix3d& R) {
  return std::acos(std::clamp((R.trace() - 1.0) / 2.0, -1.0, 1.0));
}

/// "0.02", "1" in messages.
std::string seconds(double t_s) {
  char text[32];
  std::snprintf(text, sizeof(text), "%g", t_s);
  return text;
}

}  // namespace

std::optional<std::string> validate(const TrajectoryErrorOptions& o) {
  if (!(o.max_difference_s > 0.0) || !std::isfinite(o.max_difference_s)) {
    return "max_difference_s must be a positive number of seconds, got " +
           seconds(o.max_difference_s);
  }
  if (!(o.rpe_delta_s > 0.0) || !std::isfinite(o.rpe_delta_s)) {
    return "rpe_delta_s must be a positive number of seconds, got " + seconds(o.rpe_delta_s);
  }
  return std::nullopt;
}

std::vector<StampMatch> associate_stamps(const std::vector<double>& reference_s,
                                         const std::vector<double>& estimate_s,
                                         double max_difference_s) {
  // Estimate indices by stamp, so that the candidates of each reference stamp are one range.
  std::vector<std::size_t> order(estimate_s.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return estimate_s[a] < estimate_s[b]; });

  struct Candidate {
    double difference_s;
    std::size_t reference;
    std::size_t estimate;
  };
  std::vector<Candidate> candidates;
  for (std::size_t r = 0; r < reference_s.size(); ++r) {
    const double a = reference_s[r];
    auto it = std::lower_bound(order.begin(), order.end(), a - max_difference_s,
                               [&](std::size_t e, double t) { return estimate_s[e] < t; });
    for (; it != order.end() && estimate_s[*it] <= a + max_difference_s; ++it) {
      const double difference_s = std::abs(a - estimate_s[*it]);
      if (difference_s < max_difference_s) candidates.push_back({difference_s, r, *it});
    }
  }
  // associate.py sorts (difference, a, b) tuples: by difference, then by the stamps themselves.
  std::sort(candidates.begin(), candidates.end(), [&](const Candidate& x, const Candidate& y) {
    return std::tuple(x.difference_s, reference_s[x.reference], estimate_s[x.estimate], x.reference,
                      x.estimate) < std::tuple(y.difference_s, reference_s[y.reference],
                                               estimate_s[y.estimate], y.reference, y.estimate);
  });
  std::vector<bool> reference_used(reference_s.size(), false);
  std::vector<bool> estimate_used(estimate_s.size(), false);
  std::vector<StampMatch> matches;
  for (const Candidate& c : candidates) {
    if (reference_used[c.reference] || estimate_used[c.estimate]) continue;
    reference_used[c.reference] = true;
    estimate_used[c.estimate] = true;
    matches.push_back({c.reference, c.estimate});
  }
  std::sort(matches.begin(), matches.end(), [&](const StampMatch& x, const StampMatch& y) {
    return std::tuple(reference_s[x.reference], x.reference) <
           std::tuple(reference_s[y.reference], y.reference);
  });
  return matches;
}

ErrorStatistics error_statistics(std::vector<double> errors) {
  TESSERA_ASSERT(!errors.empty());
  ErrorStatistics s;
  s.count = errors.size();
  const double n = static_cast<double>(errors.size());
  double sum = 0.0, sum_sq = 0.0;
  for (double e : errors) {
    sum += e;
    sum_sq += e * e;
  }
  s.rmse = std::sqrt(sum_sq / n);
  s.mean = sum / n;
  double deviation_sq = 0.0;
  for (double e : errors) deviation_sq += (e - s.mean) * (e - s.mean);
  s.std = std::sqrt(deviation_sq / n);
  const auto [lo, hi] = std::minmax_element(errors.begin(), errors.end());
  s.min = *lo;
  s.max = *hi;
  s.median = median_of(std::move(errors));
  return s;
}

Eigen::Isometry3d align_rigid(const std::vector<Eigen::Vector3d>& from,
                              const std::vector<Eigen::Vector3d>& to) {
  TESSERA_ASSERT(from.size() == to.size() && !from.empty());
  const double n = static_cast<double>(from.size());
  Eigen::Vector3d mean_from = Eigen::Vector3d::Zero(), mean_to = Eigen::Vector3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    mean_from += from[i];
    mean_to += to[i];
  }
  mean_from /= n;
  mean_to /= n;
  // Cross-covariance W = sum (to_i - mean_to)(from_i - mean_from)^T = U D V^T; the rotation is
  // U S V^T with S = diag(1, 1, det(U) det(V)) (Umeyama 1991, eq. 39-43; evaluate_ate.py align).
  Eigen::Matrix3d W = Eigen::Matrix3d::Zero();
  for (std::size_t i = 0; i < from.size(); ++i) {
    W += (to[i] - mean_to) * (from[i] - mean_from).transpose();
  }
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(W, Eigen::ComputeFullU | Eigen::ComputeFullV);
  Eigen::Matrix3d S = Eigen::Matrix3d::Identity();
  if (svd.matrixU().determinant() * svd.matrixV().determinant() < 0.0) S(2, 2) = -1.0;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = svd.matrixU() * S * svd.matrixV().transpose();
  T.translation() = mean_to - T.linear() * mean_from;
  return T;
}

Result<AbsoluteTrajectoryError> absolute_trajectory_error(
    const std::vector<StampedPose3>& estimate, const std::vector<StampedPose3>& reference,
    const TrajectoryErrorOptions& options) {
  TESSERA_ASSERT(!validate(options));
  const std::vector<StampedPose3> est = by_unique_stamp(estimate);
  const std::vector<StampedPose3> ref = by_unique_stamp(reference);
  const std::vector<StampMatch> matches =
      associate_stamps(stamps_of(ref), stamps_of(est), options.max_difference_s);
  if (matches.size() < 2) {
    return input_error(std::to_string(matches.size()) + " of " + std::to_string(est.size()) +
                       " estimate stamps are within " + seconds(options.max_difference_s) +
                       " s of a reference stamp; the ATE needs at least 2");
  }
  std::vector<Eigen::Vector3d> from, to;
  for (const StampMatch& m : matches) {
    from.push_back(est[m.estimate].position_m);
    to.push_back(ref[m.reference].position_m);
  }
  AbsoluteTrajectoryError ate;
  ate.estimate_poses = estimate.size();
  ate.reference_poses = reference.size();
  ate.T_reference_estimate = align_rigid(from, to);
  std::vector<double> errors_m;
  errors_m.reserve(from.size());
  for (std::size_t i = 0; i < from.size(); ++i) {
    errors_m.push_back((ate.T_reference_estimate * from[i] - to[i]).norm());
  }
  ate.trans_m = error_statistics(std::move(errors_m));
  return ate;
}

Result<RelativePoseError> relative_pose_error(const std::vector<StampedPose3>& estimate,
                                              const std::vector<StampedPose3>& reference,
                                              const TrajectoryErrorOptions& options) {
  TESSERA_ASSERT(!validate(options));
  const std::vector<StampedPose3> est = by_unique_stamp(estimate);
  const std::vector<StampedPose3> ref = by_unique_stamp(reference);
  if (ref.size() < 2) return input_error("the reference needs at least 2 poses for the RPE");
  if (est.empty()) return input_error("the estimate has no poses");
  const std::vector<double> t_est = stamps_of(est), t_ref = stamps_of(ref);

  // evaluate_rpe.py's overlap check: estimate stamps that are the closest to their closest
  // reference stamp.
  std::vector<std::size_t> returned;
  for (double t : t_est) {
    const std::size_t back = closest_index(t_est, t_ref[closest_index(t_ref, t)]);
    if (std::find(returned.begin(), returned.end(), back) == returned.end()) {
      returned.push_back(back);
      if (returned.size() >= 2) break;
    }
  }
  if (returned.size() < 2) {
    return input_error("the estimate's and the reference's stamps do not overlap");
  }

  std::vector<double> intervals_s;
  for (std::size_t k = 1; k < t_ref.size(); ++k) intervals_s.push_back(t_ref[k] - t_ref[k - 1]);
  const double max_time_difference_s = 2.0 * median_of(std::move(intervals_s));

  std::vector<double> trans_m, rot_rad;
  for (std::size_t i = 0; i < est.size(); ++i) {
    const std::size_t j = closest_index(t_est, t_est[i] + options.rpe_delta_s);
    if (j == est.size() - 1) continue;  // as the script does, even when j is a fair partner
    const std::size_t ri = closest_index(t_ref, t_est[i]);
    const std::size_t rj = closest_index(t_ref, t_est[j]);
    if (std::abs(t_ref[ri] - t_est[i]) > max_time_difference_s ||
        std::abs(t_ref[rj] - t_est[j]) > max_time_difference_s) {
      continue;
    }
    const Eigen::Isometry3d est_motion = est[i].transform().inverse() * est[j].transform();
    const Eigen::Isometry3d ref_motion = ref[ri].transform().inverse() * ref[rj].transform();
    const Eigen::Isometry3d error = est_motion * ref_motion.inverse();
    trans_m.push_back(error.translation().norm());
    rot_rad.push_back(rotation_angle_rad(error.linear()));
  }
  if (trans_m.size() < 2) {
    return input_error(std::to_string(trans_m.size()) + " pose pairs are " +
                       seconds(options.rpe_delta_s) +
                       " s apart with reference poses at both ends; the RPE needs at least 2");
  }
  RelativePoseError rpe;
  rpe.delta_s = options.rpe_delta_s;
  rpe.trans_m = error_statistics(std::move(trans_m));
  rpe.rot_rad = error_statistics(std::move(rot_rad));
  return rpe;
}

}  // namespace tessera
