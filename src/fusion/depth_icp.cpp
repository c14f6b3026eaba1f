#include "tessera/fusion/depth_icp.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "internal/fixed_text.hpp"
#include "internal/left_perturbation.hpp"

namespace tessera::fusion {
namespace {

using internal::fixed;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Matrix6d = Eigen::Matrix<double, 6, 6>;

/// One pyramid level: per cell a vertex (camera frame; z = 0: no reading) and a unit normal
/// towards the camera (zero: none), and the intrinsics of the cell grid.
struct Level {
  int width = 0;
  int height = 0;
  double fx = 0.0, fy = 0.0, cx = 0.0, cy = 0.0;
  std::vector<Eigen::Vector3d> vertex;
  std::vector<Eigen::Vector3d> normal;

  [[nodiscard]] std::size_t at(int u, int v) const {
    return static_cast<std::size_t>(v) * static_cast<std::size_t>(width) +
           static_cast<std::size_t>(u);
  }
};

double sigma_z(const DepthIcpOptions& o, double z_m) {
  return o.depth_noise_per_m * z_m * z_m + o.depth_noise_floor_m;
}

/// The mean depth of each block_px x block_px block of `frame` (step 1 of the file comment).
void average_blocks(const RgbdFrame& frame, int block_px, const DepthIcpOptions& o, Level& level) {
  const PinholeIntrinsics& k = frame.intrinsics;
  level.width = frame.width / block_px;
  level.height = frame.height / block_px;
  const double centre = 0.5 * (block_px - 1);  // the block's centre pixel, from its first
  level.fx = k.fx_px / block_px;
  level.fy = k.fy_px / block_px;
  level.cx = (k.cx_px - centre) / block_px;
  level.cy = (k.cy_px - centre) / block_px;
  const std::size_t cells = static_cast<std::size_t>(level.width) * level.height;
  level.vertex.assign(cells, Eigen::Vector3d::Zero());
  level.normal.assign(cells, Eigen::Vector3d::Zero());
  std::vector<double> depths;
  for (int cv = 0; cv < level.height; ++cv) {
    for (int cu = 0; cu < level.width; ++cu) {
      depths.clear();
      for (int v = cv * block_px; v < (cv + 1) * block_px; ++v) {
        for (int u = cu * block_px; u < (cu + 1) * block_px; ++u) {
          const double z =
              frame
                  .depth_m[static_cast<std::size_t>(v) * frame.width + static_cast<std::size_t>(u)];
          if (z >= o.min_depth_m && z <= o.max_depth_m) depths.push_back(z);
        }
      }
      if (2 * depths.size() < static_cast<std::size_t>(block_px * block_px)) continue;
      double mean = 0.0;
      for (const double z : depths) mean += z;
      mean /= static_cast<double>(depths.size());
      const bool step = std::any_of(depths.begin(), depths.end(), [&](double z) {
        return std::abs(z - mean) > o.max_block_step_ratio * mean;
      });
      if (step) continue;
      level.vertex[level.at(cu, cv)] = {(cu - level.cx) * mean / level.fx,
                                        (cv - level.cy) * mean / level.fy, mean};
    }
  }
}

/// Normals by a principal-component fit over the 5 x 5 cells around each cell (Hoppe et al.
/// 1992), on neighbours within 10 % of the cell's depth; kept where the patch is flat: its
/// thinnest spread within the depth noise or within max_patch_curvature of the total.
void fit_normals(const DepthIcpOptions& o, Level& level) {
  constexpr int kRadius = 2;
  constexpr int kMinNeighbours = 9;
  for (int v = kRadius; v < level.height - kRadius; ++v) {
    for (int u = kRadius; u < level.width - kRadius; ++u) {
      const Eigen::Vector3d& p = level.vertex[level.at(u, v)];
      if (p.z() <= 0.0) continue;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      Eigen::Matrix3d outer = Eigen::Matrix3d::Zero();
      int n = 0;
      for (int dv = -kRadius; dv <= kRadius; ++dv) {
        for (int du = -kRadius; du <= kRadius; ++du) {
          const Eigen::Vector3d& q = level.vertex[level.at(u + du, v + dv)];
          if (q.z() <= 0.0 || std::abs(q.z() - p.z()) > 0.1 * p.z()) continue;
          const Eigen::Vector3d d = q - p;  // about p, for numerical range
          sum += d;
          outer += d * d.transpose();
          ++n;
        }
      }
      if (n < kMinNeighbours) continue;
      const Eigen::Vector3d mean = sum / n;
      const Eigen::Matrix3d cov = outer / n - mean * mean.transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig;
      eig.computeDirect(cov);
      const Eigen::Vector3d lambda = eig.eigenvalues();  // ascending
      const double s = sigma_z(o, p.z());
      if (lambda(0) > std::max(o.max_patch_curvature * lambda.sum(), s * s)) continue;
      Eigen::Vector3d normal = eig.eigenvectors().col(0);
      if (normal.dot(p) > 0.0) normal = -normal;
      level.normal[level.at(u, v)] = normal;
    }
  }
}

/// Level 0 is the finest.
std::vector<Level> pyramid(const RgbdFrame& frame, const DepthIcpOptions& o) {
  std::vector<Level> levels(static_cast<std::size_t>(o.levels));
  for (int l = 0; l < o.levels; ++l) {
    Level& level = levels[static_cast<std::size_t>(l)];
    average_blocks(frame, o.finest_block_px << l, o, level);
    fit_normals(o, level);
  }
  return levels;
}

using internal::perturbed;

/// One current point and its partner in the previous view, in the previous camera frame.
struct Pair {
  Eigen::Vector3d q;  // the current point moved by the estimate
  Eigen::Vector3d p;  // its partner
  Eigen::Vector3d n;  // the partner's normal
};

/// Projective data association (step 2 of the file comment) into `pairs` (cleared first, its
/// capacity kept across iterations); `points` counts the current points with a normal.
void associate(const Level& prev, const Level& curr, const Eigen::Isometry3d& T,
               double max_distance_m, double min_normal_cos, std::vector<Pair>& pairs,
               int& points) {
  pairs.clear();
  points = 0;
  const Eigen::Matrix3d R = T.linear();
  for (std::size_t i = 0; i < curr.vertex.size(); ++i) {
    if (curr.normal[i].isZero()) continue;
    ++points;
    const Eigen::Vector3d q = T * curr.vertex[i];
    if (q.z() <= 0.0) continue;
    const long u = std::lround(prev.fx * q.x() / q.z() + prev.cx);
    const long v = std::lround(prev.fy * q.y() / q.z() + prev.cy);
    if (u < 0 || v < 0 || u >= prev.width || v >= prev.height) continue;
    const std::size_t j = prev.at(static_cast<int>(u), static_cast<int>(v));
    const Eigen::Vector3d& n = prev.normal[j];
    if (n.isZero()) continue;
    if ((q - prev.vertex[j]).norm() > max_distance_m) continue;
    if (n.dot(R * curr.normal[i]) < min_normal_cos) continue;
    pairs.push_back({q, prev.vertex[j], n});
  }
}

/// The Gauss-Newton step of the point-to-plane residuals n . (q - p), Huber-weighted in sigmas.
/// False when the normal equations are singular.
bool gauss_newton_step(const std::vector<Pair>& pairs, const DepthIcpOptions& o, Vector6d& xi) {
  Matrix6d H = Matrix6d::Zero();
  Vector6d g = Vector6d::Zero();
  for (const Pair& pr : pairs) {
    const double r = pr.n.dot(pr.q - pr.p);
    const double sigma = sigma_z(o, pr.p.z());
    const double s = std::abs(r) / sigma;
    const double w = (s <= o.huber_sigmas ? 1.0 : o.huber_sigmas / s) / (sigma * sigma);
    Vector6d J;
    J << pr.q.cross(pr.n), pr.n;
    H.noalias() += w * J * J.transpose();
    g.noalias() += w * r * J;
  }
  const Eigen::LDLT<Matrix6d> ldlt(H);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0.0)) return false;
  xi = -ldlt.solve(g);
  return xi.allFinite();
}

