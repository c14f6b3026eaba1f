#include "tessera/fusion/node_matcher.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <opencv2/core/eigen.hpp>
#include <vector>

#include "internal/fixed_text.hpp"
#include "internal/left_perturbation.hpp"
#include "internal/opencv_features.hpp"
#include "tessera/fusion/descriptor_matching.hpp"
#include "tessera/fusion/rigid_fit.hpp"

namespace tessera::fusion {
namespace {

using internal::fixed;

std::string percent(double share) { return fixed(100.0 * share, 0) + "%"; }

struct Match {
  int prev = 0;
  int curr = 0;
};

/// Ratio test on the two nearest previous features of each current feature, then the mutual test.
std::vector<Match> match_descriptors(const ImageNode& prev, const ImageNode& curr,
                                     const NodeMatcherOptions& o) {
  std::vector<Match> out;
  for (const DescriptorMatch& m : ratio_test_matches(curr.descriptors, prev.descriptors,
                                                     prev.feature_type, o.ratio, o.mutual)) {
    out.push_back({m.train, m.query});
  }
  return out;
}

Eigen::Vector3d to_eigen(const CameraPoint& p) { return {p.x_m, p.y_m, p.z_m}; }

/// Pixel error of point p (camera frame) against the keypoint f; infinite behind the camera.
double reprojection_px(const PinholeIntrinsics& k, const Eigen::Vector3d& p, const NodeFeature& f) {
  if (!(p.z() > 1e-6)) return std::numeric_limits<double>::infinity();
  const double u = k.fx_px * p.x() / p.z() + k.cx_px;
  const double v = k.fy_px * p.y() / p.z() + k.cy_px;
  return std::hypot(u - f.u_px, v - f.v_px);
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Share of the coverage grid's cells that hold at least one of the given keypoints.
double coverage(const ImageNode& node, const std::vector<int>& feature_ids,
                const NodeMatcherOptions& o) {
  const int w = node.intrinsics.width_px, h = node.intrinsics.height_px;
  std::vector<char> hit(static_cast<std::size_t>(o.coverage_cols * o.coverage_rows), 0);
  for (const int id : feature_ids) {
    const NodeFeature& f = node.features[static_cast<std::size_t>(id)];
    const int c =
        std::clamp(static_cast<int>(f.u_px * o.coverage_cols / w), 0, o.coverage_cols - 1);
    const int r =
        std::clamp(static_cast<int>(f.v_px * o.coverage_rows / h), 0, o.coverage_rows - 1);
    hit[static_cast<std::size_t>(r * o.coverage_cols + c)] = 1;
  }
  return static_cast<double>(std::count(hit.begin(), hit.end(), 1)) /
         static_cast<double>(hit.size());
}

/// Square root of the second-largest eigenvalue of the points' covariance.
double spread_m(const std::vector<Eigen::Vector3d>& points) {
  if (points.size() < 2) return 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
  for (const auto& p : points) cov += (p - mean) * (p - mean).transpose();
  cov /= static_cast<double>(points.size());
  const Eigen::Vector3d ev =
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(cov, Eigen::EigenvaluesOnly).eigenvalues();
  return std::sqrt(std::max(0.0, ev(1)));
}

/// The outcome of one method before the final decision.
struct Attempt {
  bool ok = false;
  MatchReason reason = MatchReason::kTooFewMatches;
  std::string text;
  int usable_matches = 0;
  int inliers = 0;
  double inlier_ratio = 0.0;
  double rmse_m = 0.0;
  double median_reprojection_px = 0.0;
  double image_coverage = 0.0;
  double spread_m = 0.0;
  Eigen::Isometry3d T_prev_curr = Eigen::Isometry3d::Identity();
  /// The inliers' previous-node points and (PnP) the current node's keypoints they match or
  /// (3D-3D) the current node's points.
  std::vector<Eigen::Vector3d> inlier_points_prev;
  std::vector<const NodeFeature*> inlier_features_curr;
  std::vector<Eigen::Vector3d> inlier_points_curr;
};

/// The checks both methods share, on their inliers (as match indices).
void check_inliers(const ImageNode& prev, const ImageNode& curr, const std::vector<Match>& matches,
                   const std::vector<int>& inliers, const NodeMatcherOptions& o, Attempt& a) {
  a.inliers = static_cast<int>(inliers.size());
  a.inlier_ratio = a.usable_matches > 0 ? static_cast<double>(a.inliers) / a.usable_matches : 0.0;
  std::vector<int> prev_ids, curr_ids;
  std::vector<Eigen::Vector3d> prev_points;
  for (const int i : inliers) {
    const Match& m = matches[static_cast<std::size_t>(i)];
    prev_ids.push_back(m.prev);
    curr_ids.push_back(m.curr);
    prev_points.push_back(to_eigen(prev.features[static_cast<std::size_t>(m.prev)].point));
  }
  a.image_coverage = std::min(coverage(prev, prev_ids, o), coverage(curr, curr_ids, o));
  a.spread_m = spread_m(prev_points);
  if (a.inliers < o.min_inliers) {
    a.reason = MatchReason::kTooFewInliers;
    a.text = std::to_string(a.inliers) + " inliers of " + std::to_string(a.usable_matches) +
             " matches, need " + std::to_string(o.min_inliers);
  } else if (a.inlier_ratio < o.min_inlier_ratio) {
    a.reason = MatchReason::kLowInlierRatio;
    a.text = std::to_string(a.inliers) + " inliers of " + std::to_string(a.usable_matches) +
             " matches (" + percent(a.inlier_ratio) + "), need " + percent(o.min_inlier_ratio);
  } else if (a.image_coverage < o.min_image_coverage) {
    a.reason = MatchReason::kInliersConcentrated;
    a.text = "inliers cover " + percent(a.image_coverage) + " of an image, need " +
             percent(o.min_image_coverage);
  } else if (a.spread_m < o.min_spread_m) {
    a.reason = MatchReason::kInliersDegenerate;
    a.text = "inliers spread " + fixed(a.spread_m, 3) + " m across their line, need " +
             fixed(o.min_spread_m, 3) + " m";
  } else if (a.median_reprojection_px > o.max_median_reprojection_px) {
    a.reason = MatchReason::kDepthInconsistent;
    a.text = "median reprojection error " + fixed(a.median_reprojection_px, 2) + " px, at most " +
             fixed(o.max_median_reprojection_px, 2) +
             " px: the depth does not agree with the images";
  } else {
    a.ok = true;
    a.text = std::to_string(a.inliers) + " inliers of " + std::to_string(a.usable_matches) +
             " matches, median reprojection error " + fixed(a.median_reprojection_px, 2) + " px";
  }
}

Attempt rigid_3d(const ImageNode& prev, const ImageNode& curr, const std::vector<Match>& all,
                 const NodeMatcherOptions& o, Rng& rng) {
  Attempt a;
  std::vector<Match> matches;
  std::vector<Eigen::Vector3d> pa, pb;
  for (const Match& m : all) {
    const NodeFeature& fp = prev.features[static_cast<std::size_t>(m.prev)];
    const NodeFeature& fc = curr.features[static_cast<std::size_t>(m.curr)];
    if (!fp.has_depth || !fc.has_depth) continue;
    matches.push_back(m);
    pa.push_back(to_eigen(fp.point));
    pb.push_back(to_eigen(fc.point));
  }
  a.usable_matches = static_cast<int>(matches.size());
  if (a.usable_matches < o.min_matches) {
    a.reason = MatchReason::kTooFewMatches;
    a.text = std::to_string(a.usable_matches) + " matches with depth in both nodes, need " +
             std::to_string(o.min_matches);
    return a;
  }
  const RigidRansacResult r = rigid_ransac(pa, pb, o.ransac, rng);
  if (!r.valid) {
    a.reason = MatchReason::kTooFewInliers;
    a.text = "no rigid motion fits 3 or more of " + std::to_string(a.usable_matches) + " matches";
    return a;
  }
  a.T_prev_curr = r.T_a_b;
  a.rmse_m = r.rmse_m;
  // Depth consistency: each side's 3D points, moved by the estimate, against the other side's
  // keypoints; the larger median counts.
  const Eigen::Isometry3d T_curr_prev = r.T_a_b.inverse();
  std::vector<double> into_curr, into_prev;
  for (const int i : r.inliers) {
    const auto k = static_cast<std::size_t>(i);
    const Match& m = matches[k];
    into_curr.push_back(reprojection_px(curr.intrinsics, T_curr_prev * pa[k],
                                        curr.features[static_cast<std::size_t>(m.curr)]));
    into_prev.push_back(reprojection_px(prev.intrinsics, r.T_a_b * pb[k],
                                        prev.features[static_cast<std::size_t>(m.prev)]));
  }
  a.median_reprojection_px = std::max(median(into_curr), median(into_prev));
  for (const int i : r.inliers) {
    a.inlier_points_prev.push_back(pa[static_cast<std::size_t>(i)]);
    a.inlier_points_curr.push_back(pb[static_cast<std::size_t>(i)]);
  }
  // Inlier indices refer to `matches`; check_inliers wants the same list.
  check_inliers(prev, curr, matches, r.inliers, o, a);
  return a;
}

cv::Matx33d camera_matrix(const PinholeIntrinsics& k) {
  return {k.fx_px, 0.0, k.cx_px, 0.0, k.fy_px, k.cy_px, 0.0, 0.0, 1.0};
}

Eigen::Isometry3d from_rvec_tvec(const cv::Mat& rvec, const cv::Mat& tvec) {
  cv::Mat R_cv;
  cv::Rodrigues(rvec, R_cv);
  Eigen::Matrix3d R;
  cv::cv2eigen(R_cv, R);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = Eigen::Vector3d(tvec.at<double>(0), tvec.at<double>(1), tvec.at<double>(2));
  return T;
}

std::vector<int> pnp_inliers(const std::vector<cv::Point3d>& object,
                             const std::vector<cv::Point2d>& image, const Eigen::Isometry3d& T,
                             const PinholeIntrinsics& k, double threshold_px) {
  std::vector<int> inliers;
  for (std::size_t i = 0; i < object.size(); ++i) {
    const Eigen::Vector3d p = T * Eigen::Vector3d(object[i].x, object[i].y, object[i].z);
    NodeFeature f;
    f.u_px = image[i].x;
    f.v_px = image[i].y;
    if (reprojection_px(k, p, f) <= threshold_px) inliers.push_back(static_cast<int>(i));
  }
  return inliers;
}

/// 3D->2D from the previous node's depth: RANSAC over 4-point AP3P solutions with our own seeded
/// sampling, then iterative (Levenberg-Marquardt) refinement on the inliers.
Attempt pnp_from_prev(const ImageNode& prev, const ImageNode& curr, const std::vector<Match>& all,
                      const NodeMatcherOptions& o, Rng& rng) {
  Attempt a;
  std::vector<Match> matches;
  std::vector<cv::Point3d> object;
  std::vector<cv::Point2d> image;
  for (const Match& m : all) {
    const NodeFeature& fp = prev.features[static_cast<std::size_t>(m.prev)];
    if (!fp.has_depth) continue;
    const NodeFeature& fc = curr.features[static_cast<std::size_t>(m.curr)];
    matches.push_back(m);
    object.emplace_back(fp.point.x_m, fp.point.y_m, fp.point.z_m);
    image.emplace_back(fc.u_px, fc.v_px);
  }
  a.usable_matches = static_cast<int>(matches.size());
  if (a.usable_matches < std::max(o.min_matches, 4)) {
    a.reason = MatchReason::kTooFewMatches;
    a.text = std::to_string(a.usable_matches) + " matches with depth in the previous node, need " +
             std::to_string(std::max(o.min_matches, 4));
    return a;
  }
  const cv::Matx33d K = camera_matrix(curr.intrinsics);
  const int n = a.usable_matches;
  std::size_t best_count = 0;
  Eigen::Isometry3d best_T_curr_prev = Eigen::Isometry3d::Identity();
  for (int it = 0; it < o.pnp_max_iterations; ++it) {
    std::array<int, 4> s{};
    for (std::size_t j = 0; j < s.size(); ++j) {
      bool repeated = true;
      while (repeated) {
        s[j] = rng.uniform_int(0, n - 1);
        repeated = std::find(s.begin(), s.begin() + static_cast<std::ptrdiff_t>(j), s[j]) !=
                   s.begin() + static_cast<std::ptrdiff_t>(j);
      }
    }
    std::vector<cv::Point3d> so;
    std::vector<cv::Point2d> si;
    for (const int i : s) {
      so.push_back(object[static_cast<std::size_t>(i)]);
      si.push_back(image[static_cast<std::size_t>(i)]);
    }
    cv::Mat rvec, tvec;
    bool solved = false;
    try {
      solved = cv::solvePnP(so, si, K, cv::noArray(), rvec, tvec, false, cv::SOLVEPNP_AP3P);
    } catch (const cv::Exception&) {
      solved = false;  // degenerate sample (e.g. collinear points)
    }
    if (!solved || rvec.empty() || !cv::checkRange(rvec) || !cv::checkRange(tvec)) continue;
    const Eigen::Isometry3d T = from_rvec_tvec(rvec, tvec);
    const std::vector<int> inl =
        pnp_inliers(object, image, T, curr.intrinsics, o.pnp_inlier_threshold_px);
    if (inl.size() > best_count) {
      best_count = inl.size();
      best_T_curr_prev = T;
      const double w = static_cast<double>(best_count) / n;
      const double all4 = w * w * w * w;
      if (all4 >= 1.0 || std::log(1.0 - o.ransac.confidence) / std::log(1.0 - all4) < it + 1) break;
    }
  }
  if (best_count < 4) {
    a.reason = MatchReason::kTooFewInliers;
    a.text = "no camera pose explains 4 or more of " + std::to_string(n) + " matches";
    return a;
  }
  std::vector<int> inliers =
      pnp_inliers(object, image, best_T_curr_prev, curr.intrinsics, o.pnp_inlier_threshold_px);
  for (int r = 0; r < o.ransac.refine_iterations && inliers.size() >= 4; ++r) {
    std::vector<cv::Point3d> so;
    std::vector<cv::Point2d> si;
    for (const int i : inliers) {
      so.push_back(object[static_cast<std::size_t>(i)]);
      si.push_back(image[static_cast<std::size_t>(i)]);
    }
    cv::Mat R_cv;
    Eigen::Matrix3d R = best_T_curr_prev.linear();
    cv::eigen2cv(R, R_cv);
    cv::Mat rvec, tvec(3, 1, CV_64F);
    cv::Rodrigues(R_cv, rvec);
    for (int j = 0; j < 3; ++j) tvec.at<double>(j) = best_T_curr_prev.translation()(j);
    if (!cv::solvePnP(so, si, K, cv::noArray(), rvec, tvec, true, cv::SOLVEPNP_ITERATIVE)) break;
    best_T_curr_prev = from_rvec_tvec(rvec, tvec);
    std::vector<int> next =
        pnp_inliers(object, image, best_T_curr_prev, curr.intrinsics, o.pnp_inlier_threshold_px);
    const bool stable = next == inliers;
    inliers = std::move(next);
    if (stable) break;
  }
  a.T_prev_curr = best_T_curr_prev.inverse();
  std::vector<double> errors;
  for (const int i : inliers) {
    const auto k = static_cast<std::size_t>(i);
    const Eigen::Vector3d p(object[k].x, object[k].y, object[k].z);
    errors.push_back(reprojection_px(curr.intrinsics, best_T_curr_prev * p,
                                     curr.features[static_cast<std::size_t>(matches[k].curr)]));
  }
  a.median_reprojection_px = median(errors);
  for (const int i : inliers) {
    const auto k = static_cast<std::size_t>(i);
    a.inlier_points_prev.emplace_back(object[k].x, object[k].y, object[k].z);
    a.inlier_features_curr.push_back(&curr.features[static_cast<std::size_t>(matches[k].curr)]);
  }
  check_inliers(prev, curr, matches, inliers, o, a);
  return a;
}

using internal::perturbed;

/// Covariance (6 x 6, over xi of perturbed(T_prev_curr, xi)) of a least-squares estimate, from
/// its whitened residuals r(xi) (one block per point) by Gauss-Newton: (J^T J)^-1, with J by
/// central differences.
template <typename Residuals>
Eigen::Matrix<double, 6, 6> gauss_newton_covariance(const Eigen::Isometry3d& T_prev_curr,
                                                    const Residuals& residuals) {
  constexpr double kStep = 1e-6;
  const Eigen::VectorXd r0 = residuals(T_prev_curr);
  Eigen::MatrixXd J(r0.size(), 6);
  for (int j = 0; j < 6; ++j) {
    Eigen::Matrix<double, 6, 1> xi = Eigen::Matrix<double, 6, 1>::Zero();
    xi(j) = kStep;
    J.col(j) = (residuals(perturbed(T_prev_curr, xi)) - residuals(perturbed(T_prev_curr, -xi))) /
               (2.0 * kStep);
  }
  const Eigen::Matrix<double, 6, 6> H = J.transpose() * J;
  return H.ldlt().solve(Eigen::Matrix<double, 6, 6>::Identity());
}

/// Covariance of the PnP estimate: pixel residuals of its inliers in the current image, whitened
/// by sigma^2 = SSE / (n - 6) (Hartley & Zisserman 2004, section 5.2.2 and A2.2).
Eigen::Matrix<double, 6, 6> pnp_covariance(const Attempt& pnp, const PinholeIntrinsics& k) {
  const auto residuals = [&](const Eigen::Isometry3d& T_prev_curr) {
    const Eigen::Isometry3d T_curr_prev = T_prev_curr.inverse();
    Eigen::VectorXd r(2 * static_cast<Eigen::Index>(pnp.inlier_points_prev.size()));
    for (std::size_t i = 0; i < pnp.inlier_points_prev.size(); ++i) {
      const Eigen::Vector3d p = T_curr_prev * pnp.inlier_points_prev[i];
      const auto row = 2 * static_cast<Eigen::Index>(i);
      r(row) = k.fx_px * p.x() / p.z() + k.cx_px - pnp.inlier_features_curr[i]->u_px;
      r(row + 1) = k.fy_px * p.y() / p.z() + k.cy_px - pnp.inlier_features_curr[i]->v_px;
    }
    return r;
  };
  const Eigen::VectorXd r = residuals(pnp.T_prev_curr);
  const double dof = std::max(static_cast<double>(r.size()) - 6.0, 1.0);
  const double sigma2_px2 = std::max(r.squaredNorm() / dof, 1e-12);
  return sigma2_px2 * gauss_newton_covariance(pnp.T_prev_curr, residuals);
}

/// Covariance of one back-projected point: depth noise along the viewing ray plus a lateral
/// share of half a pixel, in the point's camera frame.
Eigen::Matrix3d point_covariance(const Eigen::Vector3d& p, const PinholeIntrinsics& k,
                                 double depth_noise_per_m) {
  const double z = p.z();
  const double sigma_z_m = depth_noise_per_m * z * z;
  const double sigma_lateral_m = 0.5 * z / k.fx_px;
  const Eigen::Vector3d ray = p / z;  // dp / dz
  return sigma_z_m * sigma_z_m * ray * ray.transpose() +
         sigma_lateral_m * sigma_lateral_m * Eigen::Matrix3d::Identity();
}

/// Covariance of the 3D-3D estimate: residuals a_i - T_prev_curr b_i of its inliers, whitened by
/// the depth noise model of both points.
Eigen::Matrix<double, 6, 6> rigid_covariance(const Attempt& rigid, const PinholeIntrinsics& k_prev,
                                             const PinholeIntrinsics& k_curr,
                                             double depth_noise_per_m) {
  const std::size_t n = rigid.inlier_points_prev.size();
  std::vector<Eigen::Matrix3d> whiten(n);
  const Eigen::Matrix3d R = rigid.T_prev_curr.linear();
  for (std::size_t i = 0; i < n; ++i) {
    const Eigen::Matrix3d S =
        point_covariance(rigid.inlier_points_prev[i], k_prev, depth_noise_per_m) +
        R * point_covariance(rigid.inlier_points_curr[i], k_curr, depth_noise_per_m) *
            R.transpose();
    // L^-1 with S = L L^T: whitened residual L^-1 r has identity covariance.
    whiten[i] = S.llt().matrixL().solve(Eigen::Matrix3d::Identity());
  }
  const auto residuals = [&](const Eigen::Isometry3d& T_prev_curr) {
    Eigen::VectorXd r(3 * static_cast<Eigen::Index>(n));
    for (std::size_t i = 0; i < n; ++i) {
      r.segment<3>(3 * static_cast<Eigen::Index>(i)) =
          whiten[i] * (rigid.inlier_points_prev[i] - T_prev_curr * rigid.inlier_points_curr[i]);
    }
    return r;
  };
  return gauss_newton_covariance(rigid.T_prev_curr, residuals);
}

void take(const Attempt& a, MatchMethod method, MatchResult& r) {
  r.method = method;
  r.inliers = a.inliers;
  r.inlier_ratio = a.inlier_ratio;
  r.rmse_m = a.rmse_m;
  r.median_reprojection_px = a.median_reprojection_px;
  r.image_coverage = a.image_coverage;
  r.spread_m = a.spread_m;
  r.T_prev_curr = a.T_prev_curr;
}

}  // namespace

std::optional<std::string> validate(const NodeMatcherOptions& o) {
  if (!(o.ratio > 0.0 && o.ratio <= 1.0)) return "ratio must be in (0, 1]";
  if (o.min_matches < 3) return "min_matches must be >= 3";
  if (auto problem = validate(o.ransac)) return "ransac." + *problem;
  if (o.min_inliers < 3) return "min_inliers must be >= 3";
  if (!(o.min_inlier_ratio >= 0.0 && o.min_inlier_ratio <= 1.0)) {
    return "min_inlier_ratio must be in [0, 1]";
  }
  if (o.coverage_cols < 1 || o.coverage_rows < 1) return "coverage grid must be at least 1 x 1";
  if (!(o.min_image_coverage >= 0.0 && o.min_image_coverage <= 1.0)) {
    return "min_image_coverage must be in [0, 1]";
  }
  if (!(o.min_spread_m >= 0.0)) return "min_spread_m must be >= 0";
  if (!(o.max_median_reprojection_px > 0.0)) return "max_median_reprojection_px must be > 0";
  if (!(o.pnp_inlier_threshold_px > 0.0)) return "pnp_inlier_threshold_px must be > 0";
  if (o.pnp_max_iterations < 1) return "pnp_max_iterations must be >= 1";
  if (!(o.max_pnp_disagreement_m > 0.0) || !(o.max_pnp_disagreement_rad > 0.0)) {
    return "max_pnp_disagreement_m and max_pnp_disagreement_rad must be > 0";
  }
  if (!(o.max_pnp_disagreement_chi2 >= 0.0)) return "max_pnp_disagreement_chi2 must be >= 0";
  if (!(o.depth_noise_per_m > 0.0)) return "depth_noise_per_m must be > 0";
  return std::nullopt;
}

std::string_view to_string(MatchReason reason) {
  switch (reason) {
    case MatchReason::kAccepted:
      return "accepted";
    case MatchReason::kAcceptedByPnp:
      return "accepted by PnP";
    case MatchReason::kFeatureTypeMismatch:
      return "feature type mismatch";
    case MatchReason::kTooFewMatches:
      return "too few matches";
    case MatchReason::kTooFewInliers:
      return "too few inliers";
    case MatchReason::kLowInlierRatio:
      return "low inlier ratio";
    case MatchReason::kInliersConcentrated:
      return "inliers concentrated";
    case MatchReason::kInliersDegenerate:
      return "inliers degenerate";
    case MatchReason::kDepthInconsistent:
      return "depth inconsistent";
  }
  return "too few matches";
}

std::string_view to_string(MatchMethod method) {
  switch (method) {
    case MatchMethod::kNone:
      return "none";
    case MatchMethod::kRigid3d:
      return "3d-3d";
    case MatchMethod::kPnp:
      return "pnp";
  }
  return "none";
}

MatchResult match_nodes(const ImageNode& prev, const ImageNode& curr,
                        const NodeMatcherOptions& options, Rng& rng) {
  TESSERA_ASSERT(!validate(options));
  MatchResult r;
  if (prev.feature_type != curr.feature_type) {
    r.reason = MatchReason::kFeatureTypeMismatch;
    r.reason_text = std::string("feature type mismatch: ") +
                    std::string(to_string(prev.feature_type)) + " against " +
                    std::string(to_string(curr.feature_type));
    return r;
  }
  const std::vector<Match> matches = match_descriptors(prev, curr, options);
  r.matches = static_cast<int>(matches.size());

  Attempt rigid = rigid_3d(prev, curr, matches, options, rng);
  r.matches_3d = rigid.usable_matches;  // the matches with depth in both nodes
  // Too few matches means too little seen in common; a 3D->2D fit would see no more.
  const bool run_pnp = (rigid.ok || rigid.reason != MatchReason::kTooFewMatches) &&
                       (options.pnp_fallback || (rigid.ok && options.pnp_cross_check));
  Attempt pnp;
  if (run_pnp) pnp = pnp_from_prev(prev, curr, matches, options, rng);

  // Depth cross-check: the 3D-3D estimate uses both depth images, PnP only the previous one. When
  // the current depth does not belong to its colour image the two disagree. How far apart two
  // right estimates may be depends on the scene: against a flat wall 3 m away PnP's rotation and
  // sideways translation are nearly interchangeable, and the 3D-3D estimate carries depth noise
  // that grows with z^2. So the difference xi is measured against both estimates' covariances
  // (Gauss-Newton, Hartley & Zisserman 2004, section 5.2): xi^T (C_pnp + C_3d)^-1 xi, chi-square
  // with 6 degrees of freedom when both are right. The 3D-3D estimate is rejected when the
  // difference exceeds both the fixed bounds (tuned on the TUM pairs) and that test. When it is
  // kept, the two are combined with weights from their covariances.
  std::optional<Eigen::Isometry3d> combined_T_prev_curr;
  if (rigid.ok && options.pnp_cross_check && pnp.ok) {
    const Eigen::Isometry3d d = pnp.T_prev_curr.inverse() * rigid.T_prev_curr;
    r.pnp_disagreement_m = d.translation().norm();
    r.pnp_disagreement_rad = Eigen::AngleAxisd(d.linear()).angle();
    // The difference as a left perturbation of the PnP estimate: rigid = exp(xi) * pnp.
    const Eigen::Isometry3d D = rigid.T_prev_curr * pnp.T_prev_curr.inverse();
    Eigen::Matrix<double, 6, 1> xi;
    const Eigen::AngleAxisd aa(D.linear());
    xi.head<3>() = aa.angle() * aa.axis();
    xi.tail<3>() = D.translation();
    const Eigen::Matrix<double, 6, 6> C_pnp = pnp_covariance(pnp, curr.intrinsics);
    const Eigen::Matrix<double, 6, 6> C_sum =
        C_pnp +
        rigid_covariance(rigid, prev.intrinsics, curr.intrinsics, options.depth_noise_per_m);
    const Eigen::Matrix<double, 6, 1> C_sum_inv_xi = C_sum.ldlt().solve(xi);
    r.pnp_disagreement_chi2 = xi.dot(C_sum_inv_xi);
    // Minimum-variance combination of the two (treated as independent): PnP moved by
    // C_pnp (C_pnp + C_3d)^-1 xi towards the 3D-3D estimate.
    combined_T_prev_curr = perturbed(pnp.T_prev_curr, C_pnp * C_sum_inv_xi);
    const bool disagree = r.pnp_disagreement_m > options.max_pnp_disagreement_m ||
                          r.pnp_disagreement_rad > options.max_pnp_disagreement_rad;
    if (disagree && !(r.pnp_disagreement_chi2 <= options.max_pnp_disagreement_chi2)) {
      rigid.ok = false;
      rigid.reason = MatchReason::kDepthInconsistent;
      rigid.text = "3D-3D and PnP from the previous depth differ by " +
                   fixed(r.pnp_disagreement_m, 4) + " m and " +
                   fixed(r.pnp_disagreement_rad * 180.0 / std::numbers::pi, 2) + " deg (at most " +
                   fixed(options.max_pnp_disagreement_m, 4) + " m, " +
                   fixed(options.max_pnp_disagreement_rad * 180.0 / std::numbers::pi, 2) +
                   " deg) by " + fixed(r.pnp_disagreement_chi2, 1) +
                   " times their combined variance (at most " +
                   fixed(options.max_pnp_disagreement_chi2, 1) +
                   "): the current depth does not agree with the images";
    }
  }
  if (rigid.ok) {
    take(rigid, MatchMethod::kRigid3d, r);
    r.accepted = true;
    r.reason = MatchReason::kAccepted;
    r.reason_text = "3D-3D: " + rigid.text;
    if (combined_T_prev_curr && options.combine_with_pnp) {
      r.T_prev_curr = *combined_T_prev_curr;
      r.reason_text += "; combined with PnP from the previous depth (" +
                       fixed(r.pnp_disagreement_m, 4) + " m, " +
                       fixed(r.pnp_disagreement_rad * 180.0 / std::numbers::pi, 2) +
                       " deg apart, " + fixed(r.pnp_disagreement_chi2, 1) + " sigma^2)";
    }
    if (options.pnp_cross_check && !pnp.ok) {
      r.reason_text += " (no PnP cross-check: " + std::string(to_string(pnp.reason)) + ")";
    }
    return r;
  }
  r.reason = rigid.reason;
  r.reason_text = "3D-3D rejected: " + std::string(to_string(rigid.reason)) + ": " + rigid.text;
  if (rigid.reason != MatchReason::kTooFewMatches) take(rigid, MatchMethod::kRigid3d, r);
  if (!options.pnp_fallback || !run_pnp) return r;
  if (pnp.ok) {
    take(pnp, MatchMethod::kPnp, r);
    r.accepted = true;
    r.reason = MatchReason::kAcceptedByPnp;
    r.reason_text += "; PnP from the previous depth: " + pnp.text;
    return r;
  }
  r.reason_text += "; PnP from the previous depth rejected: " + std::string(to_string(pnp.reason)) +
                   ": " + pnp.text;
  return r;
}

}  // namespace tessera::fusion
