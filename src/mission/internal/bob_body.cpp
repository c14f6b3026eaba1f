#include "bob_body.hpp"

#include <algorithm>
#include <numbers>

#include "tessera/core/angle.hpp"

namespace tessera::internal {

BobBody::BobBody(const BobBodyOptions& options, const Pose2& start, Rng& rng)
    : options_(options), encoders_(options.encoders, rng), truth_(start), belief_(start) {
  // One side's travel error from the encoder model: tick_noise * sqrt(ticks) ticks of
  // m_per_tick each, ticks = s / m_per_tick, so sigma = tick_noise * sqrt(s * m_per_tick).
  const WheelEncoderOptions& e = options.encoders;
  const double m_per_tick = 2.0 * std::numbers::pi * e.wheel_radius_m / e.ticks_per_wheel_rev;
  side_stddev_per_sqrt_m_ = e.tick_noise_stddev * std::sqrt(m_per_tick);
}

double BobBody::position_stddev_m() const { return std::sqrt(std::max(p_[0][0], p_[1][1])); }

void BobBody::move(const WheelTravel& command, Rng& rng) {
  const double track_m = options_.encoders.track_width_m;
  if (options_.perfect) {
    truth_ = truth_ * pose_increment(command, track_m);
    belief_ = truth_;
    return;
  }
  double achieved = 1.0;
  if (options_.slip_probability > 0.0 && rng.uniform(0.0, 1.0) < options_.slip_probability) {
    achieved -= rng.uniform(0.0, options_.slip_max_fraction);
  }
  truth_ =
      truth_ * pose_increment({command.left_m * achieved, command.right_m * achieved}, track_m);
  const Pose2 before = belief_;
  belief_ = belief_ * encoders_.measure(command, rng);

  // Covariance prediction: P = F P F^T + Q, with F the Jacobian of the motion in the belief
  // (moving d along theta) and Q from the two sides' travel noise and scale errors.
  const double dx = belief_.x - before.x;
  const double dy = belief_.y - before.y;
  const Mat3 f{{{1.0, 0.0, -dy}, {0.0, 1.0, dx}, {0.0, 0.0, 1.0}}};
  Mat3 fp{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) fp[i][j] += f[i][k] * p_[k][j];
    }
  }
  Mat3 next{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      for (int k = 0; k < 3; ++k) next[i][j] += fp[i][k] * f[j][k];
    }
  }
  const auto side_var = [&](double s_m) {
    const double random = side_stddev_per_sqrt_m_ * side_stddev_per_sqrt_m_ * std::abs(s_m);
    const double scale = options_.encoders.scale_error_stddev * s_m;
    return random + scale * scale;
  };
  const double var_l = side_var(command.left_m);
  const double var_r = side_var(command.right_m);
  const double var_along = 0.25 * (var_l + var_r);
  const double var_theta = (var_l + var_r) / (track_m * track_m);
  const double c = std::cos(belief_.theta), s = std::sin(belief_.theta);
  next[0][0] += var_along * c * c;
  next[0][1] += var_along * c * s;
  next[1][0] += var_along * c * s;
  next[1][1] += var_along * s * s;
  next[2][2] += var_theta;
  p_ = next;
}

void BobBody::face(Vec2 target_m, Rng& rng) {
  const Vec2 d = target_m - belief_.translation();
  const double turn = normalize_angle(std::atan2(d.y, d.x) - belief_.theta);
  if (std::abs(turn) < 1e-9) return;
  move(turn_travel(turn, options_.encoders), rng);
}

void BobBody::drive(double distance_m, Rng& rng) { move(forward_travel(distance_m), rng); }

std::optional<double> BobBody::fix(Rng& rng) {
  if (options_.perfect) return 0.0;
  const Point3 receiver{truth_.x, truth_.y, options_.beacons.receiver_height_m};
  Vec2 sum_m{0.0, 0.0};
  int n = 0;
  for (int k = 0; k < options_.fixes_per_stop; ++k) {
    const TrilaterationResult t = trilaterate(
        options_.beacons.beacons, measure_beacon_ranges(receiver, options_.beacons, rng));
    if (t.status != TrilaterationStatus::kOk) continue;
    sum_m = sum_m + Vec2{t.position.x, t.position.y};
    ++n;
  }
  if (n == 0) return std::nullopt;
  const Vec2 fix_m = sum_m * (1.0 / n);
  const Vec2 innovation = fix_m - belief_.translation();
  const double disagreement_m = innovation.norm();
  if (disagreement_m > options_.slip_detection_m) {
    // A slip: the odometry position may be off by the disagreement and its heading by as much
    // as that seen over one cell.
    constexpr double kCellM = 0.22;
    p_[0][0] += disagreement_m * disagreement_m;
    p_[1][1] += disagreement_m * disagreement_m;
    p_[2][2] += (disagreement_m / kCellM) * (disagreement_m / kCellM);
  }
  // Update with z = (x, y): S = P_xy + R, K = P H^T S^-1.
  const double r = std::max(options_.fix_stddev_m * options_.fix_stddev_m / n, 1e-12);
  const double s00 = p_[0][0] + r, s01 = p_[0][1], s11 = p_[1][1] + r;
  const double det = s00 * s11 - s01 * s01;
  const double i00 = s11 / det, i01 = -s01 / det, i11 = s00 / det;
  double k[3][2];
  for (int i = 0; i < 3; ++i) {
    k[i][0] = p_[i][0] * i00 + p_[i][1] * i01;
    k[i][1] = p_[i][0] * i01 + p_[i][1] * i11;
  }
  belief_.x += k[0][0] * innovation.x + k[0][1] * innovation.y;
  belief_.y += k[1][0] * innovation.x + k[1][1] * innovation.y;
  belief_.theta = normalize_angle(belief_.theta + k[2][0] * innovation.x + k[2][1] * innovation.y);
  Mat3 next = p_;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) next[i][j] -= k[i][0] * p_[0][j] + k[i][1] * p_[1][j];
  }
  p_ = next;
  return disagreement_m;
}

}  // namespace tessera::internal