/// The largest over the smallest eigenvalue of Gelfand et al.'s (2003) constraint matrix of the
/// pairs: rows [(q - c) / L x n, n] with c the centroid and L the mean distance from it.
double condition_number(const std::vector<Pair>& pairs) {
  if (pairs.size() < 6) return std::numeric_limits<double>::infinity();
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (const Pair& pr : pairs) c += pr.q;
  c /= static_cast<double>(pairs.size());
  double scale = 0.0;
  for (const Pair& pr : pairs) scale += (pr.q - c).norm();
  scale /= static_cast<double>(pairs.size());
  if (!(scale > 0.0)) return std::numeric_limits<double>::infinity();
  Matrix6d C = Matrix6d::Zero();
  for (const Pair& pr : pairs) {
    Vector6d row;
    row << ((pr.q - c) / scale).cross(pr.n), pr.n;
    C.noalias() += row * row.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Matrix6d> eig(C, Eigen::EigenvaluesOnly);
  const double smallest = eig.eigenvalues()(0);
  if (!(smallest > 0.0)) return std::numeric_limits<double>::infinity();
  return eig.eigenvalues()(5) / smallest;
}

void reject(DepthIcpResult& r, DepthIcpReason reason, std::string text) {
  r.accepted = false;
  r.reason = reason;
  r.reason_text = std::move(text);
}

/// Step 3 of the file comment, on the pairs of the finest level (figures) and of the coarsest
/// (the stability test: its normals, fitted over larger patches, carry the least noise, so that
/// a plane's free directions are not hidden by noisy normals).
void judge(const std::vector<Pair>& finest, int points, const std::vector<Pair>& coarsest,
           const DepthIcpOptions& o, DepthIcpResult& r) {
  r.points = points;
  r.pairs = static_cast<int>(finest.size());
  r.overlap = points > 0 ? static_cast<double>(finest.size()) / points : 0.0;
  double sum_s2 = 0.0, sum_r2 = 0.0;
  for (const Pair& pr : finest) {
    const double res = pr.n.dot(pr.q - pr.p);
    const double s = res / sigma_z(o, pr.p.z());
    sum_s2 += s * s;
    sum_r2 += res * res;
  }
  const double n = std::max<double>(1.0, static_cast<double>(finest.size()));
  r.rms_sigmas = std::sqrt(sum_s2 / n);
  r.rmse_m = std::sqrt(sum_r2 / n);
  r.condition_number = condition_number(coarsest);
  if (r.pairs < o.min_pairs) {
    return reject(r, DepthIcpReason::kTooFewPoints,
                  std::to_string(r.pairs) + " point pairs, need " + std::to_string(o.min_pairs));
  }
  if (r.overlap < o.min_overlap) {
    return reject(r, DepthIcpReason::kLowOverlap,
                  "overlap " + fixed(100.0 * r.overlap, 0) + "% of " + std::to_string(points) +
                      " points, need " + fixed(100.0 * o.min_overlap, 0) + "%");
  }
  if (r.rms_sigmas > o.max_rms_sigmas) {
    return reject(r, DepthIcpReason::kHighResidual,
                  "residual " + fixed(r.rms_sigmas, 2) + " sigma (" + fixed(1000.0 * r.rmse_m, 1) +
                      " mm), at most " + fixed(o.max_rms_sigmas, 1));
  }
  if (!(r.condition_number <= o.max_condition_number)) {
    return reject(r, DepthIcpReason::kDegenerate,
                  "geometry leaves a motion free: condition number " +
                      (std::isfinite(r.condition_number) ? fixed(r.condition_number, 0) : "inf") +
                      ", at most " + fixed(o.max_condition_number, 0));
  }
  r.accepted = true;
  r.reason = DepthIcpReason::kAccepted;
  r.reason_text = std::to_string(r.pairs) + " point pairs, overlap " + fixed(100.0 * r.overlap, 0) +
                  "%, residual " + fixed(1000.0 * r.rmse_m, 1) + " mm, condition number " +
                  fixed(r.condition_number, 0);
}

}  // namespace

