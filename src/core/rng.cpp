#include "tessera/core/rng.hpp"

#include <cmath>
#include <numbers>

#include "tessera/core/assert.hpp"

namespace tessera {
namespace {

std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }

}  // namespace

Rng::Rng(std::uint64_t seed) {
  for (auto& s : s_) s = splitmix64(seed);
}

std::uint64_t Rng::next_u64() {
  // xoshiro256** (Blackman & Vigna 2018).
  const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
  const std::uint64_t t = s_[1] << 17;
  s_[2] ^= s_[0];
  s_[3] ^= s_[1];
  s_[1] ^= s_[2];
  s_[0] ^= s_[3];
  s_[2] ^= t;
  s_[3] = rotl(s_[3], 45);
  return result;
}

double Rng::uniform(double lo, double hi) {
  // 53 random bits -> [0, 1): exact and the same on every platform.
  const double u = static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
  return lo + (hi - lo) * u;
}

int Rng::uniform_int(int lo, int hi) {
  TESSERA_ASSERT(lo <= hi);
  const std::uint64_t span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo) + 1;
  return static_cast<int>(lo + static_cast<std::int64_t>(next_u64() % span));
}

double Rng::gaussian(double stddev) {
  if (stddev == 0.0) return 0.0;
  double u1 = uniform(0.0, 1.0);
  while (u1 <= 0.0) u1 = uniform(0.0, 1.0);
  const double u2 = uniform(0.0, 1.0);
  return stddev * std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

Rng Rng::fork(std::uint64_t stream) const {
  std::uint64_t mix = s_[0] ^ rotl(s_[1], 13) ^ rotl(s_[2], 29) ^ rotl(s_[3], 47);
  mix ^= splitmix64(stream);
  return Rng(mix);
}

}  // namespace tessera
