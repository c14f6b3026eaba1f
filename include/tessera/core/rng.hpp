#pragma once
#include <cstdint>

namespace tessera {

/// Seeded random numbers with the same bits on every platform and standard library:
/// xoshiro256** seeded by splitmix64, with its own uniform and Gaussian transforms (the standard
/// distributions differ between libraries). There is no global engine; pass Rng& explicitly.
class Rng {
 public:
  explicit Rng(std::uint64_t seed);

  /// Next raw 64-bit value.
  [[nodiscard]] std::uint64_t next_u64();
  /// Uniform in [lo, hi).
  [[nodiscard]] double uniform(double lo, double hi);
  /// Uniform integer in [lo, hi]. Precondition: lo <= hi.
  [[nodiscard]] int uniform_int(int lo, int hi);
  /// Zero-mean Gaussian with the given standard deviation (Box-Muller, no cached pair).
  [[nodiscard]] double gaussian(double stddev);
  /// An independent stream (per robot or worker), deterministic in (seed, stream).
  [[nodiscard]] Rng fork(std::uint64_t stream) const;

 private:
  std::uint64_t s_[4];
};

}  // namespace tessera
