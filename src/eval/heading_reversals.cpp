#include "tessera/eval/heading_reversals.hpp"

#include <cmath>

#include "tessera/core/angle.hpp"
#include "tessera/core/assert.hpp"

namespace tessera {

HeadingReversalCounter::HeadingReversalCounter(double threshold_rad)
    : threshold_rad_(threshold_rad) {
  TESSERA_ASSERT(std::isfinite(threshold_rad) && threshold_rad > 0.0);
}

void HeadingReversalCounter::add(double heading_rad) {
  if (!started_) {
    started_ = true;
    last_rad_ = heading_rad;
    unwrapped_rad_ = extreme_rad_ = heading_rad;
    return;
  }
  unwrapped_rad_ += normalize_angle(heading_rad - last_rad_);
  last_rad_ = heading_rad;
  if (direction_ == 0) {  // no swing yet: wait for the first turn beyond the threshold
    if (std::abs(unwrapped_rad_ - extreme_rad_) > threshold_rad_) {
      direction_ = unwrapped_rad_ > extreme_rad_ ? 1 : -1;
      extreme_rad_ = unwrapped_rad_;
    }
    return;
  }
  // Follow the extreme in the current direction; turning back past the threshold is a reversal.
  const double d = static_cast<double>(direction_);
  if (d * (unwrapped_rad_ - extreme_rad_) > 0.0) extreme_rad_ = unwrapped_rad_;
  if (d * (extreme_rad_ - unwrapped_rad_) > threshold_rad_) {
    ++reversals_;
    direction_ = -direction_;
    extreme_rad_ = unwrapped_rad_;
  }
}

}  // namespace tessera
