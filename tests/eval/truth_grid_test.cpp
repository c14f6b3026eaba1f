#include "tessera/eval/truth_grid.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace tessera {
namespace {

TEST(TruthGrid, ReadsTheBytesRowMajorAndCountsOutsideAsSolid) {
  // 3 x 2: y = 0 is "free solid free", y = 1 is "solid free free".
  const std::vector<std::uint8_t> solid{0, 1, 0, 1, 0, 0};
  const TruthGrid truth(GridGeometry({0.0, 0.0}, 0.1, 3, 2), solid);
  EXPECT_EQ(truth.geometry().width(), 3);
  EXPECT_FALSE(truth.solid({0, 0}));
  EXPECT_TRUE(truth.solid({1, 0}));
  EXPECT_TRUE(truth.solid({0, 1}));
  EXPECT_FALSE(truth.solid({2, 1}));
  EXPECT_TRUE(truth.solid({-1, 0}));
  EXPECT_TRUE(truth.solid({3, 1}));
  EXPECT_TRUE(truth.solid({0, 2}));
}

TEST(TruthGrid, IsAViewThatSeesChangesToTheBytes) {
  std::vector<std::uint8_t> solid{0, 0};
  const TruthGrid truth(GridGeometry({0.0, 0.0}, 1.0, 2, 1), solid);
  EXPECT_FALSE(truth.solid({1, 0}));
  solid[1] = 1;
  EXPECT_TRUE(truth.solid({1, 0}));
}

}  // namespace
}  // namespace tessera
