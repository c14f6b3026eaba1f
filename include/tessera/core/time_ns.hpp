#pragma once
// Differences of nanosecond stamps. Stamps near 1.7e18 ns lose 256 ns when converted to double
// first, so the difference is taken in int64; stamps from a corrupt bag or a faulty peer may be so
// far apart that int64 overflows, and then (only then) the difference is taken in double.
#include <cstdint>

namespace tessera {

[[nodiscard]] inline double ns_difference(std::int64_t later, std::int64_t earlier) {
  std::int64_t d = 0;
  if (!__builtin_sub_overflow(later, earlier, &d)) return static_cast<double>(d);
  return static_cast<double>(later) - static_cast<double>(earlier);
}

}  // namespace tessera
