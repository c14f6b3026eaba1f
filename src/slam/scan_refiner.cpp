#include "tessera/slam/scan_refiner.hpp"

#include <ceres/cubic_interpolation.h>

#include <Eigen/Dense>
#include <cmath>

namespace tessera::slam {
namespace {

/// The grid's cell probabilities as ceres' Grid concept (row = y, column = x, samples at cell
/// centres); unknown and outside cells read kMinProbability, like Cartographer's GridArrayAdapter.
class GridAdapter {
 public:
  enum { DATA_DIMENSION = 1 };
  GridAdapter(const ProbabilityGrid& grid, double unknown_probability)
      : values_(grid.values().data()),
        table_(value_to_probability_table().data()),
        width_(grid.geometry().width()),
        height_(grid.geometry().height()),
        unknown_probability_(unknown_probability) {}

  void GetValue(int row, int column, double* f) const {
    if (row < 0 || column < 0 || row >= height_ || column >= width_) {
      *f = unknown_probability_;
      return;
    }
    const std::uint16_t value =
        values_[static_cast<std::size_t>(row) * static_cast<std::size_t>(width_) +
                static_cast<std::size_t>(column)];
    *f = value == kUnknownCellValue ? unknown_probability_ : table_[value];
  }

 private:
  const std::uint16_t* values_;
  const float* table_;
  int width_;
  int height_;
  double unknown_probability_;
};

struct Evaluation {
  double cost = 0.0;
  double probability_sum = 0.0;
  Eigen::Matrix3d JtJ_occupied = Eigen::Matrix3d::Zero();
  Eigen::Matrix3d JtJ = Eigen::Matrix3d::Zero();
  Eigen::Vector3d Jtr = Eigen::Vector3d::Zero();
};

class Problem {
 public:
  Problem(const ProbabilityGrid& grid, const Pose2& prior, const std::vector<Vec2>& points,
          const ScanRefinerOptions& options, const std::optional<HeadingTarget>& heading)
      : adapter_(grid, options.unknown_probability),
        interpolator_(adapter_),
        origin_(grid.geometry().origin()),
        inv_res_(1.0 / grid.geometry().resolution_m()),
        prior_(prior),
        points_(points),
        options_(options),
        heading_(heading),
        point_scale_(options.occupied_space_weight /
                     std::sqrt(static_cast<double>(std::max<std::size_t>(points.size(), 1)))) {}

  /// Cost at pose x, and (when with_derivatives) the normal equations.
  Evaluation evaluate(const Eigen::Vector3d& x, bool with_derivatives) const {
    Evaluation e;
    const double c = std::cos(x[2]), s = std::sin(x[2]);
    for (const Vec2& p : points_) {
      const double qx = x[0] + c * p.x - s * p.y;
      const double qy = x[1] + s * p.x + c * p.y;
      const double col = (qx - origin_.x) * inv_res_ - 0.5;
      const double row = (qy - origin_.y) * inv_res_ - 0.5;
      double prob = 0.0, dprob_drow = 0.0, dprob_dcol = 0.0;
      interpolator_.Evaluate(row, col, &prob, &dprob_drow, &dprob_dcol);
      const double r = point_scale_ * (1.0 - prob);
      e.cost += r * r;
      e.probability_sum += prob;
      if (with_derivatives) {
        const double dr_dqx = -point_scale_ * dprob_dcol * inv_res_;
        const double dr_dqy = -point_scale_ * dprob_drow * inv_res_;
        const Eigen::Vector3d J(dr_dqx, dr_dqy,
                                dr_dqx * (-s * p.x - c * p.y) + dr_dqy * (c * p.x - s * p.y));
        e.JtJ_occupied.noalias() += J * J.transpose();
        e.Jtr.noalias() += J * r;
      }
    }
    e.JtJ = e.JtJ_occupied;
    const double wt = options_.translation_weight, wr = options_.rotation_weight;
    const Eigen::Vector3d r_prior(wt * (x[0] - prior_.x), wt * (x[1] - prior_.y),
                                  wr * normalize_angle(x[2] - prior_.theta));
    e.cost += r_prior.squaredNorm();
    if (with_derivatives) {
      const Eigen::Vector3d d(wt, wt, wr);
      e.JtJ.diagonal() += d.cwiseProduct(d);
      e.Jtr += d.cwiseProduct(r_prior);
    }
    if (heading_) {
      const double w = heading_->weight_per_rad;
      const double r = w * normalize_angle(x[2] - heading_->theta_rad);
      e.cost += r * r;
      if (with_derivatives) {
        e.JtJ(2, 2) += w * w;
        e.Jtr(2) += w * r;
      }
    }
    return e;
  }

