#include "tessera/slam/wall_direction.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace tessera::slam {
namespace {

constexpr double kQuarter = 0.5 * std::numbers::pi;  // walls along and across count alike
constexpr int kBins = 90;

/// `a` folded into [-pi/4, pi/4).
double fold(double a) { return a - kQuarter * std::floor((a + 0.5 * kQuarter) / kQuarter); }

struct Vote {
  double angle_rad = 0.0;  // folded
  double weight = 0.0;     // run length, metres
};

/// The direction of the run of points [first, last] when it is short and straight enough.
std::optional<Vote> fit_run(const std::vector<Vec2>& p, std::size_t first, std::size_t last,
                            const WallDirectionOptions& o) {
  const double length_m = (p[last] - p[first]).norm();
  if (!(length_m > 0.0) || length_m > o.max_run_m) return std::nullopt;
  Vec2 mean;
  for (std::size_t i = first; i <= last; ++i) mean = mean + p[i];
  const double n = static_cast<double>(last - first + 1);
  mean = mean * (1.0 / n);
  double cxx = 0.0, cxy = 0.0, cyy = 0.0;
  for (std::size_t i = first; i <= last; ++i) {
    const Vec2 d = p[i] - mean;
    cxx += d.x * d.x;
    cxy += d.x * d.y;
    cyy += d.y * d.y;
  }
  cxx /= n;
  cxy /= n;
  cyy /= n;
  // Eigenvalues of the 2 x 2 covariance; the smaller is the spread across the line.
  const double half_trace = 0.5 * (cxx + cyy);
  const double root = std::hypot(0.5 * (cxx - cyy), cxy);
  const double across = half_trace - root;
  if (across > o.max_line_sigma_m * o.max_line_sigma_m) return std::nullopt;
  return Vote{fold(0.5 * std::atan2(2.0 * cxy, cxx - cyy)), length_m};
}

}  // namespace

std::optional<std::string> validate(const WallDirectionOptions& o) {
  if (o.half_window < 1) return "half_window must be >= 1";
  if (!(o.max_run_m > 0.0)) return "max_run_m must be > 0";
  if (!(o.max_line_sigma_m > 0.0)) return "max_line_sigma_m must be > 0";
  if (!(o.peak_half_width_rad > 0.0 && o.peak_half_width_rad < 0.25 * std::numbers::pi)) {
    return "peak_half_width_rad must be in (0, pi/4)";
  }
  if (!(o.min_strength >= 0.0 && o.min_strength <= 1.0)) return "min_strength must be in [0, 1]";
  if (o.min_runs < 1) return "min_runs must be >= 1";
  return std::nullopt;
}

std::optional<WallDirection> dominant_wall_direction(const std::vector<Vec2>& points_m,
                                                     const std::vector<int>& beams,
                                                     const WallDirectionOptions& o) {
  const auto k = static_cast<std::size_t>(o.half_window);
  if (points_m.size() != beams.size() || points_m.size() < 2 * k + 1) return std::nullopt;
  std::vector<Vote> votes;
  double total = 0.0;
  for (std::size_t first = 0; first + 2 * k < points_m.size(); ++first) {
    const std::size_t last = first + 2 * k;
    if (beams[last] - beams[first] != static_cast<int>(2 * k)) continue;  // a dropped beam
    if (const std::optional<Vote> v = fit_run(points_m, first, last, o)) {
      votes.push_back(*v);
      total += v->weight;
    }
  }
  if (static_cast<int>(votes.size()) < o.min_runs || !(total > 0.0)) return std::nullopt;

  // The bin whose neighbourhood (circular, +-peak_half_width) holds the most weight.
  std::vector<double> bins(kBins, 0.0);
  const double bin_rad = kQuarter / kBins;
  for (const Vote& v : votes) {
    const auto b = static_cast<int>(std::floor((v.angle_rad + 0.5 * kQuarter) / bin_rad));
    bins[static_cast<std::size_t>(std::clamp(b, 0, kBins - 1))] += v.weight;
  }
  const int reach = static_cast<int>(std::ceil(o.peak_half_width_rad / bin_rad));
  int best = 0;
  double best_mass = -1.0;
  for (int b = 0; b < kBins; ++b) {
    double mass = 0.0;
    for (int d = -reach; d <= reach; ++d)
      mass += bins[static_cast<std::size_t>((b + d + kBins) % kBins)];
    if (mass > best_mass) {
      best_mass = mass;
      best = b;
    }
  }
  // Refined: the weighted mean of the votes near the peak bin's centre (differences folded).
  const double centre = -0.5 * kQuarter + (best + 0.5) * bin_rad;
  double near = 0.0, sum = 0.0;
  for (const Vote& v : votes) {
    const double d = fold(v.angle_rad - centre);
    if (std::abs(d) > o.peak_half_width_rad) continue;
    near += v.weight;
    sum += v.weight * d;
  }
  WallDirection out;
  out.angle_rad = fold(centre + sum / near);
  out.strength = near / total;
  out.runs = static_cast<int>(votes.size());
  if (out.strength < o.min_strength) return std::nullopt;
  return out;
}

}  // namespace tessera::slam
