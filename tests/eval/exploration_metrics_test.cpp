#include "tessera/eval/exploration_metrics.hpp"

#include <gtest/gtest.h>

namespace tessera {
namespace {

TEST(ExplorationMetrics, MilestonesAreTheFirstSamplesReachingThem) {
  ExplorationMetrics m;
  add_sample(m, {0, 0.0, 0.1});
  add_sample(m, {5, 2.5, 0.89});
  EXPECT_FALSE(m.steps_to_90.has_value());
  add_sample(m, {6, 3.0, 0.9});
  add_sample(m, {7, 3.5, 0.95});
  EXPECT_EQ(m.steps_to_90, 6);
  EXPECT_EQ(m.path_m_to_90, 3.0);
  EXPECT_FALSE(m.steps_to_99.has_value());
  EXPECT_FALSE(m.path_m_to_99.has_value());
  add_sample(m, {9, 4.5, 1.0});
  EXPECT_EQ(m.steps_to_99, 9);
  EXPECT_EQ(m.path_m_to_99, 4.5);
  EXPECT_DOUBLE_EQ(m.coverage, 1.0);
  EXPECT_EQ(m.coverage_over_time.size(), 5u);
}

}  // namespace
}  // namespace tessera
