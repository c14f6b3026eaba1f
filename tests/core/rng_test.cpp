#include "tessera/core/rng.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace tessera {
namespace {

TEST(Rng, SameSeedGivesSameSequence) {
  Rng a(42), b(42);
  for (int i = 0; i < 1000; ++i) EXPECT_EQ(a.next_u64(), b.next_u64());
}

TEST(Rng, DifferentSeedsGiveDifferentSequences) {
  Rng a(1), b(2);
  int equal = 0;
  for (int i = 0; i < 100; ++i) equal += a.next_u64() == b.next_u64() ? 1 : 0;
  EXPECT_EQ(equal, 0);
}

TEST(Rng, FirstValuesArePinnedSoResultsAreTheSameOnEveryPlatform) {
  // xoshiro256** seeded by splitmix64(0): if these change, every recorded run changes.
  Rng rng(0);
  const std::uint64_t first = rng.next_u64();
  Rng again(0);
  EXPECT_EQ(first, again.next_u64());
  EXPECT_EQ(first, 0x99ec5f36cb75f2b4ULL);
}

TEST(Rng, UniformStaysInRangeAndHasTheRightMean) {
  Rng rng(9);
  double sum = 0.0;
  constexpr int kN = 100000;
  for (int i = 0; i < kN; ++i) {
    const double u = rng.uniform(-2.0, 6.0);
    ASSERT_GE(u, -2.0);
    ASSERT_LT(u, 6.0);
    sum += u;
  }
  EXPECT_NEAR(sum / kN, 2.0, 0.05);
}

TEST(Rng, UniformIntCoversBothEnds) {
  Rng rng(4);
  std::vector<int> counts(5, 0);
  for (int i = 0; i < 10000; ++i) ++counts[static_cast<std::size_t>(rng.uniform_int(0, 4))];
  for (int c : counts) EXPECT_GT(c, 1800);
}

TEST(Rng, GaussianHasTheRequestedSpread) {
  Rng rng(8);
  double sum = 0.0, sum_sq = 0.0;
  constexpr int kN = 200000;
  for (int i = 0; i < kN; ++i) {
    const double g = rng.gaussian(0.5);
    sum += g;
    sum_sq += g * g;
  }
  const double mean = sum / kN;
  EXPECT_NEAR(mean, 0.0, 0.01);
  EXPECT_NEAR(std::sqrt(sum_sq / kN - mean * mean), 0.5, 0.01);
}

TEST(Rng, ForkedStreamsAreIndependentAndDeterministic) {
  const Rng base(77);
  Rng a = base.fork(1), b = base.fork(2), a_again = base.fork(1);
  const std::uint64_t va = a.next_u64();
  EXPECT_NE(va, b.next_u64());
  EXPECT_EQ(va, a_again.next_u64());
}

}  // namespace
}  // namespace tessera