 private:
  GridAdapter adapter_;
  ceres::BiCubicInterpolator<GridAdapter> interpolator_;
  Vec2 origin_;
  double inv_res_;
  Pose2 prior_;
  const std::vector<Vec2>& points_;
  ScanRefinerOptions options_;
  std::optional<HeadingTarget> heading_;
  double point_scale_;
};

}  // namespace

std::optional<std::string> validate(const ScanRefinerOptions& o) {
  if (!(o.occupied_space_weight > 0.0)) return "occupied_space_weight must be > 0";
  if (!(o.translation_weight >= 0.0)) return "translation_weight must be >= 0";
  if (!(o.rotation_weight >= 0.0)) return "rotation_weight must be >= 0";
  if (o.max_iterations < 0) return "max_iterations must be >= 0";
  if (!(o.unknown_probability >= kMinProbability && o.unknown_probability <= kMaxProbability)) {
    return "unknown_probability must be in [0.1, 0.9]";
  }
  return std::nullopt;
}

RefinedPose refine_scan(const ProbabilityGrid& grid, const Pose2& T_grid_robot_prior,
                        const Pose2& T_grid_robot_start, const std::vector<Vec2>& points_robot,
                        const ScanRefinerOptions& options,
                        const std::optional<HeadingTarget>& heading) {
  const Problem problem(grid, T_grid_robot_prior, points_robot, options, heading);
  // The heading is kept continuous around the prior so that the solver never sees the wrap.
  Eigen::Vector3d x(T_grid_robot_start.x, T_grid_robot_start.y,
                    T_grid_robot_prior.theta +
                        normalize_angle(T_grid_robot_start.theta - T_grid_robot_prior.theta));
  Evaluation current = problem.evaluate(x, true);
  RefinedPose out;
  out.initial_cost = current.cost;
  double lambda = 1e-3;
  int iteration = 0;
  for (; iteration < options.max_iterations; ++iteration) {
    // Levenberg-Marquardt with Marquardt's diagonal scaling.
    Eigen::Matrix3d A = current.JtJ;
    A.diagonal() += lambda * current.JtJ.diagonal().cwiseMax(1e-9);
    const Eigen::Vector3d step = A.ldlt().solve(-current.Jtr);
    if (!step.allFinite()) break;
    const Eigen::Vector3d candidate = x + step;
    Evaluation next = problem.evaluate(candidate, true);
    if (next.cost < current.cost) {
      x = candidate;
      const double gain = current.cost - next.cost;
      current = std::move(next);
      lambda = std::max(lambda * 0.1, 1e-9);
      if (step.head<2>().norm() < 1e-5 && std::abs(step[2]) < 1e-5) break;
      if (gain < 1e-10 * current.cost) break;
    } else {
      lambda *= 10.0;
      if (lambda > 1e6) break;
    }
  }
  out.T_grid_robot = {x[0], x[1], normalize_angle(x[2])};
  out.final_cost = current.cost;
  out.iterations = iteration;
  out.mean_probability = points_robot.empty()
                             ? 0.0
                             : current.probability_sum / static_cast<double>(points_robot.size());
  out.hessian = current.JtJ_occupied;
  return out;
}

}  // namespace tessera::slam
