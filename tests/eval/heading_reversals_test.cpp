#include "tessera/eval/heading_reversals.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace tessera {
namespace {

TEST(HeadingReversals, ASteadyTurnAndAUTurnCountNothing) {
  HeadingReversalCounter c(0.1);
  for (int k = 0; k <= 400; ++k) c.add(k * 0.01);  // 4 rad one way, across the +-pi seam
  EXPECT_EQ(c.reversals(), 0);
}

TEST(HeadingReversals, EachSwingBackBeyondTheThresholdCountsOnce) {
  HeadingReversalCounter c(0.1);
  // A zigzag of +-0.3 rad around pi (samples wrap at the seam): out, back, out, back = 3 swings
  // back after the first turn.
  const double amplitude = 0.3;
  for (int k = 0; k <= 400; ++k) {
    const double phase = std::fmod(k * 0.01, 1.0);  // 1 s period: up 0.5 s, down 0.5 s
    const double tri = phase < 0.5 ? phase * 4.0 - 1.0 : 3.0 - phase * 4.0;
    c.add(std::numbers::pi + amplitude * tri);
  }
  EXPECT_EQ(c.reversals(), 7);  // four periods: reversals at each peak and trough after the first
}

TEST(HeadingReversals, JitterBelowTheThresholdDoesNotCount) {
  HeadingReversalCounter c(0.1);
  for (int k = 0; k < 200; ++k) c.add(0.5 + ((k % 2) != 0 ? 0.04 : -0.04));
  EXPECT_EQ(c.reversals(), 0);
}

}  // namespace
}  // namespace tessera
