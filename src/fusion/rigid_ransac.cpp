#include "tessera/fusion/rigid_ransac.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "tessera/core/assert.hpp"
#include "tessera/fusion/rigid_fit.hpp"

namespace tessera::fusion {
namespace {

std::vector<int> collect_inliers(std::span<const Eigen::Vector3d> a,
                                 std::span<const Eigen::Vector3d> b, const Eigen::Isometry3d& T,
                                 double threshold_m) {
  const double t2 = threshold_m * threshold_m;
  std::vector<int> inliers;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if ((a[i] - T * b[i]).squaredNorm() <= t2) inliers.push_back(static_cast<int>(i));
  }
  return inliers;
}

RigidFit fit_subset(std::span<const Eigen::Vector3d> a, std::span<const Eigen::Vector3d> b,
                    const std::vector<int>& subset) {
  std::vector<Eigen::Vector3d> sa, sb;
  sa.reserve(subset.size());
  sb.reserve(subset.size());
  for (const int i : subset) {
    sa.push_back(a[static_cast<std::size_t>(i)]);
    sb.push_back(b[static_cast<std::size_t>(i)]);
  }
  return fit_rigid(sa, sb);
}

/// Hypotheses needed so that one all-inlier sample of 3 was drawn with probability `confidence`
/// (Hartley & Zisserman eq. 4.18).
int needed_iterations(double inlier_share, double confidence, int max_iterations) {
  const double all_inliers = inlier_share * inlier_share * inlier_share;
  if (all_inliers >= 1.0) return 1;
  if (all_inliers <= 0.0) return max_iterations;
  const double n = std::log(1.0 - confidence) / std::log(1.0 - all_inliers);
  return n >= max_iterations ? max_iterations : std::max(1, static_cast<int>(std::ceil(n)));
}

}  // namespace

std::optional<std::string> validate(const RigidRansacOptions& o) {
  if (!(o.inlier_threshold_m > 0.0)) return "inlier_threshold_m must be > 0";
  if (o.max_iterations < 1) return "max_iterations must be >= 1";
  if (!(o.confidence > 0.0 && o.confidence < 1.0)) return "confidence must be in (0, 1)";
  if (!(o.max_distance_mismatch_m > 0.0)) return "max_distance_mismatch_m must be > 0";
  if (o.refine_iterations < 0) return "refine_iterations must be >= 0";
  return std::nullopt;
}

RigidRansacResult rigid_ransac(std::span<const Eigen::Vector3d> a,
                               std::span<const Eigen::Vector3d> b,
                               const RigidRansacOptions& options, Rng& rng) {
  TESSERA_ASSERT(a.size() == b.size());
  TESSERA_ASSERT(!validate(options));
  RigidRansacResult best;
  const int n = static_cast<int>(a.size());
  if (n < 3) return best;

  std::size_t best_count = 0;
  Eigen::Isometry3d best_T = Eigen::Isometry3d::Identity();
  int needed = options.max_iterations;
  int it = 0;
  for (; it < needed; ++it) {
    const int i = rng.uniform_int(0, n - 1);
    int j = rng.uniform_int(0, n - 2);
    if (j >= i) ++j;
    int k = rng.uniform_int(0, n - 3);
    if (k >= std::min(i, j)) ++k;
    if (k >= std::max(i, j)) ++k;
    const std::array<int, 3> s{i, j, k};
    // Distances are invariant under rigid motion: a sample that changes them has an outlier.
    bool consistent = true;
    for (int p = 0; p < 3 && consistent; ++p) {
      const auto u = static_cast<std::size_t>(s[static_cast<std::size_t>(p)]);
      const auto v = static_cast<std::size_t>(s[static_cast<std::size_t>((p + 1) % 3)]);
      consistent =
          std::abs((a[u] - a[v]).norm() - (b[u] - b[v]).norm()) <= options.max_distance_mismatch_m;
    }
    if (!consistent) continue;
    const RigidFit fit = fit_subset(a, b, {s.begin(), s.end()});
    if (!fit.valid) continue;
    const std::vector<int> inliers = collect_inliers(a, b, fit.T_a_b, options.inlier_threshold_m);
    if (inliers.size() > best_count) {
      best_count = inliers.size();
      best_T = fit.T_a_b;
      needed = needed_iterations(static_cast<double>(best_count) / n, options.confidence,
                                 options.max_iterations);
    }
  }
  best.iterations = it;
  if (best_count < 3) return best;

  // Refinement: least squares on all inliers, then the inliers of the refined motion, until the
  // set is stable.
  std::vector<int> inliers = collect_inliers(a, b, best_T, options.inlier_threshold_m);
  for (int r = 0; r < options.refine_iterations; ++r) {
    const RigidFit fit = fit_subset(a, b, inliers);
    if (!fit.valid) break;
    std::vector<int> next = collect_inliers(a, b, fit.T_a_b, options.inlier_threshold_m);
    if (next.size() < 3) break;
    best_T = fit.T_a_b;
    const bool stable = next == inliers;
    inliers = std::move(next);
    if (stable) break;
  }
  best.valid = true;
  best.T_a_b = best_T;
  best.inliers = std::move(inliers);
  double sum2 = 0.0;
  for (const int i : best.inliers) {
    sum2 +=
        (a[static_cast<std::size_t>(i)] - best_T * b[static_cast<std::size_t>(i)]).squaredNorm();
  }
  best.rmse_m = std::sqrt(sum2 / static_cast<double>(best.inliers.size()));
  return best;
}

}  // namespace tessera::fusion
