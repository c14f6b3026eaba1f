// Consecutive scans compared beam by beam (scan_agreement.hpp).
#include "tessera/slam/scan_agreement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace tessera::slam {

ScanAgreement scan_agreement(const ScanPoints& earlier, const ScanPoints& later,
                             const Pose2& T_earlier_later, double beam_rad,
                             const ScanAgreementOptions& options) {
  // The earlier returns as (bearing, range) from the earlier sensor, sorted by bearing.
  std::vector<std::pair<double, double>> beams;
  beams.reserve(earlier.returns_m.size());
  for (const Vec2& p : earlier.returns_m) {
    const Vec2 v = p - earlier.origin_m;
    beams.emplace_back(std::atan2(v.y, v.x), std::hypot(v.x, v.y));
  }
  std::sort(beams.begin(), beams.end());

  ScanAgreement out;
  // Earlier returns with a bearing in [lo, hi] (within (-pi, pi]): is any of them there, and does
  // any agree with `range_m`?
  const auto look = [&](double lo, double hi, double range_m, bool& found, bool& agrees) {
    auto it = std::lower_bound(beams.begin(), beams.end(), std::make_pair(lo, -1.0));
    const double tolerance_m = options.agreement_m + options.agreement_share * range_m;
    for (; it != beams.end() && it->first <= hi; ++it) {
      found = true;
      if (std::abs(it->second - range_m) <= tolerance_m) agrees = true;
    }
  };
  for (const Vec2& p : later.returns_m) {
    const Vec2 v = T_earlier_later * p - earlier.origin_m;
    const double bearing = std::atan2(v.y, v.x);
    const double range_m = std::hypot(v.x, v.y);
    bool found = false, agrees = false;
    look(bearing - beam_rad, bearing + beam_rad, range_m, found, agrees);
    // A 360-degree scan's beams meet across the bearing +-pi.
    constexpr double pi = std::numbers::pi;
    if (bearing - beam_rad < -pi) look(bearing - beam_rad + 2 * pi, pi, range_m, found, agrees);
    if (bearing + beam_rad > pi) look(-pi, bearing + beam_rad - 2 * pi, range_m, found, agrees);
    out.compared += found ? 1 : 0;
    out.agreeing += agrees ? 1 : 0;
  }
  return out;
}

}  // namespace tessera::slam