std::optional<std::string> validate(const DepthIcpOptions& o) {
  if (!(o.min_depth_m > 0.0 && o.max_depth_m > o.min_depth_m)) {
    return "depth range must satisfy 0 < min_depth_m < max_depth_m";
  }
  if (o.finest_block_px < 1 || o.levels < 1 || o.levels > 5) {
    return "finest_block_px must be >= 1 and levels in [1, 5]";
  }
  if (!(o.max_block_step_ratio > 0.0)) return "max_block_step_ratio must be > 0";
  if (!(o.max_patch_curvature >= 0.0 && o.max_patch_curvature < 1.0 / 3.0)) {
    return "max_patch_curvature must be in [0, 1/3)";
  }
  if (o.iterations_per_level < 1) return "iterations_per_level must be >= 1";
  if (!(o.converged_m >= 0.0 && o.converged_rad >= 0.0)) return "convergence bounds must be >= 0";
  if (!(o.max_pair_distance_m > 0.0)) return "max_pair_distance_m must be > 0";
  if (!(o.max_normal_angle_rad > 0.0 && o.max_normal_angle_rad <= std::numbers::pi / 2)) {
    return "max_normal_angle_rad must be in (0, pi/2]";
  }
  if (!(o.depth_noise_per_m >= 0.0 && o.depth_noise_floor_m > 0.0)) {
    return "depth_noise_per_m must be >= 0 and depth_noise_floor_m > 0";
  }
  if (!(o.huber_sigmas > 0.0)) return "huber_sigmas must be > 0";
  if (!(o.min_overlap >= 0.0 && o.min_overlap <= 1.0)) return "min_overlap must be in [0, 1]";
  if (o.min_pairs < 6) return "min_pairs must be >= 6";
  if (!(o.max_rms_sigmas > 0.0)) return "max_rms_sigmas must be > 0";
  if (!(o.max_condition_number >= 1.0)) return "max_condition_number must be >= 1";
  return std::nullopt;
}

std::string_view to_string(DepthIcpReason reason) {
  switch (reason) {
    case DepthIcpReason::kAccepted:
      return "accepted";
    case DepthIcpReason::kInconsistentFrames:
      return "inconsistent frames";
    case DepthIcpReason::kTooFewPoints:
      return "too few points";
    case DepthIcpReason::kLowOverlap:
      return "low overlap";
    case DepthIcpReason::kHighResidual:
      return "high residual";
    case DepthIcpReason::kDegenerate:
      return "geometry degenerate";
  }
  return "unknown";
}

DepthIcpResult align_depth(const RgbdFrame& prev, const RgbdFrame& curr, const DepthIcpOptions& o,
                           const Eigen::Isometry3d& T_prev_curr_guess) {
  DepthIcpResult r;
  r.T_prev_curr = T_prev_curr_guess;
  const int coarsest_block = o.finest_block_px << (o.levels - 1);
  if (!prev.consistent() || !curr.consistent() || prev.width != curr.width ||
      prev.height != curr.height || prev.width < 5 * coarsest_block ||
      prev.height < 5 * coarsest_block) {
    reject(r, DepthIcpReason::kInconsistentFrames,
           "frames must be consistent, of one size and at least 5 x 5 cells of " +
               std::to_string(coarsest_block) + " px");
    return r;
  }
  const std::vector<Level> prev_levels = pyramid(prev, o);
  const std::vector<Level> curr_levels = pyramid(curr, o);
  const double min_normal_cos = std::cos(o.max_normal_angle_rad);
  Eigen::Isometry3d T = T_prev_curr_guess;
  int points = 0;
  std::vector<Pair> pairs;
  pairs.reserve(curr_levels[0].vertex.size());
  for (int l = o.levels - 1; l >= 0; --l) {
    const auto li = static_cast<std::size_t>(l);
    const double max_distance_m = o.max_pair_distance_m * static_cast<double>(1 << l);
    for (int it = 0; it < o.iterations_per_level; ++it) {
      associate(prev_levels[li], curr_levels[li], T, max_distance_m, min_normal_cos, pairs, points);
      Vector6d xi;
      if (pairs.size() < 6 || !gauss_newton_step(pairs, o, xi)) break;
      T = perturbed(T, xi);
      ++r.iterations;
      if (xi.head<3>().norm() < o.converged_rad && xi.tail<3>().norm() < o.converged_m) break;
    }
  }
  r.T_prev_curr = T;
  associate(prev_levels[0], curr_levels[0], T, o.max_pair_distance_m, min_normal_cos, pairs,
            points);
  int coarse_points = 0;
  const std::size_t top = static_cast<std::size_t>(o.levels - 1);
  std::vector<Pair> coarsest;
  associate(prev_levels[top], curr_levels[top], T,
            o.max_pair_distance_m * static_cast<double>(1 << top), min_normal_cos, coarsest,
            coarse_points);
  judge(pairs, points, coarsest, o, r);
  return r;
}

}  // namespace tessera::fusion
